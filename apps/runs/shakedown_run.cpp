#include "shakedown_run.hpp"

#include <cmath>

#include "shakedown_problem.hpp"

namespace dc::runs {

nlohmann::json shakedown_json(const Case& c, const SubsurfaceRun& field, const nlohmann::json& s) {
  const BodySubsurface* base = nullptr;
  for (const BodySubsurface& b : field.bodies)
    if (b.name == "base") base = &b;
  if (!base || !c.yields.base) return {{"status", "failed"}, {"message", "no field or yield strength of the base"}};
  const Grid& g = base->field.grid;
  StressHistory h;
  h.depths = field.depths;
  for (int i = 0; i < g.nx; ++i) h.positions.push_back(g.xc(i));
  for (std::size_t k = 0; k < field.depths.size(); ++k)
    for (int i = 0; i < g.nx; ++i) h.stress.push_back(voigt_stress(base->field.point(k, i, 0)));
  const YieldSpec& y = *c.yields.base;
  const YieldCriterion criterion =
      y.von_mises ? YieldCriterion::von_mises(y.strength) : YieldCriterion::tresca_plane_xz(y.strength);
  const ShakedownResult r = solve_shakedown(h, criterion);
  const double k = criterion.shear_yield();
  const double p0 = s.value("max_pressure", 0.0), force = std::abs(s.value("normal_force", 0.0));
  double traction = 0.0;
  if (s.contains("tangential_force") && s["tangential_force"].is_array() && force > 0.0)
    traction = std::abs(s["tangential_force"][0].get<double>()) / force;
  auto finite_or_null = [](double v) { return std::isfinite(v) ? nlohmann::json(v) : nlohmann::json(); };
  nlohmann::json j = {{"status", to_string(r.status)},
                      {"message", r.message},
                      {"load_factor", finite_or_null(r.load_factor)},
                      {"elastic_limit_load_factor", finite_or_null(r.elastic_limit)},
                      {"verdict", to_string(r.verdict)},
                      {"criterion", y.von_mises ? "von_mises" : "tresca"},
                      {"p0_over_k", p0 / k},
                      {"traction_coefficient", traction},
                      {"shakedown_p0_over_k", finite_or_null(r.load_factor * p0 / k)},
                      {"critical_depth", r.critical_depth >= 0 ? nlohmann::json(field.depths[r.critical_depth]) : nlohmann::json()},
                      {"certificate",
                       {{"yield_violation", r.certificate.yield_violation},
                        {"lower_bound", r.certificate.lower_bound},
                        {"upper_bound", finite_or_null(r.certificate.upper_bound)},
                        {"duality_gap", r.certificate.duality_gap}}},
                      {"time_s", r.time_s}};
  return j;
}

}  // namespace dc::runs
