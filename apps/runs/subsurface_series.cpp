#include "subsurface_series.hpp"

#include <algorithm>
#include <cstdio>

namespace dc::runs {
namespace {

void keep_worse(WorstSubsurface::At& worst, const FieldExtreme& e, const SubsurfaceState& s, bool first) {
  if (first || e.value > worst.extreme.value) worst = {e, s.step, s.time};
}

}  // namespace

output::StaticFields SubsurfaceStates::tractions_only(output::StaticFields fields) {
  fields.sx = {};
  fields.sy = {};
  fields.bound = {};
  return fields;
}

void SubsurfaceStates::keep(int step, double time, double x_offset, double y_offset, output::StaticFields fields) {
  kept_.push_back({step, time, x_offset, y_offset, tractions_only(std::move(fields))});
}

void SubsurfaceStates::keep_peak(int step, double time, double x_offset, double y_offset, double normal_force,
                                 output::StaticFields fields) {
  peak_ = {step, time, x_offset, y_offset, tractions_only(std::move(fields))};
  peak_force_ = normal_force;
  has_peak_ = true;
}

std::vector<SubsurfaceState> SubsurfaceStates::states() const {
  std::vector<SubsurfaceState> states;
  bool peak_listed = !has_peak_;
  for (const Kept& k : kept_) {
    if (!peak_listed && peak_.step < k.step) {
      states.push_back(peak_.state());
      peak_listed = true;
    }
    if (has_peak_ && k.step == peak_.step) peak_listed = true;
    states.push_back(k.state());
  }
  if (!peak_listed) states.push_back(peak_.state());
  return states;
}

SubsurfaceSink subsurface_file_sink(output::SubsurfaceSnapshots& series) {
  return [&series](const SubsurfaceState& s, const SubsurfaceRun& run) -> std::string {
    if (run.bodies.empty() || !output::evenly_spaced(run.depths)) return "";
    return series.write(subsurface_bodies(run), s.step, s.time);
  };
}

double contact_half_width(const Grid& grid, const output::StaticFields& fields) {
  const output::ContactMeasures m = output::contact_measures(grid, fields);
  if (m.n_contact == 0) return 0.0;
  const double half_x = 0.5 * (m.x_max - m.x_min);
  return grid.dimension == 3 ? std::max(half_x, 0.5 * (m.y_max - m.y_min)) : half_x;
}

std::vector<double> subsurface_series_depths(const Case& c, const Grid& grid, const std::vector<SubsurfaceState>& states) {
  double half = 0.0;
  if (c.subsurface.depths.empty())
    for (const SubsurfaceState& s : states) half = std::max(half, contact_half_width(grid, *s.fields));
  return subsurface_depths(c.subsurface, half);
}

SubsurfaceSeries subsurface_series(const Case& c, const Grid& grid, const std::vector<SubsurfaceState>& states,
                                   const SubsurfaceSink& sink) {
  SubsurfaceSeries series;
  series.depths = subsurface_series_depths(c, grid, states);
  bool first = true;
  for (const SubsurfaceState& s : states) {
    const SubsurfaceRun run = compute_subsurface(c, grid, *s.fields, series.depths);
    if (first) {
      series.rigid = run.rigid;
      for (const BodySubsurface& b : run.bodies) series.bodies.push_back({b.name, {}, {}, {}});
    }
    nlohmann::json state = {{"step", s.step}, {"time", s.time}};
    for (std::size_t k = 0; k < run.bodies.size(); ++k) {
      const BodySubsurface& b = run.bodies[k];
      WorstSubsurface& w = series.bodies[k];
      keep_worse(w.von_mises, b.measures.max_von_mises, s, first);
      keep_worse(w.tresca, b.measures.max_tresca, s, first);
      keep_worse(w.orthogonal_shear, b.max_orthogonal_shear, s, first);
      state[b.name] = {{"max_von_mises", b.measures.max_von_mises.value}};
    }
    if (sink) {
      const std::string file = sink(s, run);
      if (!file.empty()) state["file"] = file;
    }
    series.states.push_back(std::move(state));
    first = false;
  }
  return series;
}

nlohmann::json subsurface_series_json(const SubsurfaceSeries& series, int dimension, bool timed) {
  auto at = [&](const FieldExtreme& e) {
    return dimension == 3 ? nlohmann::json::array({e.x, e.y, e.depth}) : nlohmann::json::array({e.x, e.depth});
  };
  nlohmann::json s = nlohmann::json::object();
  for (const WorstSubsurface& b : series.bodies) {
    nlohmann::json j = {{"max_von_mises", b.von_mises.extreme.value},       {"at", at(b.von_mises.extreme)},
                        {"step", b.von_mises.step},                          {"max_tresca", b.tresca.extreme.value},
                        {"at_tresca", at(b.tresca.extreme)},                 {"step_tresca", b.tresca.step},
                        {"max_orthogonal_shear", b.orthogonal_shear.extreme.value},
                        {"at_orthogonal", at(b.orthogonal_shear.extreme)}, {"step_orthogonal", b.orthogonal_shear.step}};
    if (timed) {
      j["time"] = b.von_mises.time;
      j["time_tresca"] = b.tresca.time;
      j["time_orthogonal"] = b.orthogonal_shear.time;
    }
    s[b.name] = std::move(j);
  }
  for (const std::string& r : series.rigid) s[r] = {{"rigid", true}};
  s["depths"] = series.depths;
  s["states"] = series.states;
  return s;
}

void print_subsurface_series(const SubsurfaceSeries& series, bool timed) {
  std::printf("  subsurface       %zu states, %zu depths to %.4g m; the worst over the run:\n", series.states.size(),
              series.depths.size(), series.depths.empty() ? 0.0 : series.depths.back());
  for (const WorstSubsurface& b : series.bodies) {
    const WorstSubsurface::At& v = b.von_mises;
    if (timed)
      std::printf("    %-5s von Mises %.5g Pa at depth %.4g m (step %d, t %.5g s), Tresca %.5g Pa (step %d)\n",
                  b.name.c_str(), v.extreme.value, v.extreme.depth, v.step, v.time, b.tresca.extreme.value, b.tresca.step);
    else
      std::printf("    %-5s von Mises %.5g Pa at depth %.4g m (step %d), Tresca %.5g Pa (step %d)\n", b.name.c_str(),
                  v.extreme.value, v.extreme.depth, v.step, b.tresca.extreme.value, b.tresca.step);
  }
  for (const std::string& r : series.rigid) std::printf("    %-5s rigid: no field\n", r.c_str());
}

}  // namespace dc::runs
