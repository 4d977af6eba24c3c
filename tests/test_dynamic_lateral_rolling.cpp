// Convection of the traction memory by a lateral velocity: the transient model's (3.8) takes the
// previous relative displacement at the material point that was at (x + V_x dt, y + V_y dt) when
// the step began (TangentialProblem::convected_step, bilinear between whole-element shifts;
// ContactWrench::evaluate passes (V_x dt, V_y dt)). A steel sphere on steel (kappa = 0) under a
// quasi-static normal load, on a square grid symmetric about the origin:
//  - symmetry: rolling in +y with creepages (xi along y, eta along x) is rolling in +x with
//    (xi along x, eta along y) transposed (x <-> y): on this grid the two are the same discrete
//    problem, so tractions and forces agree to the solver's certificate (bound 10
//    certificate_tol of mu p_max and mu P);
//  - a diagonal roll against the x roll turned by 45 degrees: the grid is not rotation-invariant,
//    and the memory is interpolated, so they agree within the grid's O(dx / a) (bound dx / a of
//    mu P); without the y convection the diagonal roll misses that bound;
//  - lateral rolling with whole-element steps reaches the steady lateral creep force of the
//    rotated problem (the steady model rolling along +x) to 10 certificate_tol mu P, and that
//    force is Kalker's -G a^2 C22 eta within the grid's creep-law error (dx / a).
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "case_model.hpp"
#include "contact_closed_forms.hpp"
#include "contact_wrench.hpp"
#include "hertz.hpp"
#include "tangential_support.hpp"

namespace dc::dynamics {
namespace {

/// A steel sphere (R = 10 mm) pressed by P = 100 N on steel, n x n elements over +-extent a.
struct SphereRoll {
  double R = 0.01, P = 100.0, mu, a;
  Case c;
  SphereRoll(int n, double extent, double friction, const char* model)
      : mu(friction), c(build_case(document(n, extent, friction, model))) {
    a = hertz::sphere(R, P, c.materials.E_star()).a;
  }
  nlohmann::json document(int n, double extent, double friction, const char* model) const {
    return {{"schema", "dyncontact/1"},
            {"name", "lateral-roll"},
            {"problem", "dynamic"},
            {"dimension", 3},
            {"materials", {{"body", {{"E", 2.1e11}, {"nu", 0.3}}}, {"base", {{"E", 2.1e11}, {"nu", 0.3}}}}},
            {"profile", {{"type", "sphere"}, {"radius", R}}},
            {"grid", {{"nx", n}, {"ny", n}, {"extent", extent}}},
            {"friction", {{"law", "coulomb"}, {"mu", friction}}},
            {"body", {{"mass", 1.0}, {"inertia", {1e-4, 1e-4, 1e-4}}, {"radius", R}}},
            {"loads", {{"force", {{"z", {{"value", -P}}}}}}},
            {"time", {{"dt", 1e-4}, {"t_end", 1e-3}}},
            {"normal_model", "quasi_static"},
            {"contact_model", model}};
  }
  /// Rolling at speed V along the unit vector e = (ex, ey) with longitudinal creepage xi and
  /// lateral creepage eta (along n = (-ey, ex)): the rigid slip velocity V + Omega x r at the
  /// contact centre (r = (0, 0, -R)) is V (xi e + eta n).
  StepKinematics kinematics(double V, double ex, double ey, double xi, double eta) const {
    const double sx = V * (xi * ex - eta * ey), sy = V * (xi * ey + eta * ex);  // slip velocity
    // a_x = V_x - R W_y, a_y = V_y + R W_x  =>  W_y = (V_x - a_x) / R, W_x = (a_y - V_y) / R.
    return {Eigen::Vector3d(0, 0, R), Eigen::Quaterniond::Identity(), Eigen::Vector3d(V * ex, V * ey, 0),
            Eigen::Vector3d((sy - V * ey) / R, (V * ex - sx) / R, 0), 0.0};
  }
};

/// Rolls `steps` steps of dt from the unloaded state; returns the contact (its last state).
void roll(ContactWrench& contact, StepKinematics k, double P, double dt, int steps) {
  for (int s = 1; s <= steps; ++s) {
    contact.begin_step(dt);
    k.time = s * dt;
    contact.evaluate(k, -P);
    ASSERT_TRUE(contact.state().converged) << "step " << s << ": " << contact.state().message;
    contact.accept(k, -P);
  }
}

TEST(DynamicLateralRolling, RollingAlongYIsRollingAlongXTransposed) {
  const SphereRoll s(20, 1.25, 0.3, "transient");
  const Grid& g = s.c.grid;
  ASSERT_EQ(g.nx, g.ny);
  ASSERT_DOUBLE_EQ(g.dx, g.dy);
  // Partial slip: creepages of a fraction of the saturation creepage ~ mu a / R.
  const double xi = 0.3 * s.mu * s.a / s.R, eta = 0.15 * s.mu * s.a / s.R, V = 1.0;
  const double dt = 0.4 * g.dx / V;                                      // interpolated memory
  const int steps = static_cast<int>(std::ceil(3.0 * 2.0 * s.a / (V * dt)));  // three contact lengths
  ContactWrench along_x(s.c), along_y(s.c);
  roll(along_x, s.kinematics(V, 1.0, 0.0, xi, eta), s.P, dt, steps);
  // Along +y: the longitudinal creepage along y, the lateral one along -x (n = (-1, 0)); the
  // transposed x roll has its lateral creepage along +y, so eta enters with the opposite sign.
  roll(along_y, s.kinematics(V, 0.0, 1.0, xi, -eta), s.P, dt, steps);
  const ContactState& X = along_x.state();
  const ContactState& Y = along_y.state();
  ASSERT_GT(X.n_stick, 0);
  ASSERT_GT(X.n_slip, 0);
  const double muP = s.mu * s.P, tol = 10.0 * s.c.solver.certificate_tol;
  EXPECT_NEAR(Y.wrench.force.x() / muP, X.wrench.force.y() / muP, tol);
  EXPECT_NEAR(Y.wrench.force.y() / muP, X.wrench.force.x() / muP, tol);
  double f_max = 0.0, diff = 0.0;
  for (int j = 0; j < g.ny; ++j)
    for (int i = 0; i < g.nx; ++i) {
      const std::size_t e = g.index(i, j), t = g.index(j, i);
      f_max = std::max(f_max, X.fields->bound[e]);
      diff = std::max({diff, std::abs(Y.fields->ty[e] - X.fields->tx[t]), std::abs(Y.fields->tx[e] - X.fields->ty[t])});
    }
  EXPECT_LE(diff / f_max, tol) << "the y roll's traction is the x roll's transposed";
  // The reported creepage is the longitudinal one, along the travel, for either direction.
  EXPECT_NEAR(X.creepage, xi, 1e-12 * xi);
  EXPECT_NEAR(Y.creepage, xi, 1e-12 * xi);
  ContactWrench diagonal(s.c);
  const double r = std::sqrt(0.5);
  roll(diagonal, s.kinematics(V, r, r, xi, eta), s.P, dt, 1);
  EXPECT_NEAR(diagonal.state().creepage, xi, 1e-12 * xi);
  std::printf("[ lateral symmetry ] F_x %.6g N (x roll) %.6g N (y roll, F_y); stick %d of %d\n", X.wrench.force.x(),
              Y.wrench.force.y(), X.n_stick, X.n_contact);
}

}  // namespace
}  // namespace dc::dynamics

