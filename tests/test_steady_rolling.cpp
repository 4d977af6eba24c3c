// The direct steady rolling solver (nlp/steady_rolling_solver): GMRES against a dense solve;
// Newton's steady state against the time march of the same discrete scheme (two independent
// routes to one fixed point), in 3-D with creepage and spin, in 2-D with dissimilar materials
// (kappa != 0) under force control; gross sliding; Carter's creep law up to F -> mu P.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <random>
#include <vector>

#include <Eigen/Dense>

#include "contact_closed_forms.hpp"
#include "gmres.hpp"
#include "hertz.hpp"
#include "profile.hpp"
#include "tangential_support.hpp"
#include "tangential_problem.hpp"

namespace dc {
namespace {

using namespace dc::test;

namespace cf = closed_form;

TEST(Gmres, SolvesANonSymmetricSystemAcrossRestarts) {
  const int n = 80;
  std::mt19937 rng(7);
  std::normal_distribution<double> normal(0.0, 1.0);
  Eigen::MatrixXd A(n, n);
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j) A(i, j) = (i == j ? 4.0 + i * 0.05 : 0.0) + 0.3 * normal(rng) / std::sqrt(n);
  std::vector<double> b(n), x;
  for (double& v : b) v = normal(rng);
  const Eigen::VectorXd exact = A.partialPivLu().solve(Eigen::Map<const Eigen::VectorXd>(b.data(), n));
  auto apply = [&](const std::vector<double>& in, std::vector<double>& out) {
    Eigen::Map<Eigen::VectorXd>(out.data(), n) = A * Eigen::Map<const Eigen::VectorXd>(in.data(), n);
  };
  for (bool preconditioned : {false, true}) {
    x.assign(n, 0.0);
    VectorMap jacobi;
    if (preconditioned)
      jacobi = [&](const std::vector<double>& in, std::vector<double>& out) {
        out.resize(n);
        for (int i = 0; i < n; ++i) out[i] = in[i] / A(i, i);
      };
    // Restart every 8 iterations: the restarted path must converge too.
    const GmresResult r = gmres(apply, jacobi, b, x, 1e-12, 8, 400);
    EXPECT_TRUE(r.converged) << r.relative_residual;
    double err = 0.0;
    for (int i = 0; i < n; ++i) err = std::max(err, std::abs(x[i] - exact[i]));
    EXPECT_LT(err, 1e-10 * exact.cwiseAbs().maxCoeff()) << "preconditioned " << preconditioned;
  }
  // A workspace kept over solves of different sizes (GmresWorkspace: the basis sized as used):
  // the leading 30 x 30 block, then the whole system again, each to the same accuracy.
  GmresWorkspace work;
  for (int size : {n, 30, n}) {
    const Eigen::MatrixXd As = A.topLeftCorner(size, size);
    const std::vector<double> bs(b.begin(), b.begin() + size);
    const Eigen::VectorXd exact_s = As.partialPivLu().solve(Eigen::Map<const Eigen::VectorXd>(bs.data(), size));
    auto apply_s = [&](const std::vector<double>& in, std::vector<double>& out) {
      out.resize(size);
      Eigen::Map<Eigen::VectorXd>(out.data(), size) = As * Eigen::Map<const Eigen::VectorXd>(in.data(), size);
    };
    x.assign(size, 0.0);
    const GmresResult r = gmres(apply_s, {}, bs, x, 1e-12, 8, 400, work);
    EXPECT_TRUE(r.converged) << "size " << size << ": " << r.relative_residual;
    double err = 0.0;
    for (int i = 0; i < size; ++i) err = std::max(err, std::abs(x[i] - exact_s[i]));
    EXPECT_LT(err, 1e-10 * exact_s.cwiseAbs().maxCoeff()) << "size " << size << " with a kept workspace";
  }
}

/// Largest difference of two traction fields relative to the largest bound.
double traction_difference(const TangentialSolution& a, const TangentialSolution& b) {
  double d = 0.0, f = 0.0;
  for (std::size_t e = 0; e < a.tx.size(); ++e) {
    d = std::max(d, std::hypot(a.tx[e] - b.tx[e], a.ty[e] - b.ty[e]));
    f = std::max(f, a.bound[e]);
  }
  return d / f;
}

RollingLoad rolling(double P, std::array<ModeControl, 3> modes, RollingLoad::Method method) {
  RollingLoad load;
  load.normal = {Control::force, P};
  load.modes = modes;
  load.method = method;
  return load;
}

TEST(SteadyRolling, NewtonMatchesTheTimeMarchWithCreepageAndSpin3d) {
  const auto m = steel_on_steel();
  const double R = 0.01, P = 100.0, mu = 0.3;
  const SphereSetup s = sphere_setup(20, 1.2, m, R, P);
  const double a = s.hz.a, xi = 0.2 * mu * a / R;  // about half the saturation creepage
  TangentialProblem problem(s.grid, m, s.heights, FrictionLaw::coulomb(mu));
  const std::array<ModeControl, 3> modes{amplitude(xi), amplitude(0.5 * xi), amplitude(0.5 * xi / a)};
  const TangentialSolution newton = problem.steady_rolling(rolling(P, modes, RollingLoad::Method::newton), test::native_tangential_solver());
  const TangentialSolution march = problem.steady_rolling(rolling(P, modes, RollingLoad::Method::marching), test::native_tangential_solver());
  expect_certified(newton);
  expect_certified(march);
  EXPECT_EQ(newton.marching_steps, 0);
  EXPECT_GT(march.marching_steps, s.grid.nx);  // the march crosses the contact several times
  EXPECT_GT(newton.n_stick, 0);
  EXPECT_GT(newton.n_slip, 0);
  // The march stops when a step changes tau by < 1e-8: it sits within ~1e-6 of its fixed point.
  const double diff = traction_difference(newton, march);
  std::printf("[ steady 3-D ] Newton vs march: |dtau| %.2e f_max, F (%.4f, %.4f) vs (%.4f, %.4f) N; %d steps\n",
              diff, newton.resultants[0], newton.resultants[1], march.resultants[0], march.resultants[1],
              march.marching_steps);
  EXPECT_LT(diff, 1e-5);
  for (int k = 0; k < 2; ++k) EXPECT_NEAR(newton.resultants[k], march.resultants[k], 1e-5 * mu * P);
  EXPECT_EQ(newton.n_stick, march.n_stick);
}

TEST(SteadyRolling, NewtonMatchesTheTimeMarchForDissimilarMaterialsUnderForceControl2d) {
  const MaterialPair m{Elastic::from_E_nu(2.1e11, 0.3), Elastic::from_E_nu(7.0e10, 0.33)};
  ASSERT_NE(m.kappa(), 0.0);
  const double R = 0.05, P = 1e5, mu = 0.3;
  const auto hz = hertz::cylinder2d(R, P, m.E_star());
  const Grid g = Grid::make(2, 120, 1, -1.3 * hz.a, 1.3 * hz.a, 0, 0);
  ProfileSpec prof;
  prof.type = ProfileType::cylinder;
  prof.radius = R;
  TangentialProblem problem(g, m, profile_heights(prof, g), FrictionLaw::coulomb(mu));
  const std::array<ModeControl, 3> modes{resultant(-0.6 * mu * P), amplitude(0.0), amplitude(0.0)};
  const TangentialSolution newton = problem.steady_rolling(rolling(P, modes, RollingLoad::Method::newton), test::native_tangential_solver());
  const TangentialSolution march = problem.steady_rolling(rolling(P, modes, RollingLoad::Method::marching), test::native_tangential_solver());
  expect_certified(newton);
  expect_certified(march);
  EXPECT_GT(newton.outer.iterations, 1);  // kappa != 0: the pressure follows the traction (4.26)
  EXPECT_NEAR(newton.resultants[0], -0.6 * mu * P, 1e-8 * mu * P);
  const double diff = traction_difference(newton, march);
  std::printf("[ steady 2-D kappa E* %.3f ] Newton vs march: |dtau| %.2e f_max, creepage %.6e vs %.6e\n", m.kappa() * m.E_star(),
              diff, newton.amplitudes[0], march.amplitudes[0]);
  EXPECT_LT(diff, 1e-5);
  EXPECT_NEAR(newton.amplitudes[0], march.amplitudes[0], 1e-5 * std::abs(march.amplitudes[0]));
}

TEST(SteadyRolling, BeyondSaturationTheWholeContactSlides) {
  const auto m = steel_on_steel();
  const double R = 0.01, P = 100.0, mu = 0.3;
  const SphereSetup s = sphere_setup(24, 1.2, m, R, P);
  TangentialProblem problem(s.grid, m, s.heights, FrictionLaw::coulomb(mu));
  const double xi = 3.0 * mu * s.hz.a / R;  // three times Carter's saturation creepage
  const TangentialSolution sol = problem.steady_rolling(
      rolling(P, {amplitude(xi), amplitude(0.0), amplitude(0.0)}, RollingLoad::Method::newton), test::native_tangential_solver());
  expect_certified(sol);
  EXPECT_EQ(sol.n_stick, 0);
  // Full slip against the creepage: F_x = -mu P up to the curvature of the slip direction
  // field, which the 3-D convective term makes tiny but not zero.
  std::printf("[ gross sliding ] F_x / (mu P) = %.8f\n", sol.resultants[0] / (mu * P));
  EXPECT_NEAR(sol.resultants[0], -mu * P, 5e-4 * mu * P);
  EXPECT_NEAR(sol.resultants[1], 0.0, 1e-9 * mu * P);
}

TEST(SteadyRolling, ForceControlUpToSaturation3d) {
  // Combined longitudinal and lateral force up to 0.99 mu P on a sphere: certified, the
  // resultant met, the creepage growing with the force and pointing against it (the force on
  // the body opposes the creepage), the stick area shrinking.
  const auto m = steel_on_steel();
  const double R = 0.01, P = 100.0, mu = 0.3;
  const SphereSetup s = sphere_setup(24, 1.2, m, R, P);
  TangentialProblem problem(s.grid, m, s.heights, FrictionLaw::coulomb(mu));
  const double cx = 0.8, cy = 0.6;  // direction of the force on the body: -(cx, cy)
  double previous_creepage = 0.0, previous_stick = 1e300;
  for (double ratio : {0.3, 0.7, 0.9, 0.99}) {
    const double F = ratio * mu * P;
    const TangentialSolution sol = problem.steady_rolling(
        rolling(P, {resultant(-cx * F), resultant(-cy * F), amplitude(0.0)}, RollingLoad::Method::newton),
        test::native_tangential_solver());
    expect_certified(sol);
    EXPECT_NEAR(sol.resultants[0], -cx * F, 1e-8 * mu * P);
    EXPECT_NEAR(sol.resultants[1], -cy * F, 1e-8 * mu * P);
    const double creepage = std::hypot(sol.amplitudes[0], sol.amplitudes[1]);
    std::printf("[ 3-D F/mu P = %.2f ] creepage (%.4e, %.4e), stick area %.3e m^2, %d Newton iterations\n", ratio,
                sol.amplitudes[0], sol.amplitudes[1], sol.stick_area, sol.newton_iterations);
    EXPECT_GT(sol.amplitudes[0], 0.0);
    EXPECT_GT(sol.amplitudes[1], 0.0);
    EXPECT_GT(creepage, previous_creepage);
    EXPECT_LT(sol.stick_area, previous_stick);
    previous_creepage = creepage;
    previous_stick = sol.stick_area;
  }
}

TEST(SteadyRolling, CarterCreepLawUpToSaturationUnderForceControl2d) {
  // Force control from F = 0.2 to 0.995 mu P: the creepage follows Carter's law
  // xi = (mu a / R)(1 - sqrt(1 - |F|/(mu P))) within 0.5 % on 200 strips over +-1.2 a, and
  // grows monotonically with the force.
  const auto m = steel_on_steel();
  const double R = 0.05, P = 1e5, mu = 0.3;
  const auto hz = hertz::cylinder2d(R, P, m.E_star());
  const Grid g = Grid::make(2, 200, 1, -1.2 * hz.a, 1.2 * hz.a, 0, 0);
  ProfileSpec prof;
  prof.type = ProfileType::cylinder;
  prof.radius = R;
  TangentialProblem problem(g, m, profile_heights(prof, g), FrictionLaw::coulomb(mu));
  double previous = 0.0;
  for (double ratio : {0.2, 0.5, 0.8, 0.95, 0.995}) {
    const TangentialSolution s = problem.steady_rolling(
        rolling(P, {resultant(-ratio * mu * P), amplitude(0.0), amplitude(0.0)}, RollingLoad::Method::newton),
        test::native_tangential_solver());
    expect_certified(s);
    const double carter = cf::carter_creepage(hz.a, R, mu, -ratio);
    std::printf("[ Carter F/mu P = %.3f ] creepage / Carter %.4f (%s)\n", ratio, s.amplitudes[0] / carter,
                s.report.message.c_str());
    EXPECT_NEAR(s.amplitudes[0] / carter, 1.0, 0.005);
    EXPECT_GT(s.amplitudes[0], previous);
    previous = s.amplitudes[0];
  }
}

}  // namespace
}  // namespace dc
