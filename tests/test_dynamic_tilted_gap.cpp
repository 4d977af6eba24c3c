// The gap of a body tilted about a horizontal axis ((2.6) at the body's full orientation,
// docs/dynamics.md "Body shapes").
// - Ellipsoid of semi-axes a, b, c (curvature radii a^2/c, b^2/c at its lowest point) tilted by
//   theta about y: in body axes the vertical is n = (-sin, 0, cos), the lowest point is
//   S = sqrt(a^2 sin^2 + c^2 cos^2) below the centre and x0 = (a^2 - c^2) sin cos / S ahead of
//   it, and the curvature radii there are a^2 c^2 / S^3 (along x: the support function h(n) of
//   the x-z ellipse gives h + h'' = a^2 c^2 / h^3) and b^2 / S (the Gaussian curvature of an
//   ellipsoid, h^4 / (a b c)^2). Pressed, the contact is the Hertz ellipse of those radii centred
//   at x0, and the approach at centre height z is S - z. At 90 degrees: radii c^2/a, b^2/a, depth a.
// - A wheel (cylinder about the body's y axis) is the same rolled by any angle; cambered by phi
//   about x it touches with the rim of its lower end face.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>

#include "body_gap.hpp"
#include "case_model.hpp"
#include "contact_wrench.hpp"
#include "dynamic_case_support.hpp"
#include "dynamic_simulation.hpp"
#include "errors.hpp"
#include "hertz.hpp"
#include "material.hpp"
#include "profile_turned.hpp"

