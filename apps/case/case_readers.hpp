#pragma once
// The case layer's readers, one per block, each in apps/case/read_<block>.cpp and used by
// build_case (case_model.cpp). Each reads through JsonBlock (json_block.hpp) and throws
// InputError naming the key path and the reason.
#include <istream>
#include <string>

#include <nlohmann/json.hpp>

#include "case_model.hpp"
#include "json_block.hpp"

namespace dc {

/// "materials": the body's and the half-space's elastic constants. `body_from_mesh` (an
/// fe_body): the block gives the half-space ("base") only and the pair's body is rigid.
MaterialPair read_materials(const nlohmann::json& j, bool body_from_mesh);

/// {"force": P} or {"approach": d} at `path` ("normal", "tangential.history[2].normal").
NormalSpec read_normal(const nlohmann::json& j, const std::string& path);

/// "friction": Coulomb, Tresca or a table f(p).
FrictionSpec read_friction(const nlohmann::json& j);

/// "solver": the solver's options, each checked by SolverOptions::validate().
SolverOptions read_solver(const nlohmann::json& j);

/// "accuracy": the error estimate and the target of a `problem` (its quantities checked).
AccuracySpec read_accuracy(const nlohmann::json& j, ProblemKind problem, int dimension);

/// materials.body.yield and materials.base.yield (the block read by read_materials).
BodyYields read_yields(const nlohmann::json& materials);
/// materials.body.fatigue and materials.base.fatigue (Dang Van's alpha and beta).
BodyFatigue read_fatigue_limits(const nlohmann::json& materials);

/// materials.body.thermal, materials.base.thermal and the "temperature" block (may be null):
/// the surfaces' thermal constants and the heat's partition.
ThermalSpec read_thermal(const nlohmann::json& materials, const nlohmann::json* temperature);

/// "subsurface": the depths, bodies and planes of the field inside the bodies.
SubsurfaceSpec read_subsurface(const nlohmann::json& j);

/// "output": the folder, which files, snapshots.
OutputSpec read_output(const nlohmann::json& j);

/// "profile": the body's shape; a table profile's CSV read relative to `base_dir`.
ProfileSpec read_profile(const nlohmann::json& j, int dimension, const std::string& base_dir);

/// The CSV of a table profile (a header naming the columns x, y (optional) and h, then rows;
/// blank lines and lines starting with # skipped) into p.table_x/y/h, heights shifted to a
/// minimum of 0. Throws InputError naming `file_key` and the line.
void read_profile_table(std::istream& in, ProfileSpec& p, const std::string& file_key);

/// "grid": nx, ny, bounds or `extent` (the Hertz contact of `c`'s profile, materials and
/// normal load, when `has_normal`).
Grid read_grid(const nlohmann::json& j, const Case& c, bool has_normal);

/// The profile must be able to touch inside the grid (else the load cannot be carried).
void check_contact_in_grid(const Case& c);

/// "tangential" for a case of `dimension` whose normal load is `normal`. Throws InputError
/// naming the key path (tangential.history[1].shift) and the reason.
TangentialSpec read_tangential(const nlohmann::json& j, int dimension, const NormalSpec& normal);

/// "wear" of case `c` (its problem, tangential block and accuracy already read): the law,
/// bodies, cycles, update, cycle_from_step and rolling_radius. A case it cannot apply to (not a
/// shift or torsion history, steady rolling or a dynamic run) is an InputError naming "wear".
WearSpec read_wear(const nlohmann::json& j, const Case& c);

/// The dynamic blocks of `document` (body, loads, time, normal_model, contact_model); `c` holds
/// the common blocks already read.
DynamicSpec read_dynamic(const nlohmann::json& document, const Case& c);

/// {"value": v, "rate": r} at `parent.k` (both default 0): a load component v + r t.
inline ValueRate read_value_rate(const case_json::JsonBlock& parent, const char* k) {
  const case_json::JsonBlock v = parent.child(k);
  v.allow({"value", "rate"});
  // Forces (N) and moments (N m) of real machines lie far inside these bounds.
  const double value = v.has("value") ? v.bounded("value", -1e15, 1e15, "(N or N m)") : 0.0;
  const double rate = v.has("rate") ? v.bounded("rate", -1e18, 1e18, "(N/s or N m/s)") : 0.0;
  return {value, rate};
}

/// The paper_cylinder blocks of `document`; `c` holds the already read common blocks
/// (materials, friction).
PaperCylinderSpec read_paper_cylinder(const nlohmann::json& document, const Case& c);

/// "fe_body" (key prefix "fe_body"); paths relative to `case_dir`.
FeBodySpec read_fe_body(const nlohmann::json& block, const std::string& case_dir);

/// Problem finite, or a dynamic body of finite elements: fe_body, grid (x/y bounds) and normal.
void read_finite_blocks(const nlohmann::json& document, Case& c, const std::string& base_dir);

/// The top-level `sweep` block.
SweepSpec read_sweep(const nlohmann::json& block);

}  // namespace dc
