#pragma once
// A Hertz impact of the bundled ball (examples/ball-impact: steel on steel, R = 10 mm, 1 m/s)
// run through DynamicSimulation and measured: the contact time between the crossings of
// z = R (linear between steps; the body is in free flight there), the rebound speed at the end,
// and Hertz's closed form (Johnson 11.4): delta* = (15 m v0^2 / (16 E* sqrt(R)))^(2/5), the
// contact lasting 2.9432 delta* / v0, the elastic rebound at v0. For the adaptive-step tests.
#include <cmath>

#include <nlohmann/json.hpp>

#include "case_model.hpp"
#include "cli_runner.hpp"
#include "dynamic_simulation.hpp"

namespace dc::test {

struct ImpactMeasure {
  double contact_time = 0.0;  ///< s (0: the ball did not leave)
  double rebound = 0.0;       ///< vertical speed at the end (m/s)
  double first_contact = -1.0;  ///< time of the first step ending in contact (s)
  double last_free = 0.0;       ///< time of the last step before it (s)
  dynamics::DynamicResult result;
};

/// The ball on an n x n grid, starting `height` above the half-space at 1 m/s downward, to
/// t_end = 1.1 contact times after the touch; `time` the time block.
inline nlohmann::json ball_impact(int n, double height, const nlohmann::json& time) {
  nlohmann::json doc = example_json("ball-impact");
  doc["grid"]["nx"] = doc["grid"]["ny"] = n;
  doc["body"]["initial"]["position"] = {0, 0, 0.01 + height};
  doc["time"] = time;
  return doc;
}

/// Hertz's contact time of the case's impact at its initial speed (s).
inline double hertz_contact_time(const Case& c) {
  const double E = c.materials.E_star(), R = c.profile.radius, m = c.dynamic->mass, v0 = -c.dynamic->velocity[2];
  const double delta = std::pow(15.0 * m * v0 * v0 / (16.0 * E * std::sqrt(R)), 0.4);
  return 2.9432 * delta / v0;
}

inline ImpactMeasure measure_impact(const nlohmann::json& doc) {
  const Case c = build_case(doc);
  dynamics::DynamicSimulation sim(c);
  ImpactMeasure out;
  const double R = c.dynamic->radius;
  double t_prev = 0.0, z_prev = c.dynamic->position[2], t_down = c.dynamic->position[2] <= R ? 0.0 : -1.0;
  out.result = sim.run([&](const dynamics::DynamicSample& s) {
    const double z = s.state.position.z(), t = s.state.time;
    if (out.first_contact < 0.0 && s.contact_state.in_contact) {
      out.first_contact = t;
      out.last_free = t_prev;
    }
    if (t_down < 0.0 && z <= R && z_prev > R) t_down = t_prev + (R - z_prev) / (z - z_prev) * (t - t_prev);
    if (t_down >= 0.0 && out.contact_time == 0.0 && z > R && z_prev <= R && t > t_down)
      out.contact_time = t_prev + (R - z_prev) / (z - z_prev) * (t - t_prev) - t_down;
    t_prev = t;
    z_prev = z;
    out.rebound = s.state.velocity.z();
  });
  return out;
}

}  // namespace dc::test