namespace dc::dynamics {
namespace {

/// Rolls a Hertz sphere along e = (ex, ey) at creepages (xi along e, eta along n = (-ey, ex)),
/// travel d per step, over `lengths` contact lengths; `convect_y` false drops the y travel (the
/// memory convected along x only, as before V_y was convected). Returns (F_x, F_y).
Eigen::Vector2d convected_roll(const test::SphereSetup& s, const MaterialPair& m, double mu, double P, double ex,
                               double ey, double xi, double eta, double d, double lengths, bool convect_y) {
  TangentialProblem problem(s.grid, m, s.heights, FrictionLaw::coulomb(mu));
  const NormalSpec load{Control::force, P};
  const std::array<double, 3> increment = {d * (xi * ex - eta * ey), d * (xi * ey + eta * ex), 0.0};
  const std::array<double, 2> travel = {d * ex, convect_y ? d * ey : 0.0};
  const int steps = static_cast<int>(std::ceil(lengths * 2.0 * s.hz.a / d));
  TangentialSolution sol;
  for (int k = 0; k < steps; ++k) {
    sol = problem.convected_step(load, increment, travel, test::native_tangential_solver());
    EXPECT_EQ(sol.report.status, SolveStatus::converged) << "step " << k << ": " << sol.report.message;
  }
  EXPECT_GT(sol.n_stick, 0);
  EXPECT_GT(sol.n_slip, 0);
  return {sol.resultants[0], sol.resultants[1]};
}

TEST(DynamicLateralRolling, DiagonalRollIsTheXRollTurned) {
  const MaterialPair m = test::steel_on_steel();
  const double R = 0.01, P = 100.0, mu = 0.3;
  const test::SphereSetup s = test::sphere_setup(24, 1.25, m, R, P);
  const double a = s.hz.a, dx = s.grid.dx;
  // Partial slip (|F| ~ mu P / 4); half an element of travel per step: the diagonal roll's
  // memory is interpolated between all four neighbouring shifts, the x roll's between two.
  const double xi = 0.1 * mu * a / R, eta = 0.05 * mu * a / R, d = 0.5 * dx, c = std::sqrt(0.5);
  const Eigen::Vector2d along_x = convected_roll(s, m, mu, P, 1.0, 0.0, xi, eta, d, 3.0, true);
  const Eigen::Vector2d diagonal = convected_roll(s, m, mu, P, c, c, xi, eta, d, 3.0, true);
  const Eigen::Vector2d x_only = convected_roll(s, m, mu, P, c, c, xi, eta, d, 3.0, false);
  // The x roll's (longitudinal, lateral) force turned by 45 degrees.
  const Eigen::Vector2d turned(c * (along_x.x() - along_x.y()), c * (along_x.x() + along_x.y()));
  const double bound = dx / a * turned.norm();
  std::printf("[ diagonal roll ] |F| / (mu P) %.4f; off the turned x roll by %.4f |F| (without y convection %.4f |F|), "
              "bound dx / a = %.4f\n",
              turned.norm() / (mu * P), (diagonal - turned).norm() / turned.norm(),
              (x_only - turned).norm() / turned.norm(), dx / a);
  EXPECT_LE((diagonal - turned).norm(), bound);
  EXPECT_GT((x_only - turned).norm(), bound) << "without the y convection the bound is not met";
}

TEST(DynamicLateralRolling, LateralRollingReachesTheSteadyLateralCreepForce) {
  // mu = 10 and a creepage of 1e-3 a / R: far below saturation, Kalker's linear regime.
  const SphereRoll transient(24, 1.1, 10.0, "transient"), steady(24, 1.1, 10.0, "steady");
  const Grid& g = transient.c.grid;
  const double eta = 1e-3 * transient.a / transient.R, V = 1.0, dt = g.dy / V;  // one element per step
  // Rolling in +y with a lateral creepage along +x, for eight contact lengths.
  ContactWrench lateral(transient.c);
  roll(lateral, transient.kinematics(V, 0.0, 1.0, 0.0, -eta), transient.P, dt,
       static_cast<int>(std::ceil(8.0 * 2.0 * transient.a / g.dy)));
  // The rotated problem: steady rolling in +x with the lateral creepage along +y.
  ContactWrench rotated(steady.c);
  roll(rotated, steady.kinematics(V, 1.0, 0.0, 0.0, eta), steady.P, dt, 1);
  ASSERT_EQ(rotated.model_used(), "steady");
  const double F = lateral.state().wrench.force.x(), F_steady = rotated.state().wrench.force.y();
  const auto k = closed_form::kalker_circular(transient.c.materials.body.nu);
  const double kalker = -transient.c.materials.body.G * transient.a * transient.a * k.c22 * eta;
  std::printf("[ lateral rolling ] F_x %.8g N, steady F_y %.8g N, Kalker -G a^2 C22 eta %.8g N\n", F, F_steady, kalker);
  EXPECT_NEAR(F / F_steady, 1.0, 10.0 * transient.c.solver.certificate_tol);
  EXPECT_NEAR(lateral.state().wrench.force.y() / F, 0.0, 10.0 * transient.c.solver.certificate_tol);
  EXPECT_NEAR(F / kalker, 1.0, g.dx / transient.a) << "Kalker's C22 within the grid's creep-law error";
}

TEST(DynamicLateralRolling, SteadyModelLeavesSidewaysTravelToTheTransientOne) {
  // The steady model rolls along +x: a step travelling along y is solved by the transient
  // model (the same force as the transient model's), and the model used says so.
  const SphereRoll steady(16, 1.25, 0.3, "steady"), transient(16, 1.25, 0.3, "transient");
  const double xi = 0.1 * steady.mu * steady.a / steady.R, dt = 0.5 * steady.c.grid.dy;
  ContactWrench a(steady.c), b(transient.c);
  roll(a, steady.kinematics(1.0, 0.0, 1.0, xi, 0.0), steady.P, dt, 4);
  roll(b, transient.kinematics(1.0, 0.0, 1.0, xi, 0.0), transient.P, dt, 4);
  EXPECT_EQ(a.state().wrench.force.y(), b.state().wrench.force.y());
  EXPECT_EQ(a.model_used(), "steady (transient in 4 of 4 steps: travel not along +x)");
  EXPECT_EQ(b.model_used(), "transient");
  // Travel within the steady model's reach (|V_y| <= 0.1 V_x) stays steady.
  EXPECT_TRUE(ContactWrench::travel_along_x(Eigen::Vector3d(1.0, 0.1, 0.0)));
  EXPECT_FALSE(ContactWrench::travel_along_x(Eigen::Vector3d(1.0, -0.11, 0.0)));
  EXPECT_FALSE(ContactWrench::travel_along_x(Eigen::Vector3d(-1.0, 0.0, 0.0)));
}

}  // namespace
}  // namespace dc::dynamics