namespace dc::dynamics {
namespace {

// The ellipsoid: curvature radii 0.04 and 0.0225 upright, depth c = 0.01: a = 0.02, b = 0.015.
constexpr double kRx = 0.04, kRy = 0.0225, kC = 0.01;
const double kA = std::sqrt(kRx * kC), kB = std::sqrt(kRy * kC);
constexpr double kLoad = 100.0;

struct TiltedEllipsoid {
  double depth, x0, rho_x, rho_y;
};

TiltedEllipsoid closed_form(double theta) {
  const double s = std::sin(theta), c = std::cos(theta);
  const double S = std::sqrt(kA * kA * s * s + kC * kC * c * c);
  return {S, (kA * kA - kC * kC) * s * c / S, kA * kA * kC * kC / (S * S * S), kB * kB / S};
}

nlohmann::json ellipsoid_case(double x_lo, double x_hi, double y_half, int n, const char* normal_model) {
  return test::steel_dynamic_case("tilted-ellipsoid", {{"type", "ellipsoid"}, {"radius_x", kRx}, {"radius_y", kRy}},
                                  {{"nx", n}, {"ny", n}, {"x", {x_lo, x_hi}}, {"y", {-y_half, y_half}}},
                                  {{"mass", 1.0}, {"inertia", {1e-4, 1e-4, 1e-4}}, {"radius", kC}}, kLoad, 1e-4,
                                  normal_model);
}

StepKinematics at_rest(double z, const Eigen::Quaterniond& q) {
  return {Eigen::Vector3d(0, 0, z), q, Eigen::Vector3d::Zero(), Eigen::Vector3d::Zero(), 1e-4};
}

struct PressedContact {
  double force = 0.0, approach = 0.0, peak = 0.0, x_centroid = 0.0, x_extent = 0.0, y_extent = 0.0;
};

/// The contact of `c` at rest at orientation q: quasi-static under kLoad, or at centre height z.
PressedContact press(const Case& c, const Eigen::Quaterniond& q, double z, double x_centre) {
  ContactWrench contact(c);
  contact.begin_step(1e-4);
  const Wrench w = contact.evaluate(at_rest(z, q), -kLoad);
  const ContactState& s = contact.state();
  EXPECT_TRUE(s.converged) << s.message;
  PressedContact out;
  out.force = w.force.z();
  out.approach = s.approach;
  const Grid& g = c.grid;
  double sum = 0.0, sx = 0.0;
  for (int j = 0; j < g.ny; ++j)
    for (int i = 0; i < g.nx; ++i) {
      const double p = (*s.pressure)[g.index(i, j)];
      if (!(p > 0.0)) continue;
      sum += p;
      sx += p * g.xc(i);
      out.peak = std::max(out.peak, p);
      out.x_extent = std::max(out.x_extent, std::abs(g.xc(i) - x_centre) + 0.5 * g.dx);
      out.y_extent = std::max(out.y_extent, std::abs(g.yc(j)) + 0.5 * g.dy);
    }
  out.x_centroid = sx / sum;
  return out;
}

Eigen::Quaterniond about_y(double angle) { return Eigen::Quaterniond(Eigen::AngleAxisd(angle, Eigen::Vector3d::UnitY())); }

// Tolerances of the 48^2 grid over +-1.25 semi-axes (dx = a/19), as tests/test_normal_hertz's
// elliptic contact: approach 0.5 %, peak 1.5 %, semi-axes within one element; the force at a
// given approach follows P ~ delta^(3/2): 0.75 %.
void expect_hertz(double theta) {
  const TiltedEllipsoid t = closed_form(theta);
  const double E = MaterialPair{Elastic::from_E_nu(2.1e11, 0.3), Elastic::from_E_nu(2.1e11, 0.3)}.E_star();
  const auto hz = hertz::elliptic(0.5 / t.rho_x, 0.5 / t.rho_y, kLoad, E);
  const Case c = build_case(
      ellipsoid_case(t.x0 - 1.25 * hz.a, t.x0 + 1.25 * hz.a, 1.25 * hz.b, 48, "quasi_static"));
  const Grid& g = c.grid;
  const PressedContact qs = press(c, about_y(theta), kC, t.x0);
  EXPECT_NEAR(qs.approach / hz.approach, 1.0, 5e-3);
  EXPECT_NEAR(qs.peak / hz.p0, 1.0, 1.5e-2);
  EXPECT_NEAR(qs.x_extent, hz.a, 1.01 * g.dx);
  EXPECT_NEAR(qs.y_extent, hz.b, 1.01 * g.dy);
  // The centre: the lowest point's closed form to a tenth of an element (the contact is the
  // Hertz ellipse about x0; its discrete centroid is off by the grid's sampling only).
  EXPECT_NEAR(qs.x_centroid, t.x0, 0.1 * g.dx);
  // The dynamic normal model: the approach is the lowest point's depth S - z.
  Case dynamic = build_case(ellipsoid_case(t.x0 - 1.25 * hz.a, t.x0 + 1.25 * hz.a, 1.25 * hz.b, 48, "dynamic"));
  const double z = t.depth - hz.approach;
  const PressedContact dyn = press(dynamic, about_y(theta), z, t.x0);
  EXPECT_NEAR(dyn.approach, t.depth - z, 1e-12 * t.depth);
  EXPECT_NEAR(dyn.force / kLoad, 1.0, 7.5e-3);
}

TEST(DynamicTiltedGap, EllipsoidTurnedUpOnItsLongAxisPressesTheHertzEllipseOfItsEnd) {
  // 90 degrees about y: the long semi-axis a vertical, radii c^2/a and b^2/a, depth a.
  const TiltedEllipsoid t = closed_form(M_PI / 2.0);
  EXPECT_NEAR(t.depth, kA, 1e-15);
  EXPECT_NEAR(t.rho_x, kC * kC / kA, 1e-15);
  EXPECT_NEAR(t.rho_y, kB * kB / kA, 1e-15);
  expect_hertz(M_PI / 2.0);
}

TEST(DynamicTiltedGap, SmallTiltMovesTheContactToTheTiltedLowestPoint) {
  // theta = 0.01: x0 = (a^2 - c^2) theta / c ~ 0.3 mm, about one contact length; the depth grows
  // by (a^2 - c^2) theta^2 / (2c) = 1.5 um, more than the Hertz approach.
  expect_hertz(0.01);
}

TEST(DynamicTiltedGap, LowestPointMovesWithTheTurnAsTheClosedForm) {
  // BodyGap::sensitivity, for Newton's Jacobian: turned further about y, the lowest point runs
  // ahead by dx0/dtheta = (a^2 - c^2) (cos 2 theta - sin cos x0 / S) / S and the centre rises by
  // dS/dtheta = x0; a turn about z carries the lowest point round, d lowest_y / d theta_z = x0.
  const Case c = build_case(ellipsoid_case(-1e-3, 1e-3, 1e-3, 8, "dynamic"));
  const BodyGap gap(c.profile, c.grid, kC);
  for (double theta : {0.0, 0.01, 0.3, 1.2}) {
    const TiltedEllipsoid t = closed_form(theta);
    const double s = std::sin(theta), co = std::cos(theta);
    const double dx0 = (kA * kA - kC * kC) * (std::cos(2.0 * theta) - s * co * t.x0 / t.depth) / t.depth;
    const GapSensitivity d = gap.sensitivity(about_y(theta));
    const double tol = 1e-6 * kA;  // central differences over 1e-6 rad
    EXPECT_NEAR(d.lowest(0, 1), dx0, tol) << theta;
    EXPECT_NEAR(d.centre_height(1), t.x0, tol) << theta;
    EXPECT_NEAR(d.lowest(1, 2), t.x0, tol) << theta;
    EXPECT_NEAR(d.lowest(1, 1), 0.0, tol) << theta;
  }
  // A sphere's gap is invariant: nothing moves.
  nlohmann::json sphere = ellipsoid_case(-1e-3, 1e-3, 1e-3, 8, "dynamic");
  sphere["profile"] = {{"type", "sphere"}, {"radius", kC}};
  const Case cs = build_case(sphere);
  const BodyGap round(cs.profile, cs.grid, kC);
  EXPECT_EQ(round.sensitivity(about_y(0.3)).lowest.norm(), 0.0);
}

TEST(DynamicTiltedGap, UprightEllipsoidKeepsTheProfileGap) {
  const Case c = build_case(ellipsoid_case(-1e-3, 1e-3, 1e-3, 16, "dynamic"));
  BodyGap gap(c.profile, c.grid, kC);
  const Eigen::Quaterniond turned(Eigen::AngleAxisd(0.7, Eigen::Vector3d::UnitZ()));
  EXPECT_TRUE(gap.update(turned, 0.0));
  EXPECT_EQ(gap.heights(), profile_heights(c.profile, c.grid, 0.7)) << "bit-identical to the turned profile";
  EXPECT_EQ(gap.centre_height(), kC);
  EXPECT_FALSE(gap.update(turned, 0.0)) << "nothing to recompute";
  // Tilted, the exact surface: to second order the same quadratic gap about the moved lowest point.
  EXPECT_TRUE(gap.update(about_y(1e-3), 0.0));
  EXPECT_NEAR(gap.lowest_point().x(), closed_form(1e-3).x0, 1e-15);
}

TEST(DynamicTiltedGap, FrictionlessEllipsoidRocksWithTheMomentOfItsMovingLowestPoint) {
  // Spun slowly about y under a constant quasi-static load P, without friction: the centre of
  // mass stays put and the contact force P at the lowest point x0(psi) gives the moment
  // M_y = -x0 P at every step. For small psi, x0 = (Rx - c) psi: the body rocks as a pendulum,
  // I_y psi'' = -(Rx - c) P psi, psi = (w0 / W) sin(W t), W^2 = (Rx - c) P / I_y.
  const double Iy = 1e-4, W = std::sqrt((kRx - kC) * kLoad / Iy), amplitude = 0.01;
  const double period = 2.0 * M_PI / W, dt = period / 48.0;
  const double reach = (kRx - kC) * amplitude + 1.3 * 3.2e-4;  // x0 and the Hertz semi-axis
  nlohmann::json doc = ellipsoid_case(-reach, reach, 1.3 * 3.2e-4, 32, "quasi_static");
  doc["body"]["inertia"] = {Iy, Iy, Iy};
  doc["body"]["initial"] = {{"omega", {0.0, amplitude * W, 0.0}}};
  doc["time"] = {{"dt", dt}, {"t_end", 0.5 * period}, {"scheme", "bdf2"}};
  const Case c = build_case(doc);
  DynamicSimulation run(c);
  int steps = 0, worst_newton = 0;
  const DynamicResult r = run.run([&](const DynamicSample& s) {
    ++steps;
    worst_newton = std::max(worst_newton, s.newton_iterations);
    const Eigen::Vector3d ex = s.state.orientation * Eigen::Vector3d::UnitX();
    const double psi = std::atan2(-ex.z(), ex.x());  // about y
    // The moment of the contact at the lowest point: its centroid to a tenth of an element.
    EXPECT_NEAR(s.contact.moment.y(), -closed_form(psi).x0 * kLoad, 0.1 * c.grid.dx * kLoad) << s.state.time;
    // The pendulum: the scheme's phase and amplitude errors (bdf2, 48 steps a period, a bdf1
    // first step) stay within 5 % of the amplitude over half a period.
    EXPECT_NEAR(psi, amplitude * std::sin(W * s.state.time), 0.05 * amplitude) << s.state.time;
  });
  EXPECT_TRUE(r.completed) << r.status;
  EXPECT_EQ(steps, 24);
  // The step's Jacobian carries the lowest point's motion with the turn (BodyGap::sensitivity):
  // Newton converges in two iterations (four without it: the moment's stiffness unknown to it).
  EXPECT_LE(worst_newton, 2);
}

TEST(DynamicTiltedGap, RockingEllipsoidLiftsItsCentreByTheDepthOfItsLowestPoint) {
  // The same rocking with the dynamic normal model: the centre of mass is free to move
  // vertically. The Hertz frequency (~1e4 rad/s) is far above the rocking's (173 rad/s) and
  // bdf2 damps it within a step, so the centre follows the quasi-static height
  // z = S(psi) - delta_H(psi): it rises by (a^2 - c^2) psi^2 / (2c) (1.5 um at psi = 0.01,
  // over half the Hertz approach) while the contact stays Hertzian.
  const double Iy = 1e-4, W = std::sqrt((kRx - kC) * kLoad / Iy), amplitude = 0.01;
  const double period = 2.0 * M_PI / W, dt = period / 48.0;
  const double reach = (kRx - kC) * amplitude + 1.3 * 3.2e-4;
  const double E = MaterialPair{Elastic::from_E_nu(2.1e11, 0.3), Elastic::from_E_nu(2.1e11, 0.3)}.E_star();
  auto hertz_at = [&](double psi, double P) {
    const TiltedEllipsoid t = closed_form(psi);
    return hertz::elliptic(0.5 / t.rho_x, 0.5 / t.rho_y, P, E);
  };
  nlohmann::json doc = ellipsoid_case(-reach, reach, 1.3 * 3.2e-4, 32, "dynamic");
  doc["body"]["inertia"] = {Iy, Iy, Iy};
  doc["body"]["initial"] = {{"position", {0.0, 0.0, kC - hertz_at(0.0, kLoad).approach}},
                            {"omega", {0.0, amplitude * W, 0.0}}};
  doc["time"] = {{"dt", dt}, {"t_end", 0.5 * period}, {"scheme", "bdf2"}};
  const Case c = build_case(doc);
  DynamicSimulation run(c);
  double lift = 0.0;
  int worst_newton = 0;
  const DynamicResult r = run.run([&](const DynamicSample& s) {
    worst_newton = std::max(worst_newton, s.newton_iterations);
    const Eigen::Vector3d ex = s.state.orientation * Eigen::Vector3d::UnitX();
    const double psi = std::atan2(-ex.z(), ex.x());
    const auto hz = hertz_at(psi, s.contact.force.z());
    const double z = closed_form(psi).depth - hz.approach;
    lift = std::max(lift, s.state.position.z() - c.dynamic->position[2]);
    // The grid's approach error: 0.5 % at dx = a/19 (test_normal_hertz), 2 % allowed at a/7.
    EXPECT_NEAR(s.state.position.z(), z, 0.02 * hz.approach) << s.state.time;
  });
  EXPECT_TRUE(r.completed) << r.status;
  EXPECT_GT(lift, 0.5 * (kA * kA - kC * kC) * amplitude * amplitude / (2.0 * kC));
  // With the lowest point's motion and the approach's change in the Jacobian: at most four
  // iterations (five without; the normal stiffness is the contact footprint's flat punch).
  EXPECT_LE(worst_newton, 4);
}

nlohmann::json wheel_case(int ny) {
  return test::steel_dynamic_case("cambered-wheel", {{"type", "cylinder"}, {"radius", 0.1}, {"length", 0.01}},
                                  {{"nx", 12}, {"ny", ny}, {"x", {-4.5e-4, 4.5e-4}}, {"y", {-6.0e-3, 6.0e-3}}},
                                  {{"mass", 100.0}, {"inertia", {0.25, 0.5, 0.25}}, {"radius", 0.1}}, 1000.0, 0.02,
                                  "quasi_static");
}

TEST(DynamicTiltedGap, WheelRolledAboutItsAxisKeepsItsGapBitForBit) {
  const Case c = build_case(wheel_case(12));
  BodyGap gap(c.profile, c.grid, 0.1);
  const std::vector<double> upright = gap.heights();
  for (double roll : {0.3, 1.7, M_PI / 2.0, M_PI, 4.0, -2.2}) {
    EXPECT_FALSE(gap.update(about_y(roll), 0.0)) << roll;
    EXPECT_EQ(gap.heights(), upright) << roll;
    EXPECT_EQ(gap.centre_height(), 0.1);
  }
  // Turned about z, then rolled: the turned gap, whatever the roll.
  const Eigen::Quaterniond heading(Eigen::AngleAxisd(0.4, Eigen::Vector3d::UnitZ()));
  EXPECT_TRUE(gap.update(heading, 0.0));
  const std::vector<double> turned = gap.heights();
  const Eigen::Vector3d ex = heading * Eigen::Vector3d::UnitX();
  EXPECT_EQ(turned, profile_heights(c.profile, c.grid, std::atan2(ex.y(), ex.x())));
  for (double roll : {0.3, 1.7, M_PI, -2.2}) {
    EXPECT_FALSE(gap.update(heading * about_y(roll), 0.0)) << roll;
    EXPECT_EQ(gap.heights(), turned);
  }
  // Cambered, then rolled: still one gap.
  const Eigen::Quaterniond camber(Eigen::AngleAxisd(2e-3, Eigen::Vector3d::UnitX()));
  EXPECT_TRUE(gap.update(camber, 0.0));
  const std::vector<double> cambered = gap.heights();
  for (double roll : {0.3, 1.7, M_PI, -2.2}) {
    EXPECT_FALSE(gap.update(camber * about_y(roll), 0.0)) << roll;
    EXPECT_EQ(gap.heights(), cambered);
  }
}

TEST(DynamicTiltedGap, CamberedWheelTouchesWithItsRim) {
  // Camber phi about x: the axis u = (0, cos, sin); the lowest point is on the rim of the end at
  // y = -L/2: y* = -(L/2) cos(phi) + R sin(phi), R cos(phi) + (L/2) sin(phi) below the centre.
  // The far end is L sin(phi) = 50 um higher, about five times the approach: the contact is a
  // band at the rim.
  const double R = 0.1, L = 0.01, phi = 5e-3;
  const Case c = build_case(wheel_case(40));
  const Grid& g = c.grid;
  const Eigen::Quaterniond camber(Eigen::AngleAxisd(phi, Eigen::Vector3d::UnitX()));
  const double y_rim = -0.5 * L * std::cos(phi) + R * std::sin(phi);
  {
    BodyGap gap(c.profile, g, R);
    gap.update(camber, 0.0);
    EXPECT_NEAR(gap.centre_height(), R * std::cos(phi) + 0.5 * L * std::sin(phi), 1e-16);
    EXPECT_NEAR(gap.lowest_point().x(), 0.0, 1e-16);
    EXPECT_NEAR(gap.lowest_point().y(), y_rim, 1e-16);
  }
  ContactWrench contact(c);
  contact.begin_step(0.02);
  const Wrench w = contact.evaluate(at_rest(R, camber), -1000.0);
  ASSERT_TRUE(contact.state().converged) << contact.state().message;
  EXPECT_NEAR(w.force.z(), 1000.0, 1e-6 * 1000.0);
  const std::vector<double>& p = *contact.state().pressure;
  double sum = 0.0, sy = 0.0, nearest = 1.0, farthest = -1.0;
  for (int j = 0; j < g.ny; ++j)
    for (int i = 0; i < g.nx; ++i) {
      const double pe = p[g.index(i, j)];
      if (!(pe > 0.0)) continue;
      sum += pe;
      sy += pe * g.yc(j);
      nearest = std::min(nearest, std::abs(g.yc(j) - y_rim));
      farthest = std::max(farthest, g.yc(j) - y_rim);
    }
  EXPECT_LE(nearest, g.dy) << "the rim is loaded";
  EXPECT_LE(farthest, 0.25 * L) << "the contact is a band at the rim, not the whole width";
  EXPECT_LT(sy / sum, y_rim + 0.125 * L);
  // The moment about x of the contact force at the rim: M_x = y P (lever (y, -h) x (0, 0, P)).
  EXPECT_NEAR(w.moment.x(), sy / sum * w.force.z(), 1e-9 * std::abs(w.moment.x()));
}

TEST(DynamicTiltedGap, BodiesDefinedUprightOnlyRejectATilt) {
  const Case c = build_case(wheel_case(12));
  auto tilted = [](double angle, const Eigen::Vector3d& axis) { return Eigen::Quaterniond(Eigen::AngleAxisd(angle, axis)); };
  auto expect_error = [&](const ProfileSpec& profile, double radius, const Eigen::Quaterniond& q, const std::string& key) {
    BodyGap gap(profile, c.grid, radius);
    try {
      gap.update(q, 0.25);
      ADD_FAILURE() << "no error for " << to_string(profile.type);
    } catch (const InputError& e) {
      EXPECT_EQ(e.key(), key);
      EXPECT_NE(std::string(e.what()).find("t = 0.25 s"), std::string::npos) << e.what();
    }
  };
  ProfileSpec quadratic;
  quadratic.type = ProfileType::quadratic;
  quadratic.a = quadratic.b = 10.0;
  expect_error(quadratic, 0.05, tilted(1e-3, Eigen::Vector3d::UnitY()), "profile.type");
  ProfileSpec punch;
  punch.type = ProfileType::flat_punch;
  punch.radius = 1e-3;
  expect_error(punch, 0.05, tilted(1e-3, Eigen::Vector3d::UnitX()), "profile.type");
  ProfileSpec unbounded = c.profile;
  unbounded.length = 0.0;
  expect_error(unbounded, 0.1, tilted(1e-3, Eigen::Vector3d::UnitX()), "profile.length");
  expect_error(c.profile, 0.12, tilted(1e-3, Eigen::Vector3d::UnitX()), "body.radius");
  // Within the tolerance, and rolling the unbounded cylinder: the upright gap.
  BodyGap small(quadratic, c.grid, 0.05);
  EXPECT_NO_THROW(small.update(tilted(0.5 * BodyGap::kRejectTilt, Eigen::Vector3d::UnitY()), 0.0));
  BodyGap rolling(unbounded, c.grid, 0.1);
  EXPECT_FALSE(rolling.update(tilted(2.0, Eigen::Vector3d::UnitY()), 0.0));
}

}  // namespace
}  // namespace dc::dynamics
