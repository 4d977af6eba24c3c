// The case file contract (shared spec CASES.md): parsing, overrides, the small blocks
// (materials, normal, friction, solver, output) and build_case; the larger blocks each have
// their reader file (case_profile, case_grid, case_tangential, case_paper_cylinder).
// Every bad input throws InputError(key path, reason); unknown keys are errors.
#include "case_model.hpp"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "case_blocks.hpp"
#include "errors.hpp"
#include "json_block.hpp"
#include "json_parse.hpp"
#include "linear_operator.hpp"

namespace dc {
namespace {

using json = nlohmann::json;

Elastic parse_elastic(const json& j, const std::string& path) {
  JsonBlock o(j, path);
  o.allow({"E", "G", "nu", "rigid"});
  if (o.boolean_or("rigid", false)) {
    for (const char* k : {"E", "G", "nu"})
      if (o.has(k)) throw InputError(o.key(k), "a rigid body takes no elastic constants");
    return Elastic::make_rigid();
  }
  const bool hasE = o.has("E"), hasG = o.has("G");
  if (hasE && hasG) throw InputError(o.key("G"), "give either E or G, not both");
  if (!hasE && !hasG)
    throw InputError(o.key("E"), "missing required key (give E or G with nu, or \"rigid\": true)");
  const double nu = o.number("nu");
  return hasE ? Elastic::from_E_nu(o.number("E"), nu, path) : Elastic::from_G_nu(o.number("G"), nu, path);
}

/// `body_from_mesh` (problem finite): the body's elasticity is its mesh's (fe_body), so the
/// block gives the half-space ("base") only and the pair's body is rigid.
MaterialPair parse_materials(const json& j, bool body_from_mesh = false) {
  JsonBlock o(j, "materials");
  if (body_from_mesh) {
    o.allow({"base", "allow_large_strain"});
    return MaterialPair{Elastic::make_rigid(), parse_elastic(o.at("base"), "materials.base")};
  }
  o.allow({"body", "base", "allow_large_strain"});
  (void)o.boolean_or("allow_large_strain", false);  // read into Case by build_case
  MaterialPair m;
  m.body = parse_elastic(o.at("body"), "materials.body");
  m.base = parse_elastic(o.at("base"), "materials.base");
  if (m.body.rigid && m.base.rigid)
    throw InputError("materials", "both bodies are rigid: at least one must be elastic");
  return m;
}

// ---------------------------------------------------------------- normal, friction, solver, output

FrictionSpec parse_friction(const json& j) {
  JsonBlock o(j, "friction");
  FrictionSpec f;
  const std::string law = o.choice("law", "", {"coulomb", "tresca", "table"});
  f.law = law == "coulomb"  ? FrictionLawKind::coulomb
          : law == "tresca" ? FrictionLawKind::tresca
                            : FrictionLawKind::table;
  if (f.law == FrictionLawKind::coulomb) {
    o.allow({"law", "mu"});
    f.mu = o.number("mu");
    if (std::abs(f.mu) > 1e3) throw InputError(o.key("mu"), "must be at most 1000, got " + fmt(f.mu));
    if (f.mu < 0.0) throw InputError("friction.mu", "mu must be non-negative, got " + fmt(f.mu));
  } else if (f.law == FrictionLawKind::tresca) {
    o.allow({"law", "bound"});
    f.bound = o.positive_at_most("bound", 1e15, "Pa");
  } else {
    o.allow({"law", "pressure", "bound"});
    f.pressure = o.numbers("pressure");
    f.bound_table = o.numbers("bound");
    if (f.pressure.size() < 2) throw InputError("friction.pressure", "needs at least two values");
    if (f.bound_table.size() != f.pressure.size())
      throw InputError("friction.bound", "must have as many values as friction.pressure (" +
                                             std::to_string(f.pressure.size()) + "), got " +
                                             std::to_string(f.bound_table.size()));
    for (std::size_t i = 0; i < f.pressure.size(); ++i) {
      if (f.pressure[i] < 0.0) throw InputError("friction.pressure", "pressures must be non-negative");
      if (i > 0 && !(f.pressure[i] > f.pressure[i - 1]))
        throw InputError("friction.pressure", "pressures must be strictly increasing");
      if (f.bound_table[i] < 0.0) throw InputError("friction.bound", "bounds must be non-negative");
    }
  }
  return f;
}

/// SolverOptions::validate()'s "<field>: <reason>" as InputError("solver.<field>", reason).
void check_solver(const SolverOptions& s) {
  const std::string why = s.validate();
  if (why.empty()) return;
  const std::size_t colon = why.find(": ");
  throw InputError("solver." + why.substr(0, colon), why.substr(colon + 2));
}

SolverOptions parse_solver(const json& j) {
  JsonBlock o(j, "solver");
  o.allow({"backend", "tol", "certificate_tol", "max_iter", "fallback", "accept_unconverged", "hessian",
           "operator"});
  SolverOptions s;
  s.backend = *backend_from_string(o.choice("backend", to_string(s.backend), {"auto", "ipopt", "nlopt", "native"}));
  // Each value checked as it is read (the first bad key is the one reported).
  s.tol = o.number_or("tol", s.tol);
  check_solver(s);
  s.certificate_tol = o.number_or("certificate_tol", s.certificate_tol);
  check_solver(s);
  s.max_iter = o.integer_or("max_iter", s.max_iter);
  check_solver(s);
  s.fallback = o.boolean_or("fallback", s.fallback);
  s.accept_unconverged = o.boolean_or("accept_unconverged", s.accept_unconverged);
  s.hessian = *hessian_from_string(o.choice("hessian", to_string(s.hessian), {"auto", "exact", "limited-memory"}));
  s.operator_kind =
      *operator_kind_from_string(o.choice("operator", to_string(s.operator_kind), {"auto", "dense", "fft"}));
  return s;
}

OutputSpec parse_output(const json& j) {
  JsonBlock o(j, "output");
  o.allow({"dir", "fields", "plots", "snapshot_every"});
  OutputSpec out;
  out.snapshot_every = o.integer_or("snapshot_every", 0);
  if (out.snapshot_every < 0) throw InputError("output.snapshot_every", "must be 0 (none) or a number of steps");
  out.dir = o.string_or("dir", "");
  out.fields = o.boolean_or("fields", true);
  out.plots = o.boolean_or("plots", true);
  return out;
}

ProblemKind parse_problem(const JsonBlock& top) {
  const std::string kind = top.string("problem");
  if (kind == "normal") return ProblemKind::normal;
  if (kind == "tangential") return ProblemKind::tangential;
  if (kind == "dynamic") return ProblemKind::dynamic;
  if (kind == "paper_cylinder") return ProblemKind::paper_cylinder;
  if (kind == "finite") return ProblemKind::finite;
  throw InputError("problem", "unknown problem '" + kind +
                                  "' (expected normal, tangential, dynamic, paper_cylinder or finite)");
}

bool all_digits(const std::string& s) {
  return !s.empty() && std::all_of(s.begin(), s.end(), [](char ch) { return ch >= '0' && ch <= '9'; });
}

}  // namespace

NormalSpec read_normal(const json& j, const std::string& path) {
  JsonBlock o(j, path);
  o.allow({"force", "approach"});
  NormalSpec n;
  if (o.has("force") && o.has("approach"))
    throw InputError(o.key("approach"), "give either force or approach, not both");
  if (o.has("force")) {
    n.control = Control::force;
    n.value = o.positive_at_most("force", 1e15, "N (2-D: N/m)");
  } else if (o.has("approach")) {
    n.control = Control::approach;
    n.value = o.positive_at_most("approach", kMaxLength, "m");
  } else {
    throw InputError(o.key("force"), "missing required key (give force or approach)");
  }
  return n;
}

// ---------------------------------------------------------------- public API

nlohmann::json parse_case_text(const std::string& text, const std::string& origin) {
  try {
    return parse_json_checked(text, origin);
  } catch (const json::parse_error& e) {
    std::size_t pos = e.byte == 0 ? 0 : e.byte - 1;  // 0-based index of the offending character
    pos = std::min(pos, text.size());
    std::size_t line = 1, line_start = 0;
    for (std::size_t i = 0; i < pos; ++i)
      if (text[i] == '\n') {
        ++line;
        line_start = i + 1;
      }
    const std::size_t column = pos - line_start + 1;
    std::string reason = e.what();
    const auto at = reason.find(", column ");
    const auto colon = reason.find(": ", at == std::string::npos ? 0 : at);
    if (colon != std::string::npos) reason = reason.substr(colon + 2);
    throw InputError(origin, "malformed JSON at line " + std::to_string(line) + ", column " +
                                 std::to_string(column) + ": " + reason);
  }
}

nlohmann::json read_case_file(const std::string& path) {
  namespace fs = std::filesystem;
  std::error_code ec;
  if (fs::is_directory(path, ec)) throw InputError(path, "cannot open (it is a directory)");
  std::ifstream in(path, std::ios::binary);
  if (!in) throw InputError(path, "cannot open");
  std::ostringstream text;
  text << in.rdbuf();
  json doc = parse_case_text(text.str(), path);
  // Relative file names inside the case are relative to the case file's folder.
  const fs::path folder = fs::path(path).parent_path();
  auto resolve = [&](const char* block, const char* key) {
    if (!doc.is_object() || !doc.contains(block) || !doc[block].is_object()) return;
    json& b = doc[block];
    if (!b.contains(key) || !b[key].is_string()) return;
    const fs::path file(b[key].get<std::string>());
    if (file.is_relative() && !file.empty() && !folder.empty())
      b[key] = (folder / file).lexically_normal().string();
  };
  resolve("profile", "file");
  resolve("fe_body", "mesh");
  return doc;
}

void apply_override(nlohmann::json& document, const std::string& assignment) {
  const auto eq = assignment.find('=');
  if (eq == std::string::npos)
    throw InputError("--set", "expected path=value (e.g. materials.body.E=2e11), got '" + assignment + "'");
  const std::string path = assignment.substr(0, eq);
  const std::string text = assignment.substr(eq + 1);
  if (path.empty()) throw InputError("--set", "missing key path before '=' in '" + assignment + "'");
  if (text.empty()) throw InputError("--set", "missing value after '=' in '" + assignment + "'");
  std::vector<std::string> segments;
  {
    std::size_t start = 0;
    while (true) {
      const auto dot = path.find('.', start);
      segments.push_back(path.substr(start, dot == std::string::npos ? std::string::npos : dot - start));
      if (segments.back().empty())
        throw InputError("--set", "empty segment in key path '" + path + "'");
      if (dot == std::string::npos) break;
      start = dot + 1;
    }
  }
  json value;
  try {
    value = parse_json_checked(text, "--set " + path, path, /*ignore_comments=*/false);
  } catch (const json::parse_error&) {
    value = text;  // not JSON: a plain string (e.g. --set solver.backend=ipopt)
  }
  if (document.is_null()) document = json::object();
  json* node = &document;
  std::string walked;
  for (std::size_t s = 0; s < segments.size(); ++s) {
    const std::string& seg = segments[s];
    if (node->is_null()) *node = json::object();
    json* next = nullptr;
    if (node->is_object()) {
      next = &(*node)[seg];
    } else if (node->is_array() && all_digits(seg)) {
      const auto idx = std::stoull(seg);
      if (idx >= node->size())
        throw InputError("--set", "index " + seg + " is out of range for '" + walked + "' (" +
                                      std::to_string(node->size()) + " entries)");
      next = &(*node)[idx];
    } else {
      throw InputError("--set", "'" + (walked.empty() ? std::string("(top level)") : walked) + "' is " +
                                    describe(*node) + ", not an object: cannot set '" + path + "'");
    }
    walked = join(walked, seg);
    if (s + 1 == segments.size()) *next = value;
    node = next;
  }
}

namespace {

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

}  // namespace

bool Case::has_block(const std::string& block) const {
  return std::find(blocks.begin(), blocks.end(), block) != blocks.end();
}

Case build_case(const nlohmann::json& document, const std::string& base_dir) {
  JsonBlock top(document, "");
  top.allow({"schema", "name", "description", "problem", "dimension", "materials", "profile", "grid", "normal",
             "friction", "tangential", "fe_body", "body", "loads", "time", "traction_model", "dimensionless",
             "solver", "sweep", "output", "normal_model", "contact_model"});
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
  c.problem = parse_problem(top);
  c.dimension = top.integer_or("dimension", 3);
  if (c.dimension != 2 && c.dimension != 3)
    throw InputError("dimension", "must be 2 (plane strain) or 3, got " + std::to_string(c.dimension));

  // Blocks the static problems need; the other kinds take them when present.
  const bool static_problem = c.problem == ProblemKind::normal || c.problem == ProblemKind::tangential;
  auto required = [&](const char* k) { return static_problem || top.has(k); };
  const bool finite = c.problem == ProblemKind::finite;
  // A dynamic case may take its body as finite elements (core/case_fe_body.cpp).
  const bool fe = finite || (c.problem == ProblemKind::dynamic && top.has("fe_body"));
  if (required("materials")) {
    c.materials = parse_materials(top.at("materials"), fe);
    c.allow_large_strain = JsonBlock(top.at("materials"), "materials").boolean_or("allow_large_strain", false);
  }
  const bool has_profile = required("profile");
  if (has_profile) c.profile = read_profile(top.at("profile"), c.dimension, base_dir);
  bool has_normal = required("normal");
  if (has_normal) c.normal = read_normal(top.at("normal"), "normal");
  if (top.has("friction") || c.problem == ProblemKind::tangential)
    c.friction = parse_friction(top.at("friction"));
  if (top.has("tangential") || c.problem == ProblemKind::tangential) {
    if (!top.has("tangential")) throw InputError("tangential", "required for a tangential problem (an object)");
    c.tangential = read_tangential(top.at("tangential"), c.dimension, c.normal);
  }
  if (top.has("solver")) c.solver = parse_solver(top.at("solver"));
  if (top.has("output")) c.output = parse_output(top.at("output"));
  if (c.problem == ProblemKind::dynamic) {
    c.dynamic = read_dynamic(document, c);
    if (!has_normal && !fe) has_normal = dynamic_sizing_load(*c.dynamic, c, c.normal);
  }
  if (fe) read_finite_blocks(document, c, base_dir);  // core/case_fe_body.cpp
  if (required("grid") && !fe) {
    if (!has_profile) throw InputError("profile", "missing required key (the grid needs a profile)");
    c.grid = read_grid(top.at("grid"), c, has_normal);
    c.allow_edge_contact = JsonBlock(top.at("grid"), "grid").boolean_or("allow_edge_contact", false);
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

const char* to_string(FrictionLawKind law) {
  switch (law) {
    case FrictionLawKind::coulomb: return "coulomb";
    case FrictionLawKind::tresca: return "tresca";
    case FrictionLawKind::table: return "table";
  }
  return "unknown";
}

}  // namespace dc
