#include "subsurface_run.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "subsurface_writer.hpp"

namespace dc::runs {

Case with_verdict_bodies(const Case& c) {
  Case fc = c;
  std::vector<std::string>& bodies = fc.subsurface.bodies;
  auto need = [&](bool wanted, const char* name) {
    if (wanted && std::find(bodies.begin(), bodies.end(), name) == bodies.end()) bodies.push_back(name);
  };
  need(c.yields.base || c.fatigue.base || c.shakedown, "base");
  need(c.yields.body || c.fatigue.body, "body");
  return fc;
}

std::vector<double> subsurface_depths(const SubsurfaceSpec& spec, double half_width) {
  if (!spec.depths.empty()) return spec.depths;
  constexpr int kDepths = 32;
  std::vector<double> depths;
  for (int k = 0; k < kDepths; ++k) depths.push_back(1.5 * half_width * k / (kDepths - 1));
  return depths;
}

std::vector<double> subsurface_depths(const SubsurfaceSpec& spec, const nlohmann::json& summary) {
  const double half = summary.contains("contact_half_width")
                          ? summary.value("contact_half_width", 0.0)
                          : std::max(summary.value("contact_half_width_x", 0.0), summary.value("contact_half_width_y", 0.0));
  return subsurface_depths(spec, half);
}

SubsurfaceRun compute_subsurface(const Case& c, const Grid& grid, const output::StaticFields& fields,
                                 const nlohmann::json& summary) {
  return compute_subsurface(c, grid, fields, subsurface_depths(c.subsurface, summary));
}

SubsurfaceRun compute_subsurface(const Case& c, const Grid& grid, const output::StaticFields& fields,
                                 const std::vector<double>& depths) {
  SubsurfaceRun run;
  run.depths = depths;
  SurfaceTractions t{fields.p, fields.tx, grid.dimension == 3 ? fields.ty : std::vector<double>()};
  for (std::vector<double>* v : {&t.p, &t.tau_x, &t.tau_y})  // what the solve left undefined is no load
    for (double& x : *v)
      if (!std::isfinite(x)) x = 0.0;
  for (const std::string& name : c.subsurface.bodies) {
    const bool base = name == "base";
    const Elastic& m = base ? c.materials.base : c.materials.body;
    if (m.rigid) {
      run.rigid.push_back(name);
      continue;
    }
    SubsurfaceField field(grid, m, base ? BodySide::base : BodySide::body);
    BodySubsurface b{name, field.compute(t, run.depths), {}, {}};
    b.measures = subsurface_measures(b.field);
    // The orthogonal shear |sigma_xz|: the classical rolling-contact fatigue index.
    for (std::size_t k = 0; k < run.depths.size(); ++k) {
      const double* sxz = b.field.component(k, kSxz);
      for (int j = 0; j < grid.ny; ++j)
        for (int i = 0; i < grid.nx; ++i) {
          const double v = std::abs(sxz[grid.index(i, j)]);
          if (v > b.max_orthogonal_shear.value)
            b.max_orthogonal_shear = {v, k, i, j, grid.xc(i), grid.yc(j), run.depths[k]};
        }
    }
    run.bodies.push_back(std::move(b));
  }
  return run;
}

std::vector<output::SubsurfaceBody> subsurface_bodies(const SubsurfaceRun& run) {
  std::vector<output::SubsurfaceBody> bodies;
  for (const BodySubsurface& b : run.bodies) bodies.push_back({b.name, &b.field, &b.measures});
  return bodies;
}

nlohmann::json subsurface_json(const SubsurfaceRun& run, int dimension) {
  auto at = [&](const FieldExtreme& e) {
    return dimension == 3 ? nlohmann::json::array({e.x, e.y, e.depth}) : nlohmann::json::array({e.x, e.depth});
  };
  nlohmann::json s = nlohmann::json::object();
  for (const BodySubsurface& b : run.bodies)
    s[b.name] = {{"max_von_mises", b.measures.max_von_mises.value}, {"at", at(b.measures.max_von_mises)},
                 {"max_tresca", b.measures.max_tresca.value},       {"at_tresca", at(b.measures.max_tresca)},
                 {"max_orthogonal_shear", b.max_orthogonal_shear.value},
                 {"at_orthogonal", at(b.max_orthogonal_shear)}};
  for (const std::string& r : run.rigid) s[r] = {{"rigid", true}};
  s["depths"] = run.depths;
  return s;
}

std::vector<output::SubsurfaceBody> write_subsurface_files(const std::string& dir, const Case& c,
                                                          const SubsurfaceRun& run, nlohmann::json& files) {
  if (!c.subsurface.enabled) return {};
  const std::vector<output::SubsurfaceBody> bodies = subsurface_bodies(run);
  if (bodies.empty()) return bodies;
  if (output::evenly_spaced(run.depths)) files["subsurface"] = output::write_subsurface_vti(dir, bodies);
  if (c.subsurface.planes) files["subsurface_planes"] = output::write_subsurface_planes(dir, bodies);
  return bodies;
}

void print_subsurface(const SubsurfaceRun& run) {
  std::printf("  subsurface       %zu depths to %.4g m\n", run.depths.size(), run.depths.empty() ? 0.0 : run.depths.back());
  for (const BodySubsurface& b : run.bodies)
    std::printf("    %-5s von Mises %.5g Pa at depth %.4g m, Tresca %.5g Pa at %.4g m, |sxz| %.5g Pa at %.4g m\n",
                b.name.c_str(), b.measures.max_von_mises.value, b.measures.max_von_mises.depth, b.measures.max_tresca.value,
                b.measures.max_tresca.depth, b.max_orthogonal_shear.value, b.max_orthogonal_shear.depth);
  for (const std::string& r : run.rigid) std::printf("    %-5s rigid: no field\n", r.c_str());
}

}  // namespace dc::runs
