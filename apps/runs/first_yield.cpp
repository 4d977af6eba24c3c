#include "first_yield.hpp"

#include <cmath>

#include "tangential_run.hpp"

namespace dc::runs {
namespace {

constexpr double kTolerance = 1e-3;  ///< |utilisation - 1| at the factor found
constexpr int kMaxSolves = 12;

/// The body's utilisation at `factor` x the case's normal load (the grid solved, no estimate).
struct Trial {
  bool ok = false;
  double utilisation = 0.0;
  std::string why;
};

/// The normal load (force or approach, as c.normal) and every tangential force and moment scaled
/// by `factor` (a force-controlled traction coefficient kept); shifts, creepages, spin and angles
/// as given.
void scale_loads(NormalSpec& normal, std::array<ModeControl, 3>& modes, double factor) {
  normal.value *= factor;
  for (ModeControl& m : modes)
    if (m.kind == ModeControl::Kind::resultant) m.value *= factor;
}

Trial trial(const Case& c, const Grid& grid, const std::string& body, const YieldSpec& y, double factor) {
  Case s = c;
  s.grid = grid;
  s.accuracy.estimate = false;
  s.accuracy.target.reset();
  s.normal.value *= factor;
  if (s.tangential) {
    scale_loads(s.tangential->load.normal, s.tangential->load.modes, factor);
    scale_loads(s.tangential->rolling.normal, s.tangential->rolling.modes, factor);
  }
  s.subsurface.bodies = {body};
  const StaticRun r = run_static_once(s, false);
  if (!r.converged || r.fields.empty()) return {false, 0.0, "the solve at load factor " + std::to_string(factor) + " did not converge"};
  const nlohmann::json& sum = r.summary.contains("steps") && !r.summary["steps"].empty() ? r.summary["steps"].back() : r.summary;
  if (sum.value("contact_touches_boundary", false))
    return {false, 0.0, "at load factor " + std::to_string(factor) + " the contact reaches the grid's edge (enlarge the grid)"};
  const SubsurfaceRun field = compute_subsurface(s, r.grid, r.fields.back(), sum);
  return {true, utilisation(y, field.bodies.front().measures), ""};
}

}  // namespace

double utilisation(const YieldSpec& y, const SubsurfaceMeasures& m, FieldExtreme* at) {
  const FieldExtreme& e = y.von_mises ? m.max_von_mises : m.max_tresca;
  if (at) *at = e;
  return e.value / y.strength;
}

std::vector<FirstYield> first_yield(const Case& c, const StaticRun& run) {
  std::vector<FirstYield> out;
  if (!run.subsurface) return out;
  for (const BodySubsurface& b : run.subsurface->bodies) {
    const std::optional<YieldSpec>& y = b.name == "base" ? c.yields.base : c.yields.body;
    if (!y) continue;
    FirstYield f{b.name, *y, utilisation(*y, b.measures, nullptr), {}, std::nullopt, "", 0};
    utilisation(*y, b.measures, &f.at);
    if (run.history) {
      f.note = "the first-yield load factor is solved for single normal and tangential problems";
      out.push_back(f);
      continue;
    }
    // Secant on log u = s log(factor) + const, from Hertz's s (3-D force control 1/3, else 1/2).
    double s = c.dimension == 3 && c.normal.control == Control::force ? 1.0 / 3.0 : 0.5;
    double factor = 1.0, u = f.utilisation;
    for (f.solves = 0; f.solves < kMaxSolves; ) {
      if (std::abs(u - 1.0) <= kTolerance) {
        f.load_factor = factor;
        break;
      }
      const double next = factor * std::pow(1.0 / u, 1.0 / s);
      const Trial t = trial(c, run.grid, b.name, *y, next);
      ++f.solves;
      if (!t.ok) {
        f.note = t.why;
        break;
      }
      const double slope = std::log(t.utilisation / u) / std::log(next / factor);
      if (std::isfinite(slope) && slope > 0.05) s = slope;
      factor = next;
      u = t.utilisation;
    }
    if (!f.load_factor && f.note.empty()) f.note = "not found within " + std::to_string(kMaxSolves) + " solves";
    out.push_back(f);
  }
  return out;
}

nlohmann::json worst_yield_json(const Case& c, const SubsurfaceSeries& series, int dimension, bool timed) {
  nlohmann::json j = nlohmann::json::object();
  for (const WorstSubsurface& b : series.bodies) {
    const std::optional<YieldSpec>& y = b.name == "base" ? c.yields.base : c.yields.body;
    if (!y) continue;
    const WorstSubsurface::At& w = y->von_mises ? b.von_mises : b.tresca;
    const FieldExtreme& e = w.extreme;
    nlohmann::json entry = {{"criterion", y->von_mises ? "von_mises" : "tresca"},
                            {"strength", y->strength},
                            {"utilisation", e.value / y->strength},
                            {"at", dimension == 3 ? nlohmann::json::array({e.x, e.y, e.depth})
                                                  : nlohmann::json::array({e.x, e.depth})},
                            {"step", w.step},
                            {"first_yield_load_factor", nlohmann::json()},
                            {"solves", 0},
                            {"note", "the worst state of the run; the first-yield load factor is solved for single "
                                     "normal problems"}};
    if (timed) entry["time"] = w.time;
    j[b.name] = std::move(entry);
  }
  return j;
}

nlohmann::json first_yield_json(const std::vector<FirstYield>& yields, int dimension) {
  nlohmann::json j = nlohmann::json::object();
  for (const FirstYield& f : yields) {
    nlohmann::json b = {{"criterion", f.criterion.von_mises ? "von_mises" : "tresca"},
                        {"strength", f.criterion.strength},
                        {"utilisation", f.utilisation},
                        {"at", dimension == 3 ? nlohmann::json::array({f.at.x, f.at.y, f.at.depth})
                                              : nlohmann::json::array({f.at.x, f.at.depth})},
                        {"first_yield_load_factor", f.load_factor ? nlohmann::json(*f.load_factor) : nlohmann::json()},
                        {"solves", f.solves}};
    if (!f.note.empty()) b["note"] = f.note;
    j[f.body] = b;
  }
  return j;
}

}  // namespace dc::runs
