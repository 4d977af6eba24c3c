// Slow validations (label "slow"): the finer grids of test_tangential_validation.cpp.
//  * Kalker's linear creep coefficients on 64^2 (3-D steady rolling, circular contact).
//  * Spence's stick ratio on 64^2 with 24 load steps, two values of beta/mu.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <vector>

#include "contact_closed_forms.hpp"
#include "hertz.hpp"
#include "profile.hpp"
#include "summary_entries.hpp"
#include "tangential_problem.hpp"
#include "tangential_support.hpp"

namespace dc {
namespace {

namespace cf = closed_form;


using test::amplitude;

TEST(SlowTangentialValidation, KalkerLinearCreepCoefficients64) {
  const double nu = 0.25;
  const Elastic e = Elastic::from_E_nu(2.1e11, nu);
  const MaterialPair m{e, e};
  const double R = 0.01, P = 100.0, mu = 10.0;
  const auto hz = hertz::sphere(R, P, m.E_star());
  const double a = hz.a, L = 1.1 * a;
  const Grid g = Grid::make(3, 64, 64, -L, L, -L, L);
  ProfileSpec prof;
  prof.type = ProfileType::sphere;
  prof.radius = R;
  TangentialProblem problem(g, m, profile_heights(prof, g), FrictionLaw::coulomb(mu));
  const double xi = 1e-3 * a / R, phi = xi / a;
  auto run = [&](double cx, double cy, double sp) {
    RollingLoad load;
    load.normal = {Control::force, P};
    load.modes = {amplitude(cx), amplitude(cy), amplitude(sp)};
    const TangentialSolution s = problem.steady_rolling(load, test::native_tangential_solver());
    EXPECT_NE(s.report.status, SolveStatus::failed) << s.report.message;
    EXPECT_LT(s.report.certificate.friction_law, 1e-6) << dc::output::to_json(s.report.certificate).dump();
    EXPECT_LT(s.report.certificate.gap_function, 1e-4) << dc::output::to_json(s.report.certificate).dump();
    return s;
  };
  const double G = e.G;
  const double c11 = -run(xi, 0.0, 0.0).resultants[0] / (G * a * a * xi);
  const double c22 = -run(0.0, xi, 0.0).resultants[1] / (G * a * a * xi);
  const double c23 = -run(0.0, 0.0, phi).resultants[1] / (G * a * a * a * phi);
  const auto k = cf::kalker_circular(nu);
  std::printf("[ Kalker n=64 nu=0.25 ] C11 %.4f (%.2f)  C22 %.4f (%.2f)  C23 %.4f (%.2f)\n", c11, k.c11, c22, k.c22,
              c23, k.c23);
  // 64^2 over +-1.1 a (dx = a/29): within 2 % (48^2 gives 1.6-1.9 %, 32^2 3.1-3.5 %).
  EXPECT_NEAR(c11 / k.c11, 1.0, 0.02);
  EXPECT_NEAR(c22 / k.c22, 1.0, 0.02);
  EXPECT_NEAR(c23 / k.c23, 1.0, 0.02);
}

/// Stick ratio per load step: rigid sphere on a nearly incompressible substrate (nu = 0.49,
/// beta = -0.0196, so the shear's effect on the pressure, neglected by the closed form, is
/// negligible), contact radius from a_max/2 to a_max in `steps` steps on 64^2.
std::vector<double> spence_history(double beta_over_mu, int steps) {
  const MaterialPair m{Elastic::make_rigid(), Elastic::from_E_nu(7e10, 0.49)};
  const double mu = std::abs(cf::dundurs_beta(m)) / beta_over_mu;
  const double R = 0.01, P_max = 100.0;
  const auto hz = hertz::sphere(R, P_max, m.E_star());
  const double L = 1.2 * hz.a;
  const Grid g = Grid::make(3, 64, 64, -L, L, -L, L);
  ProfileSpec prof;
  prof.type = ProfileType::sphere;
  prof.radius = R;
  TangentialProblem problem(g, m, profile_heights(prof, g), FrictionLaw::coulomb(mu));
  TangentialLoad load;
  load.modes = {amplitude(0.0), amplitude(0.0), amplitude(0.0)};
  std::vector<double> out;
  for (int k = 0; k <= steps; ++k) {
    const double s_a = 0.5 + 0.5 * k / steps;
    load.normal = {Control::force, P_max * s_a * s_a * s_a};
    const TangentialSolution s = problem.step(load, test::native_tangential_solver());
    EXPECT_EQ(s.report.status, SolveStatus::converged) << s.report.message;
    double area = 0.0;
    for (double f : s.bound) area += f > 0.0 ? g.area() : 0.0;
    out.push_back(std::sqrt(s.stick_area / area));
  }
  return out;
}

TEST(SlowTangentialValidation, SpenceStickRatioFine) {
  // |beta|/mu = 1.5 (c/a = 0.7015) and 3 (c/a = 0.1953), 24 load steps on 64^2 (dx = a_max/27):
  // after the first quarter of the history, within 0.015 of the closed form.
  for (double bm : {1.5, 3.0}) {
    const double ratio = cf::spence_stick_ratio(bm);
    const auto c = spence_history(bm, 24);
    for (std::size_t k = 6; k < c.size(); ++k) EXPECT_NEAR(c[k], ratio, 0.015) << "beta/mu " << bm << " step " << k;
    std::printf("[ Spence 64 ] beta/mu %.1f: c/a %.4f .. %.4f (Spence %.4f)\n", bm,
                *std::min_element(c.begin() + 6, c.end()), *std::max_element(c.begin() + 6, c.end()), ratio);
  }
}

}  // namespace
}  // namespace dc
