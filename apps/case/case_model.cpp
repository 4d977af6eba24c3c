// The case file contract (shared spec CASES.md): build_case reads a document block by block,
// each with its reader (read_<block>.cpp), and checks which blocks the problem uses. Every bad
// input throws InputError(key path, reason); unknown keys are errors.
#include "case_model.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>
#include <string>
#include <vector>

#include "case_readers.hpp"
#include "errors.hpp"
#include "json_block.hpp"
#include "dynamic_limits.hpp"  // dynamic_sizing_load
#include "linear_operator.hpp"

namespace dc {

using namespace case_json;

namespace {

ProblemKind read_problem(const JsonBlock& top) {
  const std::string kind = top.string("problem");
  if (kind == "normal") return ProblemKind::normal;
  if (kind == "tangential") return ProblemKind::tangential;
  if (kind == "dynamic") return ProblemKind::dynamic;
  if (kind == "paper_cylinder") return ProblemKind::paper_cylinder;
  if (kind == "finite") return ProblemKind::finite;
  throw InputError("problem", "unknown problem '" + kind +
                                  "' (expected normal, tangential, dynamic, paper_cylinder or finite)");
}

/// Which problems use each optional top-level block (the keys every problem takes - schema,
/// name, description, problem, dimension, solver, output - are not listed). A block given to
/// a problem that does not use it is an error naming it. `finite` takes every block until its
/// reader lists its own here.
struct BlockUse {
  const char* block;
  std::vector<ProblemKind> problems;
};
const std::vector<BlockUse>& block_uses() {
  using P = ProblemKind;
  static const std::vector<BlockUse> uses = {
      {"materials", {P::normal, P::tangential, P::paper_cylinder, P::dynamic, P::finite}},
      {"profile", {P::normal, P::tangential, P::paper_cylinder, P::dynamic}},
      {"grid", {P::normal, P::tangential, P::paper_cylinder, P::dynamic, P::finite}},
      {"normal", {P::normal, P::tangential, P::paper_cylinder, P::finite}},
      {"friction", {P::tangential, P::paper_cylinder, P::dynamic, P::finite}},
      {"tangential", {P::tangential, P::finite}},
      {"body", {P::paper_cylinder, P::dynamic}},
      {"loads", {P::paper_cylinder, P::dynamic}},
      {"time", {P::paper_cylinder, P::dynamic}},
      {"normal_model", {P::dynamic}},
      {"contact_model", {P::dynamic}},
      {"traction_model", {P::paper_cylinder}},
      {"dimensionless", {P::paper_cylinder}},
      {"sweep", {P::paper_cylinder, P::dynamic}},
      {"fe_body", {P::finite, P::dynamic}},
      {"accuracy", {P::normal, P::tangential, P::dynamic}},
      {"subsurface", {P::normal, P::tangential, P::dynamic}},
      {"shakedown", {P::normal, P::tangential}},
      {"wear", {P::tangential, P::dynamic}},
      {"temperature", {P::tangential, P::dynamic}},
  };
  return uses;
}

void reject_unused_blocks(const JsonBlock& top, ProblemKind problem) {
  for (const BlockUse& use : block_uses()) {
    if (!top.has(use.block)) continue;
    if (std::find(use.problems.begin(), use.problems.end(), problem) != use.problems.end()) continue;
    std::string users;
    for (ProblemKind p : use.problems) users += std::string(users.empty() ? "" : ", ") + to_string(p);
    throw InputError(use.block, std::string("not used by problem '") + to_string(problem) + "' (remove it" +
                                    (users.empty() ? "" : "; it belongs to problem " + users) + ")");
  }
}

/// solver.operator "dense" holds the whole influence matrix (linear_operator.hpp: at most 4096 x
/// 4096 entries, 128 MB); a grid beyond it is refused here, not when the solve builds it.
void check_dense_operator_size(const Case& c) {
  if (c.solver.operator_kind != OperatorKind::dense) return;
  const bool two_components = c.dimension == 3 && c.friction.has_value();
  const double rows = static_cast<double>(c.grid.size()) * (two_components ? 2.0 : 1.0);
  const double limit = std::sqrt(static_cast<double>(kDenseAutoLimit * 16));
  if (rows <= limit) return;
  std::ostringstream why;
  why << "a dense influence matrix of " << c.grid.size() << " elements" << (two_components ? " (two components)" : "")
      << " needs " << rows * rows * 8.0 / 1e9 << " GB; dense is for at most " << limit << " rows (" << "e.g. "
      << static_cast<int>(std::sqrt(limit / (two_components ? 2.0 : 1.0))) << " x "
      << static_cast<int>(std::sqrt(limit / (two_components ? 2.0 : 1.0)))
      << " elements): use \"fft\" or \"auto\"";
  throw InputError("solver.operator", why.str());
}

/// The flash temperature (apps/runs/temperature_run.hpp) needs the contact's speed over both
/// surfaces: rolling (its velocity), and both surfaces' thermal constants.
void check_thermal(const Case& c, bool has_block, bool fe_body) {
  const ThermalSpec& t = c.thermal;
  if (!t.body && !t.base && !has_block) return;
  const char* key = t.base ? "materials.base.thermal" : t.body ? "materials.body.thermal" : "temperature";
  const bool rolling = c.problem == ProblemKind::tangential && c.tangential &&
                       c.tangential->regime == TangentialRegime::rolling;
  const bool dynamic = c.problem == ProblemKind::dynamic;
  if (!rolling && !dynamic)
    throw InputError(key, "the flash temperature is computed for rolling (problem tangential, regime rolling) and "
                          "dynamic runs (the contact's speed over the surfaces), not for this case");
  if (dynamic && fe_body)  // the body's surface speed omega_y R needs the rigid profile's radius
    throw InputError(key, "a dynamic run's flash temperature is computed for a rigid-profile body, not an fe_body");
  if (dynamic && c.output.snapshot_every <= 0)
    throw InputError(key, "a dynamic run's flash temperature is computed at its snapshots: set output.snapshot_every");
  if (t.model == ThermalSpec::Model::transient && !dynamic)
    throw InputError("temperature.model", "the transient temperature follows a dynamic run's steps; a rolling "
                                          "state's is quasi-steady");
  if (t.model == ThermalSpec::Model::transient && t.partition.rule == HeatPartition::Rule::pointwise)
    throw InputError("temperature.partition", "the pointwise partition is not offered by the transient "
                                              "temperature: use auto, equal_mean, equal_max or a fraction");
  if (!t.base) throw InputError("materials.base.thermal", "missing: the flash temperature needs both surfaces' "
                                                          "conductivity and diffusivity");
  if (!t.body) throw InputError("materials.body.thermal", "missing: the flash temperature needs both surfaces' "
                                                          "conductivity and diffusivity");
}

}  // namespace

bool Case::has_block(const std::string& block) const {
  return std::find(blocks.begin(), blocks.end(), block) != blocks.end();
}

Case build_case(const nlohmann::json& document, const std::string& base_dir) {
  JsonBlock top(document, "");
  top.allow({"schema", "name", "description", "problem", "dimension", "materials", "profile", "grid", "normal",
             "friction", "tangential", "fe_body", "body", "loads", "time", "traction_model", "dimensionless",
             "solver", "sweep", "output", "normal_model", "contact_model", "accuracy",
             "subsurface", "shakedown", "wear", "temperature"});
  Case c;
  c.source = document;
  for (auto it = document.begin(); it != document.end(); ++it) c.blocks.push_back(it.key());
  c.schema = top.string_or("schema", c.schema);
  if (c.schema != "dyncontact/1")
    throw InputError("schema", "unsupported schema '" + c.schema + "' (this version reads dyncontact/1)");
  c.name = top.string_or("name", "case");
  if (c.name.empty() || c.name == "." || c.name == ".." || c.name.find_first_of("/\\") != std::string::npos)
    throw InputError("name", "must be a non-empty name without '/' (it names the output folder)");
  c.description = top.string_or("description", "");
  c.problem = read_problem(top);
  c.dimension = top.integer_or("dimension", 3);
  if (c.dimension != 2 && c.dimension != 3)
    throw InputError("dimension", "must be 2 (plane strain) or 3, got " + std::to_string(c.dimension));

  // Blocks the static problems need; the other kinds take them when present.
  const bool static_problem = c.problem == ProblemKind::normal || c.problem == ProblemKind::tangential;
  auto required = [&](const char* k) { return static_problem || top.has(k); };
  const bool finite = c.problem == ProblemKind::finite;
  // A dynamic case may take its body as finite elements (read_fe_body.cpp).
  const bool fe = finite || (c.problem == ProblemKind::dynamic && top.has("fe_body"));
  if (required("materials")) {
    c.materials = read_materials(top.at("materials"), fe);
    c.allow_large_strain = JsonBlock(top.at("materials"), "materials").boolean_or("allow_large_strain", false);
  }
  const bool has_profile = required("profile");
  if (has_profile) c.profile = read_profile(top.at("profile"), c.dimension, base_dir);
  bool has_normal = required("normal");
  if (has_normal) c.normal = read_normal(top.at("normal"), "normal");
  if (top.has("friction") || c.problem == ProblemKind::tangential)
    c.friction = read_friction(top.at("friction"));
  if (top.has("tangential") || c.problem == ProblemKind::tangential) {
    if (!top.has("tangential")) throw InputError("tangential", "required for a tangential problem (an object)");
    c.tangential = read_tangential(top.at("tangential"), c.dimension, c.normal);
  }
  if (top.has("solver")) c.solver = read_solver(top.at("solver"));
  if (top.has("output")) c.output = read_output(top.at("output"));
  if (top.has("accuracy")) c.accuracy = read_accuracy(top.at("accuracy"), c.problem, c.dimension);
  if (top.has("subsurface")) c.subsurface = read_subsurface(top.at("subsurface"));
  if (top.has("wear")) c.wear = read_wear(top.at("wear"), c);
  if (top.has("materials")) {
    c.yields = read_yields(top.at("materials"));
    c.fatigue = read_fatigue_limits(top.at("materials"));
    if (c.problem == ProblemKind::dynamic && c.fatigue.body)
      throw InputError("materials.body.fatigue", "a dynamic run's fatigue index is computed for the base (its "
                                                 "material points stay in place), not the moving body");
    if ((c.fatigue.body || c.fatigue.base) && !static_problem && c.problem != ProblemKind::dynamic)
      throw InputError(c.fatigue.base ? "materials.base.fatigue" : "materials.body.fatigue",
                       std::string("the fatigue index is computed for problems normal, tangential and dynamic, not '") +
                           to_string(c.problem) + "'");
    if ((c.yields.body || c.yields.base) && !static_problem && c.problem != ProblemKind::dynamic)
      throw InputError(c.yields.base ? "materials.base.yield" : "materials.body.yield",
                       std::string("first yield is computed for problems normal, tangential and dynamic, not '") +
                           to_string(c.problem) + "'");
  }
  if (top.has("materials") || top.has("temperature")) {
    static const nlohmann::json none = nlohmann::json::object();
    c.thermal = read_thermal(top.has("materials") ? top.at("materials") : none,
                             top.has("temperature") ? &top.at("temperature") : nullptr);
    check_thermal(c, top.has("temperature"), fe);
  }
  c.shakedown = top.boolean_or("shakedown", false);
  if (c.shakedown && !c.yields.base)
    throw InputError("shakedown", "needs the base's yield strength (materials.base.yield: von_mises or tresca_k)");
  if (c.problem == ProblemKind::dynamic && c.fatigue.base && c.output.snapshot_every <= 0)
    throw InputError("materials.base.fatigue", "a dynamic run's fatigue index follows the base's points over its "
                                               "snapshots: set output.snapshot_every");
  if (top.has("sweep") && (c.thermal.base || c.thermal.body))
    throw InputError(c.thermal.base ? "materials.base.thermal" : "materials.body.thermal",
                     "the flash temperature is computed for single runs, not a sweep's (run the values one by one)");
  if (top.has("sweep") && (c.subsurface.enabled || c.yields.body || c.yields.base || c.fatigue.base))
    throw InputError(c.subsurface.enabled ? "subsurface" : "materials.base.yield",
                     "the subsurface field is computed for single runs, not a sweep's (run the values one by one)");
  if (!top.has("accuracy") && c.problem == ProblemKind::dynamic) c.accuracy.estimate = false;  // opt-in there
  if (c.problem == ProblemKind::dynamic) {
    c.dynamic = read_dynamic(document, c);
    if (!has_normal && !fe) has_normal = dynamics::dynamic_sizing_load(*c.dynamic, c, c.normal);
  }
  if (fe) read_finite_blocks(document, c, base_dir);  // read_fe_body.cpp
  if (c.wear && c.problem == ProblemKind::dynamic) {  // the body's circumference is body.radius's
    if (fe) throw InputError("wear", "a dynamic run's wear is computed for a rigid profile, not an fe_body");
    if (top.has("sweep")) throw InputError("wear", "computed for single runs, not a sweep's (run the values one by one)");
    if (!c.friction) throw InputError("wear", "needs friction (the laws wear by the slip)");
    if (c.wear->gap_feedback && c.accuracy.estimate)
      throw InputError("wear.gap_feedback", "not with accuracy.estimate (its coarser runs would wear the same "
                                            "surfaces): set it false, or the estimate off");
  }
  if ((required("grid") || c.accuracy.target) && !fe) {
    if (!has_profile) throw InputError("profile", "missing required key (the grid needs a profile)");
    // An accuracy target sizes the grid itself: the block (its extent or bounds) is optional.
    static const nlohmann::json no_grid = nlohmann::json::object();
    const nlohmann::json& grid = c.accuracy.target && !top.has("grid") ? no_grid : top.at("grid");
    c.grid = read_grid(grid, c, has_normal);
    c.allow_edge_contact = JsonBlock(grid, "grid").boolean_or("allow_edge_contact", false);
    check_contact_in_grid(c);
    check_dense_operator_size(c);
  }
  if (top.has("sweep") && top.at("sweep").is_object() &&
      (c.problem == ProblemKind::paper_cylinder || c.problem == ProblemKind::dynamic))
    c.sweep = read_sweep(top.at("sweep"));
  if (c.problem == ProblemKind::paper_cylinder) c.paper_cylinder = read_paper_cylinder(document, c);

  // Blocks of the dynamic and finite problems: shape only, until their readers are here.
  for (const char* k : {"body", "loads", "time", "dimensionless", "sweep"})
    if (top.has(k) && !top.at(k).is_object())
      throw InputError(k, "expected an object, got " + describe(top.at(k)));
  if (top.has("traction_model")) (void)top.choice("traction_model", "numerical", {"numerical", "carter_poritsky"});
  // Last, so a bad value in a block names its key before the block is found unused.
  reject_unused_blocks(top, c.problem);
  return c;
}

const char* to_string(ProblemKind kind) {
  switch (kind) {
    case ProblemKind::normal: return "normal";
    case ProblemKind::tangential: return "tangential";
    case ProblemKind::dynamic: return "dynamic";
    case ProblemKind::paper_cylinder: return "paper_cylinder";
    case ProblemKind::finite: return "finite";
  }
  return "unknown";
}

}  // namespace dc
