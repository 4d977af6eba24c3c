#include "shakedown_run.hpp"

#include <cmath>

#include "shakedown_3d.hpp"
#include "shakedown_problem.hpp"

namespace dc::runs {

nlohmann::json shakedown_json(const Case& c, const SubsurfaceRun& field, const nlohmann::json& s) {
  const BodySubsurface* base = nullptr;
  for (const BodySubsurface& b : field.bodies)
    if (b.name == "base") base = &b;
  if (!base || !c.yields.base) return {{"status", "failed"}, {"message", "no field or yield strength of the base"}};
  const Grid& g = base->field.grid;
  const YieldSpec& y = *c.yields.base;
  const bool three_d = g.dimension == 3;
  // 3-D: Tresca through its inscribed cone (core/yield_criterion.hpp), a safe lower bound.
  const YieldCriterion criterion = y.von_mises ? YieldCriterion::von_mises(y.strength)
                                   : three_d   ? YieldCriterion::tresca_inscribed(y.strength)
                                               : YieldCriterion::tresca_plane_xz(y.strength);
  ShakedownResult r;
  if (three_d) {
    // The field over every line y_j of the grid, the positions along x the instants.
    StressHistory3d h;
    h.depths = field.depths;
    for (int j = 0; j < g.ny; ++j) h.lines.push_back(g.yc(j));
    for (int i = 0; i < g.nx; ++i) h.positions.push_back(g.xc(i));
    for (std::size_t k = 0; k < field.depths.size(); ++k)
      for (int j = 0; j < g.ny; ++j)
        for (int i = 0; i < g.nx; ++i) h.stress.push_back(voigt_stress(base->field.point(k, i, j)));
    r = solve_shakedown_3d(h, criterion);
  } else {
    StressHistory h;
    h.depths = field.depths;
    for (int i = 0; i < g.nx; ++i) h.positions.push_back(g.xc(i));
    for (std::size_t k = 0; k < field.depths.size(); ++k)
      for (int i = 0; i < g.nx; ++i) h.stress.push_back(voigt_stress(base->field.point(k, i, 0)));
    r = solve_shakedown(h, criterion);
  }
  const double k = criterion.shear_yield();
  const double p0 = s.value("max_pressure", 0.0), force = std::abs(s.value("normal_force", 0.0));
  double traction = 0.0;
  if (s.contains("tangential_force") && s["tangential_force"].is_array() && force > 0.0) {
    const auto& t = s["tangential_force"];
    const double tx = t[0].get<double>(), ty = t.size() > 1 ? t[1].get<double>() : 0.0;
    traction = std::hypot(tx, ty) / force;
  }
  auto finite_or_null = [](double v) { return std::isfinite(v) ? nlohmann::json(v) : nlohmann::json(); };
  nlohmann::json j = {{"status", to_string(r.status)},
                      {"message", r.message},
                      {"load_factor", finite_or_null(r.load_factor)},
                      {"elastic_limit_load_factor", finite_or_null(r.elastic_limit)},
                      {"limit_upper_bound", finite_or_null(r.limit_upper_bound)},
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
  if (three_d) {
    j["critical_y"] = r.critical_line >= 0 ? nlohmann::json(g.yc(r.critical_line)) : nlohmann::json();
    j["residual_model"] = "rho_xx(y, z), rho_yy(z), rho_xy(z) and stress functions phi(y, z), psi(y, z)";
    if (!y.von_mises) j["cone"] = "inscribed von Mises sqrt(J2) <= k: load_factor is safe for Tresca";
  }
  return j;
}

}  // namespace dc::runs
