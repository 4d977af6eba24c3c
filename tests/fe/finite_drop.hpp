#pragma once
// An FE hemisphere dropped on the half-space (problem "dynamic" with an fe_body), shared by
// test_finite_dynamic (unit) and slow_finite_dynamic (slow).
#include <cmath>

#include "case_model.hpp"
#include "dynamic_simulation.hpp"
#include "finite_body_contact.hpp"

namespace dc::dynamics::test {


constexpr double kR = 0.01, kE = 2.1e11, kNu = 0.3, kRho = 7800.0, kV0 = 1.0;

/// The Hertz impact (Johnson 11.4) of mass m at v0 with radius R and plane modulus E*.
struct HertzImpact {
  double delta, duration, peak;
};
inline HertzImpact hertz_impact(double m, double R, double E_star, double v0) {
  const double delta = std::pow(15.0 * m * v0 * v0 / (16.0 * E_star * std::sqrt(R)), 0.4);
  return {delta, 2.9432 * delta / v0, 4.0 / 3.0 * E_star * std::sqrt(R) * std::pow(delta, 1.5)};
}

/// A hemisphere of modulus E_body dropped at kV0, the grid and time step sized by the Hertz
/// impact of the pair (half-width 1.5 a, `steps` steps over the contact).
inline nlohmann::json drop_case(double E_body, const char* scheme, int steps) {
  const double m = kRho * 2.0 / 3.0 * M_PI * kR * kR * kR;  // for sizing only: the run takes the mesh's
  const double E_pair = 1.0 / ((1.0 - kNu * kNu) / kE + (1.0 - kNu * kNu) / E_body);
  const HertzImpact h = hertz_impact(m, kR, E_pair, kV0);
  const double a = std::sqrt(kR * h.delta), L = 1.5 * a;
  return {{"schema", "dyncontact/1"},
          {"name", "fe-drop"},
          {"problem", "dynamic"},
          {"materials", {{"base", {{"E", kE}, {"nu", kNu}}}}},
          {"fe_body",
           {{"shape", "hemisphere"},
            {"radius", kR},
            {"elements", {8, 8, 4}},
            {"contact_size", 0.25 * a},
            {"material", {{"E", E_body}, {"nu", kNu}}},
            {"density", kRho}}},
          {"grid", {{"nx", 24}, {"ny", 24}, {"x", {-L, L}}, {"y", {-L, L}}}},
          {"body", {{"initial", {{"velocity", {0.0, 0.0, -kV0}}}}}},
          {"time", {{"dt", h.duration / steps}, {"t_end", 1.1 * h.duration}, {"scheme", scheme}}},
          {"solver", {{"backend", "native"}, {"tol", 1e-10}}}};
}

struct Drop {
  double duration = 0.0, peak = 0.0, rebound = 0.0, mass = 0.0, max_momentum_error = 0.0, impulse = 0.0;
  double max_body_displacement = 0.0, centre_height = 0.0;
  DynamicResult result;
};

inline Drop run_drop(const nlohmann::json& doc) {
  const Case c = build_case(doc);
  DynamicSimulation sim(c, make_finite_body(c));
  Drop out;
  out.mass = sim.body().mass();
  out.centre_height = sim.finite_body() ? sim.finite_body()->centre_height() : c.dynamic->radius;
  const double zc = sim.finite_body() ? sim.finite_body()->centre_height() : c.dynamic->radius;
  double t_prev = 0.0, z_prev = zc;
  Eigen::Vector3d v_prev(0.0, 0.0, -kV0);
  bool left = false;
  out.result = sim.run([&](const DynamicSample& s) {
    out.peak = std::max(out.peak, s.contact.force.z());
    const double z = s.state.position.z(), dt = s.state.time - t_prev;
    if (!left && z > zc && z_prev <= zc && s.state.time > 0.0) {
      out.duration = t_prev + (zc - z_prev) / (z - z_prev) * dt;  // leaves where z crosses zc again
      left = true;
    }
    const Eigen::Vector3d F = s.contact.force + s.external.force;
    out.max_momentum_error = std::max(out.max_momentum_error, (out.mass * (s.state.velocity - v_prev) - dt * F).norm());
    out.impulse += dt * F.norm();
    t_prev = s.state.time;
    z_prev = z;
    v_prev = s.state.velocity;
    out.rebound = s.state.velocity.z();
  });
  if (sim.finite_body()) out.max_body_displacement = sim.finite_body()->max_displacement();
  return out;
}

/// The rigid-body dynamic case of the same drop: a rigid sphere profile of kR with the FE
/// body's mass and centre height, on the same grid with the same steps.
inline nlohmann::json rigid_drop_case(const nlohmann::json& fe_case, double mass, double centre_height) {
  nlohmann::json doc = fe_case;
  doc.erase("fe_body");
  doc["materials"]["body"] = {{"rigid", true}};
  doc["profile"] = {{"type", "sphere"}, {"radius", kR}};
  const double I = 0.4 * mass * kR * kR;  // a central impact: the inertia plays no part
  doc["body"] = {{"mass", mass},
                 {"inertia", {I, I, I}},
                 {"radius", centre_height},
                 {"initial", {{"velocity", {0.0, 0.0, -kV0}}}}};
  return doc;
}

}  // namespace dc::dynamics::test
