// Stiff creep: the steel cylinder of cylinder-dynamic-2d (eps = a/R ~ 1.2e-3) stepped with
// steps hundreds of slip-relaxation times long through stick -> gross slip -> stick: rolling
// freely, then driven by a moment twice what friction can carry, then released (three runs,
// each starting from the last's final state). The slip velocity w = V - Omega R relaxes in
// tau = eps V M / (2 P (1 + eta)) (Carter's creep slope dF/dxi = 2 P / eps, eta = M R^2 / I).
// Closed forms:
//  - free rolling: F = 0, V constant;
//  - driven by M1 = 2 mu P R (1 + eta) / eta: gross sliding, F = mu P exactly, V = V0 + mu P t / M;
//  - released: the wheel slides back to rolling after as long as it was driven (dw/dt = -+ mu P
//    (1 + eta) / M), keeping its angular momentum about the contact point L_c = M V R + I Omega,
//    which the drive raised by M1 T: it ends rolling at V = (L_c0 + M1 T) R / (M R^2 + I).
// Stability: BDF1 with a monotone creep law cannot overshoot (w never changes sign after the
// release, F never reverses), and the kinetic energy never grows by more than the work of the
// applied moment (the contact only dissipates). Bounds: the step's Newton tolerance rel_tol
// (relative to the body's speeds) carried into creepage, force and energy.
#include <gtest/gtest.h>

#include <cmath>

#include "case_model.hpp"
#include "cli_runner.hpp"
#include "dynamic_simulation.hpp"

