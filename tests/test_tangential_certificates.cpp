// The tangential certificate (friction law (2.4)-(2.5), gap function (4.24), prescribed
// resultants) is scale-invariant: every correct solution certifies at the default tolerance at
// both ends of every scale - full stick, full slip, mu -> 0, mu -> infinity, tiny and huge loads,
// soft and stiff materials, 2-D and 3-D - and the same solution perturbed by 0.1 % does not.
// A perturbation tau' = (1 - 1e-3) tau with the slip it implies ds' = ds - 1e-3 C_t tau stays
// feasible, so only the certificate can catch it.
#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

#include "linear_operator.hpp"
#include "tangential_support.hpp"

namespace dc {
namespace {

using test::amplitude;
using test::resultant;

struct Scenario {
  std::string name;
  int dimension = 3;
  double E = 2.1e11;    // Pa, both bodies
  double mu = 0.3;
  double P = 400.0;     // N (2-D: N/m)
  double R = 0.015;     // m
  // Rigid-mode controls; a shift or force given as a fraction of the gross-sliding one.
  enum class Kind { force, shift, torsion } kind = Kind::force;
  double level = 0.5;   // force: Q / (mu P); shift: x mu P / (G a) units; torsion: angle (rad)
};

std::ostream& operator<<(std::ostream& os, const Scenario& s) { return os << s.name; }

std::vector<Scenario> scenarios() {
  using K = Scenario::Kind;
  return {
      {"cattaneo_partial_slip", 3, 2.1e11, 0.3, 400.0, 0.015, K::force, 0.5},
      {"force_nearly_stick", 3, 2.1e11, 0.3, 400.0, 0.015, K::force, 1e-6},
      {"force_nearly_sliding", 3, 2.1e11, 0.3, 400.0, 0.015, K::force, 0.995},
      {"full_stick_tiny_shift", 3, 2.1e11, 0.3, 400.0, 0.015, K::shift, 1e-9},
      {"full_slip_large_shift", 3, 2.1e11, 0.3, 400.0, 0.015, K::shift, 1e3},
      {"torsion_stick_mu_1e3", 3, 2.1e11, 1e3, 400.0, 0.015, K::torsion, 1e-9},
      {"torsion_stick_mu_50", 3, 2.1e11, 50.0, 400.0, 0.015, K::torsion, 1e-6},
      {"mu_1e_minus_6", 3, 2.1e11, 1e-6, 400.0, 0.015, K::force, 0.5},
      {"tiny_load_1e_minus_6_N", 3, 2.1e11, 0.3, 1e-6, 0.015, K::force, 0.5},
      {"huge_load_1e9_N_stick", 3, 2.1e11, 0.3, 1e9, 0.015, K::shift, 1e-6},
      {"soft_1e6_Pa_small_body", 3, 1e6, 0.5, 1e-3, 1e-4, K::force, 0.3},
      {"cylinder_2d_partial", 2, 2.1e11, 0.3, 1e5, 0.015, K::force, 0.5},
      {"cylinder_2d_full_slip", 2, 2.1e11, 0.3, 1e5, 0.015, K::shift, 1e3},
  };
}

class TangentialCertificates : public ::testing::TestWithParam<Scenario> {};

TEST_P(TangentialCertificates, CorrectCertifiesAndPerturbedDoesNot) {
  const Scenario& sc = GetParam();
  const MaterialPair m{Elastic::from_E_nu(sc.E, 0.3), Elastic::from_E_nu(sc.E, 0.3)};
  Grid g;
  double a = 0.0;
  if (sc.dimension == 3) {
    a = hertz::sphere(sc.R, sc.P, m.E_star()).a;
    g = Grid::make(3, 16, 16, -1.3 * a, 1.3 * a, -1.3 * a, 1.3 * a);
  } else {
    a = std::sqrt(4.0 * sc.P * sc.R / (M_PI * m.E_star()));
    g = Grid::make(2, 48, 1, -1.3 * a, 1.3 * a, 0.0, 0.0);
  }
  TangentialProblem problem = test::round_body_problem(g, m, sc.R, sc.mu);
  TangentialLoad load;
  load.normal = {Control::force, sc.P};
  const double G = m.body.G;
  switch (sc.kind) {
    case Scenario::Kind::force: load.modes[0] = resultant(sc.level * sc.mu * sc.P); break;
    case Scenario::Kind::shift: load.modes[0] = amplitude(sc.level * sc.mu * sc.P / (G * a) * (sc.dimension == 3 ? 1.0 : a)); break;
    case Scenario::Kind::torsion: load.modes[2] = amplitude(sc.level); break;
  }
  if (sc.dimension == 3 && sc.kind != Scenario::Kind::torsion) load.modes[1] = resultant(0.0);
  SolverOptions solver;  // the defaults: auto, certificate_tol 1e-6
  const TangentialSolution s = problem.step(load, solver);
  ASSERT_EQ(s.report.status, SolveStatus::converged) << s.report.message;
  EXPECT_LE(s.report.certificate.worst(), solver.certificate_tol);
  if (sc.kind == Scenario::Kind::shift && sc.level >= 1e3) {
    EXPECT_EQ(s.n_stick, 0) << "full slip expected";
  }
  if (sc.level <= 1e-6 && sc.kind != Scenario::Kind::force) {
    EXPECT_EQ(s.n_slip, 0) << "full stick expected";
  }

  // The same solution shrunk by 0.1 %, with the slip that implies.
  const HalfSpace hs(g, m);
  const auto Ct = hs.tangential(OperatorKind::dense);
  const std::size_t N = g.size();
  std::vector<double> tau(s.tx);
  if (g.dimension == 3) tau.insert(tau.end(), s.ty.begin(), s.ty.end());
  std::vector<double> dtau(tau.size());
  for (std::size_t i = 0; i < tau.size(); ++i) dtau[i] = -1e-3 * tau[i];
  std::vector<double> dds;
  Ct->apply(dtau, dds);
  std::vector<double> tx(N), ty(N, 0.0), sx(N), sy(N, 0.0);
  for (std::size_t e = 0; e < N; ++e) {
    tx[e] = tau[e] + dtau[e];
    sx[e] = s.sx[e] + dds[e];
    if (g.dimension == 3) {
      ty[e] = tau[N + e] + dtau[N + e];
      sy[e] = s.sy[e] + dds[N + e];
    }
  }
  const Certificate bad = TangentialProblem::certify_friction(g, tx, ty, sx, sy, s.bound, Ct->diagonal(0));
  EXPECT_GT(std::max(bad.friction_law, bad.gap_function), 100.0 * solver.certificate_tol)
      << "friction law " << bad.friction_law << ", gap function " << bad.gap_function;
  // And the correct one measured the same way certifies (the certificate is the solver's).
  const Certificate good = TangentialProblem::certify_friction(g, s.tx, s.ty, s.sx, s.sy, s.bound, Ct->diagonal(0));
  EXPECT_LE(std::max(good.friction_law, good.gap_function), solver.certificate_tol);
}

std::string scenario_name(const ::testing::TestParamInfo<Scenario>& p) { return p.param.name; }

INSTANTIATE_TEST_SUITE_P(Ends, TangentialCertificates, ::testing::ValuesIn(scenarios()), scenario_name);

TEST(TangentialCertificates, ZeroTractionWithSlipIsCaught) {
  // tau = 0 where friction acts while the surfaces slip: wrong whatever the scale.
  const Grid g = Grid::make(3, 4, 4, -1.0, 1.0, -1.0, 1.0);
  const std::vector<double> zero(16, 0.0), bound(16, 1e12), slip(16, 1e-15);
  const Certificate c = TangentialProblem::certify_friction(g, zero, zero, slip, zero, bound, 1e-16);
  EXPECT_GE(c.friction_law, 1.0);
  const Certificate none = TangentialProblem::certify_friction(g, zero, zero, zero, zero, bound, 1e-16);
  EXPECT_EQ(none.worst(), 0.0);
}

TEST(TangentialCertificates, ANotFiniteSolutionNeverCertifies) {
  // A NaN or infinite traction or slip anywhere (an overflowed creepage, a diverged backend) must
  // fail the certificate; NaN used to drop out of the max() reductions and certify as 0.
  const Grid g = Grid::make(3, 4, 4, -1.0, 1.0, -1.0, 1.0);
  const std::vector<double> zero(16, 0.0), bound(16, 1.0);
  for (double bad : {std::nan(""), HUGE_VAL, -HUGE_VAL}) {
    std::vector<double> v(16, 0.1);
    v[5] = bad;
    for (int which = 0; which < 4; ++which) {
      const Certificate c = TangentialProblem::certify_friction(g, which == 0 ? v : zero, which == 1 ? v : zero,
                                                                which == 2 ? v : zero, which == 3 ? v : zero, bound, 1.0);
      EXPECT_FALSE(c.worst() <= 1e-6) << "component " << which << " holding " << bad;
    }
  }
  Certificate nan_measure;
  nan_measure.gap_function = std::nan("");
  EXPECT_TRUE(std::isinf(nan_measure.worst()));
}

}  // namespace
}  // namespace dc
