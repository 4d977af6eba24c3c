// The paper's Section 5 cylinder through the general dynamic solver (problem "dynamic", 2-D,
// the contact solved numerically in every step) against dynamics/paper_cylinder's integration
// of (5.7)-(5.9) with the Carter-Poritsky law (5.1)-(5.6): the speed u = V/V0 and the friction
// force F/(mu P) follow the motion (0.5 %), the rigid slip v/(mu eps V0) the creep law, which
// the grid (80 strips across the contact) reproduces to a few percent; gross sliding starts
// where the quasi-static limit puts it, t^* = ((1 + eta)/eta - M0^)/gamma^.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "case_model.hpp"
#include "cli_runner.hpp"
#include "dynamic_simulation.hpp"
#include "paper_cylinder.hpp"

namespace dc::dynamics {
namespace {

TEST(DynamicPaperCylinder, MatchesTheSectionFiveIntegration) {
  nlohmann::json doc = dc::test::example_json("cylinder-dynamic-2d");
  doc["time"]["t_end"] = 9.5;
  const Case c = build_case(doc);
  const DynamicSpec& s = *c.dynamic;
  const double M = s.mass, R = s.radius, I = s.inertia[1], V0 = s.velocity[0], P = -s.force[2].value;
  const double mu = c.friction->mu, E = c.materials.E_star();
  const double a = std::sqrt(4.0 * P * R / (std::numbers::pi * E));  // Hertz half-width (5.4)
  paper_cylinder::Parameters p;
  p.epsilon = a / R;
  p.mu = mu;
  p.eta = M * R * R / I;
  p.M0_bar = s.moment[1].value / (mu * P * R);
  p.gamma_bar = s.moment[1].rate * M * V0 / (mu * P * mu * P * R);
  p.v_bar0 = 0.0;
  const double t_scale = M * V0 / (mu * P);  // t = t^ t_scale
  p.t_bar_end = s.t_end / t_scale;
  const paper_cylinder::Run ref = paper_cylinder::simulate(p, 1e-4, paper_cylinder::Scheme::bdf2);
  ASSERT_TRUE(ref.ok) << ref.message;
  auto reference_at = [&](double t_bar) {
    std::size_t k = 0;
    while (k + 1 < ref.samples.size() && ref.samples[k + 1].t_bar <= t_bar) ++k;
    return ref.samples[k];
  };
  const double t_slide = ((1.0 + p.eta) / p.eta - p.M0_bar) / p.gamma_bar * t_scale;

  DynamicSimulation sim(c);
  double first_sliding = -1.0, worst_u = 0.0, worst_F = 0.0, worst_v = 0.0;
  const DynamicResult r = sim.run([&](const DynamicSample& x) {
    const double t = x.state.time;
    if (first_sliding < 0.0 && x.contact_state.n_stick == 0) first_sliding = t;
    if (t > 0.9 * t_slide || t < 0.5) return;  // away from the start transient and the onset of sliding
    const paper_cylinder::Sample q = reference_at(t / t_scale);
    const double u = x.state.velocity.x() / V0;
    const double F = std::abs(x.contact.force.x()) / (mu * P);
    const double v = std::abs(x.state.velocity.x() - R * x.state.omega.y()) / (mu * p.epsilon * V0);
    worst_u = std::max(worst_u, std::abs(u / q.u - 1.0));
    worst_F = std::max(worst_F, std::abs(F / q.F_bar - 1.0));
    worst_v = std::max(worst_v, std::abs(v / q.v_bar - 1.0));
  });
  ASSERT_TRUE(r.completed) << r.status;
  EXPECT_EQ(r.contact_model, "steady");
  EXPECT_LE(worst_u, 5e-3);
  EXPECT_LE(worst_F, 5e-3);
  EXPECT_LE(worst_v, 0.04);
  EXPECT_NEAR(first_sliding, t_slide, 0.02 * t_slide);
  EXPECT_LE(r.momentum_imbalance, 1e-9);  // bdf1: m dV = sum dt F
  EXPECT_LE(r.worst_certificate, c.solver.certificate_tol);
}

}  // namespace
}  // namespace dc::dynamics