namespace dc::dynamics {
namespace {

struct Phase {
  DynamicResult result;
  double max_force_error = 0.0;    // sliding: max |F_x / (mu P) - 1|
  double max_positive_w = 0.0;     // released: max creepage of the wrong sign (overshoot)
  double min_force = 0.0;          // released: most negative F_x / (mu P) (a reversed force)
  double energy_excess = 0.0;      // max over steps of (dKE - W_applied) / KE
  double max_contact_power = 0.0;  // max over steps of W_contact / KE (> 0: the contact did work)
  double max_speed_error = 0.0;    // sliding: max |V - (V0 + mu P t / M)| / V0
  double max_abs_force = 0.0;      // max |F_x| / (mu P)
};

nlohmann::json base_case() {
  nlohmann::json doc = dc::test::example_json("cylinder-dynamic-2d");
  doc["time"] = {{"dt", 0.05}, {"t_end", 1.0}, {"scheme", "bdf1"}};
  doc["contact_model"] = "auto";
  return doc;
}

Phase run_phase(nlohmann::json doc, const RigidBodyState& start, double moment, double duration, double muP,
                double mass) {
  doc["body"]["initial"] = {{"position", {start.position.x(), 0.0, start.position.z()}},
                            {"velocity", {start.velocity.x(), 0.0, 0.0}},
                            {"omega", {0.0, start.omega.y(), 0.0}}};
  doc["loads"]["moment"] = {{"y", {{"value", moment}}}};
  doc["time"]["t_end"] = duration;
  const Case c = build_case(doc);
  Phase ph;
  DynamicSimulation sim(c);
  double ke_prev = 0.5 * mass * start.velocity.squaredNorm() + 0.5 * c.dynamic->inertia[1] * std::pow(start.omega.y(), 2);
  double ext_prev = 0.0, con_prev = 0.0;
  const double v0 = start.velocity.x();
  ph.result = sim.run([&](const DynamicSample& s) {
    const double fx = s.contact.force.x() / muP;
    const double ke = s.kinetic_energy;
    ph.energy_excess = std::max(ph.energy_excess, (ke - ke_prev - (s.external_work - ext_prev)) / ke);
    ph.max_contact_power = std::max(ph.max_contact_power, (s.contact_work - con_prev) / ke);
    ke_prev = ke;
    ext_prev = s.external_work;
    con_prev = s.contact_work;
    ph.max_force_error = std::max(ph.max_force_error, std::abs(fx - 1.0));
    ph.max_positive_w = std::max(ph.max_positive_w, s.contact_state.creepage);
    ph.min_force = std::min(ph.min_force, fx);
    ph.max_abs_force = std::max(ph.max_abs_force, std::abs(fx));
    ph.max_speed_error =
        std::max(ph.max_speed_error, std::abs(s.state.velocity.x() - (v0 + muP * s.state.time / mass)) / v0);
  });
  return ph;
}

TEST(DynamicStiffCreep, StickSlipStickWithStepsOfHundredsOfRelaxationTimes) {
  const nlohmann::json doc = base_case();
  const Case c = build_case(doc);
  const DynamicSpec& s = *c.dynamic;
  const double M = s.mass, I = s.inertia[1], R = s.radius, P = -s.force[1 + 1].value, mu = c.friction->mu;
  const double eta = M * R * R / I, muP = mu * P;
  const double a = std::sqrt(4.0 * P * R / (M_PI * c.materials.E_star()));  // Hertz (plane strain)
  const double eps = a / R, V0 = s.velocity[0];
  const double tau = eps * V0 * M / (2.0 * P * (1.0 + eta));
  ASSERT_LT(eps, 2e-3);
  ASSERT_GT(s.dt / tau, 200.0) << "steps of hundreds of relaxation times";
  const double rel_tol = std::max(1e-10, 10.0 * c.solver.tol);  // the step's Newton tolerance
  // Bounds from the Newton tolerance: speeds to rel_tol V, so creepage to ~ rel_tol (1 + R/rho)
  // and the creep force to its slope 2 P / eps times that; energy to ~ 2 rel_tol KE per step.
  const double creep_bound = 10.0 * rel_tol, force_bound = 2.0 / (eps * mu) * creep_bound;
  const double energy_bound = 10.0 * rel_tol;

  RigidBodyState start = initial_state(s);
  start.omega.y() = V0 / R;  // rolling freely
  const double M1 = 2.0 * muP * R * (1.0 + eta) / eta, T = 0.52;

  const Phase free = run_phase(doc, start, 0.0, 0.2, muP, M);
  ASSERT_TRUE(free.result.completed) << free.result.status;
  EXPECT_NEAR(free.result.final.velocity.x(), V0, rel_tol * V0) << "free rolling keeps its speed";
  EXPECT_LE(free.max_abs_force, force_bound) << "free rolling: no friction force";

  const Phase driven = run_phase(doc, free.result.final, M1, T, muP, M);
  ASSERT_TRUE(driven.result.completed) << driven.result.status;
  EXPECT_LE(driven.max_force_error, c.solver.certificate_tol) << "gross sliding: F = mu P every step";
  EXPECT_LE(driven.max_speed_error, rel_tol) << "V = V0 + mu P t / M";
  EXPECT_LE(driven.energy_excess, energy_bound);
  EXPECT_LE(driven.max_contact_power, energy_bound);

  const RigidBodyState& d = driven.result.final;
  const double w_release = d.velocity.x() - d.omega.y() * R;
  EXPECT_NEAR(w_release, -muP * (1.0 + eta) / M * T, rel_tol * V0) << "slip velocity at the release";
  const Phase released = run_phase(doc, d, 0.0, 2.0 * T + 0.3, muP, M);
  ASSERT_TRUE(released.result.completed) << released.result.status;
  EXPECT_LE(released.max_positive_w, creep_bound) << "the slip relaxes without overshoot";
  EXPECT_GE(released.min_force, -force_bound) << "the friction force never reverses";
  EXPECT_LE(released.energy_excess, energy_bound) << "energy does not grow without work";
  EXPECT_LE(released.max_contact_power, energy_bound);
  const RigidBodyState& f = released.result.final;
  const double L0 = M * V0 * R + I * V0 / R;
  EXPECT_NEAR(f.velocity.x() / ((L0 + M1 * T) * R / (M * R * R + I)), 1.0, 10.0 * rel_tol)
      << "rolling again with the angular momentum about the contact point";
  EXPECT_NEAR((f.velocity.x() - f.omega.y() * R) / f.velocity.x(), 0.0, creep_bound) << "rolling";
}

}  // namespace
}  // namespace dc::dynamics
