// The undeformed gap of a body at its current orientation ((2.6)): an ellipsoid turned by 90
// degrees about z presses the swapped Hertz ellipse. On a square grid symmetric about the
// origin the turn maps the grid onto itself, so the pressure is the unturned one transposed
// (to the solver's tolerance), and both have the Hertz ellipse's second moments: for
// p = p0 sqrt(1 - x^2/a^2 - y^2/b^2), sum p x^2 / sum p = a^2 / 5 (within the grid's error).
#include <gtest/gtest.h>

#include <cmath>

#include "case_model.hpp"
#include "contact_wrench.hpp"
#include "dynamic_case_support.hpp"
#include "hertz.hpp"

namespace dc::dynamics {
namespace {

nlohmann::json ellipsoid_case() {
  const double L = 1.2e-3;
  return test::steel_dynamic_case("turned-ellipsoid", {{"type", "ellipsoid"}, {"radius_x", 0.04}, {"radius_y", 0.01}},
                                  {{"nx", 32}, {"ny", 32}, {"x", {-L, L}}, {"y", {-L, L}}},
                                  {{"mass", 1.0}, {"inertia", {1e-4, 1e-4, 1e-4}}, {"radius", 0.01}}, 100.0, 1e-4,
                                  "quasi_static");
}

struct Moments {
  double xx, yy;
};

Moments second_moments(const Grid& g, const std::vector<double>& p) {
  double s = 0.0, xx = 0.0, yy = 0.0;
  for (int j = 0; j < g.ny; ++j)
    for (int i = 0; i < g.nx; ++i) {
      const double q = p[g.index(i, j)];
      s += q;
      xx += q * g.xc(i) * g.xc(i);
      yy += q * g.yc(j) * g.yc(j);
    }
  return {xx / s, yy / s};
}

TEST(DynamicTurnedGap, EllipsoidTurnedAboutZPressesTheSwappedHertzEllipse) {
  const Case c = build_case(ellipsoid_case());
  const Grid& g = c.grid;
  ContactWrench contact(c);
  const double P = 100.0;
  auto pressure_at = [&](double heading) {
    const StepKinematics k{Eigen::Vector3d(0, 0, 0.01),
                           Eigen::Quaterniond(Eigen::AngleAxisd(heading, Eigen::Vector3d::UnitZ())),
                           Eigen::Vector3d::Zero(), Eigen::Vector3d::Zero(), 1e-4};
    contact.begin_step(1e-4);
    contact.evaluate(k, -P);
    EXPECT_TRUE(contact.state().converged) << contact.state().message;
    return *contact.state().pressure;
  };
  const std::vector<double> p0 = pressure_at(0.0);
  const std::vector<double> p90 = pressure_at(M_PI / 2.0);
  double pmax = 0.0, diff = 0.0;
  for (int j = 0; j < g.ny; ++j)
    for (int i = 0; i < g.nx; ++i) {
      pmax = std::max(pmax, p0[g.index(i, j)]);
      diff = std::max(diff, std::abs(p90[g.index(i, j)] - p0[g.index(j, i)]));
    }
  EXPECT_LE(diff / pmax, 10.0 * c.solver.certificate_tol) << "the turned pressure is the transposed one";
  // Hertz: h = x^2/(2 Rx) + y^2/(2 Ry), the long semi-axis along the flatter direction x.
  const auto hz = hertz::elliptic(1.0 / (2.0 * 0.04), 1.0 / (2.0 * 0.01), P, c.materials.E_star());
  const double a = std::max(hz.a, hz.b), b = std::min(hz.a, hz.b);
  const Moments m0 = second_moments(g, p0), m90 = second_moments(g, p90);
  const double tol = 2.0 * g.dx / b;  // the grid's resolution of the short semi-axis
  EXPECT_NEAR(m0.xx / (a * a / 5.0), 1.0, tol);
  EXPECT_NEAR(m0.yy / (b * b / 5.0), 1.0, tol);
  EXPECT_NEAR(m90.xx / (b * b / 5.0), 1.0, tol) << "turned: the short axis along x";
  EXPECT_NEAR(m90.yy / (a * a / 5.0), 1.0, tol);
}

}  // namespace
}  // namespace dc::dynamics
