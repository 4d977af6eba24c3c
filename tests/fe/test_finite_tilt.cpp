// The moment rows of the body's rigid motion: a stiff hemisphere pressed off its axis tilts
// until the pressure's centre lies on the load's line of action. For a rigid sphere the tilt
// theta_y turns the profile r^2 / 2R into ((x - R theta_y)^2 + y^2) / 2R + const: the Hertz
// contact, centred at x = R theta_y, so the tilt is e / R for a load line at x = e, and the
// peak pressure is Hertz's.
#include <algorithm>
#include <array>
#include <cmath>
#include <vector>

#include <gtest/gtest.h>

#include "finite_contact.hpp"
#include "hertz.hpp"

namespace dc {
namespace {

constexpr double kR = 0.01, kE = 2.1e11, kNu = 0.3;

/// A hemisphere 1000 times stiffer than the half-space (rigid against it), contact elements a / 4.
FeBodySpec stiff_hemisphere(double a) {
  FeBodySpec s;
  s.shape = FeShape::hemisphere;
  s.radius = kR;
  s.elements = {8, 8, 4};
  s.contact_size = 0.25 * a;
  s.material = {fe::isotropic_stiffness(1000.0 * kE, kNu, "test"), 7800.0};
  return s;
}

/// The first moments of the pressure about the axes through the origin: sum p A x, sum p A y.
std::array<double, 2> pressure_moments(const std::vector<double>& p, const Grid& g) {
  std::array<double, 2> m{0.0, 0.0};
  for (int j = 0; j < g.ny; ++j)
    for (int i = 0; i < g.nx; ++i) {
      m[0] += p[g.index(i, j)] * g.area() * g.xc(i);
      m[1] += p[g.index(i, j)] * g.area() * g.yc(j);
    }
  return m;
}

/// The body `s` pressed by P on a 24 x 24 grid over 1.5 a, solved by the native backend.
struct TiltRun {
  Grid grid;
  FiniteContact contact;
  FiniteNormalSolution solution;
  TiltRun(const FeBodySpec& s, double a, double P)
      : grid(Grid::make(3, 24, 24, -1.5 * a, 1.5 * a, -1.5 * a, 1.5 * a)),
        contact(s, grid, Elastic::from_E_nu(kE, kNu)) {
    SolverOptions solver;
    solver.backend = Backend::native;
    solution = contact.solve_normal({Control::force, P}, solver);
  }
};

TEST(FiniteTilt, EccentricLoadTiltsAStiffHemisphereByEOverR) {
  const double Es = kE / (1.0 - kNu * kNu);
  const double a_target = 0.06 * kR;
  const double P = 4.0 * Es * a_target * a_target * a_target / (3.0 * kR);
  const auto h = hertz::sphere(kR, P, Es);
  const double e = 0.3 * h.a;
  FeBodySpec s = stiff_hemisphere(h.a);
  s.load_line = std::array<double, 2>{e, 0.0};
  TiltRun run(s, h.a, P);
  const Grid& g = run.grid;
  FiniteContact& fc = run.contact;
  const FiniteNormalSolution& sol = run.solution;
  const SolverOptions solver;
  ASSERT_EQ(sol.contact.report.status, SolveStatus::converged) << sol.contact.report.message;
  // The moment rows hold: the pressure's centre is on the load line (to the certificate).
  const auto [mx, my] = pressure_moments(sol.contact.pressure, g);
  EXPECT_NEAR(mx / P, e, solver.certificate_tol * h.a);
  EXPECT_NEAR(my / P, 0.0, solver.certificate_tol * h.a);
  // The tilt: e / R within the 3 % of the stiff-hemisphere Hertz test (mesh and grid).
  EXPECT_NEAR(fc.tilt()[1], e / kR, 0.03 * e / kR);
  EXPECT_NEAR(fc.tilt()[0], 0.0, 1e-3 * e / kR);
  // The contact is Hertz's, shifted: peak pressure p0 within 3 %, its element within one cell of x = e.
  const auto peak = std::max_element(sol.contact.pressure.begin(), sol.contact.pressure.end());
  EXPECT_NEAR(*peak, h.p0, 0.03 * h.p0);
  const auto k = static_cast<std::size_t>(peak - sol.contact.pressure.begin());
  EXPECT_NEAR(g.xc(static_cast<int>(k % static_cast<std::size_t>(g.nx))), e, g.dx);
}

TEST(FiniteTilt, GivenTiltShiftsTheContactByRTheta) {
  // The same geometry with the tilt given instead: the pressure's centre at x = R theta_y.
  const double Es = kE / (1.0 - kNu * kNu);
  const double P = 2000.0;
  const auto h = hertz::sphere(kR, P, Es);
  const double theta = 0.3 * h.a / kR;
  FeBodySpec s = stiff_hemisphere(h.a);
  s.tilt = {0.0, theta};
  TiltRun run(s, h.a, P);
  const Grid& g = run.grid;
  const FiniteNormalSolution& sol = run.solution;
  ASSERT_EQ(sol.contact.report.status, SolveStatus::converged) << sol.contact.report.message;
  const double mx = pressure_moments(sol.contact.pressure, g)[0];
  EXPECT_NEAR(mx / P, kR * theta, 0.03 * kR * theta);
}

}  // namespace
}  // namespace dc
