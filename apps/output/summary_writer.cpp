#include "summary_writer.hpp"

#include <cmath>
#include <filesystem>

#include "analytic_reference.hpp"
#include "output_files.hpp"
#include "summary_entries.hpp"

#ifndef DYNCONTACT_VERSION
#define DYNCONTACT_VERSION "unknown"
#endif

namespace dc::output {
namespace {

nlohmann::json material_json(const Elastic& m) {
  if (m.rigid) return {{"rigid", true}};
  return {{"E", m.E}, {"nu", m.nu}, {"G", m.G}};
}

/// A finite-element body (fe_body) is its mesh, not the rigid stand-in the pair holds for it.
nlohmann::json fe_body_json(const FeBodySpec& b) {
  const char* shape = b.shape == FeShape::block      ? "block"
                      : b.shape == FeShape::cylinder ? "cylinder"
                      : b.shape == FeShape::mesh     ? "mesh"
                                                     : "hemisphere";
  return {{"fe_body", shape}, {"density", b.material.density}, {"regions", b.regions.size()}};
}

double relative(double value, double reference) {
  return reference != 0.0 ? (value - reference) / std::abs(reference) : 0.0;
}

}  // namespace

nlohmann::json summary_header(const Case& c) {
  nlohmann::json s;
  s["schema"] = "dyncontact/1";
  s["name"] = c.name;
  s["problem"] = to_string(c.problem);
  s["dimension"] = c.dimension;
  s["version"] = DYNCONTACT_VERSION;
  const Grid& g = c.grid;
  nlohmann::json grid = {{"nx", g.nx}, {"ny", g.ny}, {"elements", g.size()}, {"x", {g.x0, g.x_max()}}, {"dx", g.dx}};
  if (g.dimension == 3) {
    grid["y"] = {g.y0, g.y_max()};
    grid["dy"] = g.dy;
  }
  s["grid"] = grid;
  s["materials"] = {{"body", c.fe_body ? fe_body_json(*c.fe_body) : material_json(c.materials.body)},
                    {"base", material_json(c.materials.base)},
                    {"E_star", c.materials.E_star()}};  // with an fe_body: the half-space's share
  s["profile"] = c.fe_body ? "fe_body" : to_string(c.profile.type);
  return s;
}

nlohmann::json normal_summary(const Case& c, const NormalSolution& solution, const StaticFields& fields) {
  nlohmann::json s = summary_header(c);
  s["solver"] = to_json(solution.report);
  s["control"] = c.normal.control == Control::force ? "force" : "approach";
  s["normal_force"] = solution.force;
  s["approach"] = solution.approach;
  if (c.dimension == 2) s["approach_reference_length"] = c.grid.nx * c.grid.dx;
  add_contact_measures(s, c.grid, fields);
  if (const auto ref = analytic_reference(c)) {
    nlohmann::json h = ref->to_json();
    nlohmann::json diff;
    diff["normal_force"] = relative(solution.force, ref->force);
    diff["contact_area"] = relative(s["contact_area"].get<double>(), ref->contact_area());
    if (ref->kind != "boussinesq_flat_punch")
      diff["max_pressure"] = relative(s["max_pressure"].get<double>(), ref->max_pressure);
    if (ref->approach) diff["approach"] = relative(solution.approach, *ref->approach);
    h["relative_difference"] = diff;
    s["hertz"] = h;
  }
  return s;
}

std::string write_summary(const std::string& dir, const nlohmann::json& summary) {
  const std::string path = (std::filesystem::path(dir) / "summary.json").string();
  write_file_whole(path, summary.dump(2) + "\n");
  return path;
}

}  // namespace dc::output
