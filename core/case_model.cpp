// The case file contract (shared spec CASES.md): parsing, overrides and validation.
// Every bad input throws InputError(key path, reason); unknown keys are errors.
#include "case_model.hpp"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <initializer_list>
#include <limits>
#include <sstream>
#include <string>
#include <vector>

#include "errors.hpp"
#include "json_block.hpp"
#include "json_parse.hpp"
#include "hertz.hpp"

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

MaterialPair parse_materials(const json& j) {
  JsonBlock o(j, "materials");
  o.allow({"body", "base", "allow_large_strain"});
  (void)o.boolean_or("allow_large_strain", false);  // read into Case by build_case
  MaterialPair m;
  m.body = parse_elastic(o.at("body"), "materials.body");
  m.base = parse_elastic(o.at("base"), "materials.base");
  if (m.body.rigid && m.base.rigid)
    throw InputError("materials", "both bodies are rigid: at least one must be elastic");
  return m;
}

// ---------------------------------------------------------------- profile

/// Reads a CSV table with a header naming the columns x, y (optional) and h.
void read_table(ProfileSpec& p, const std::string& file_key, const std::string& base_dir) {
  namespace fs = std::filesystem;
  fs::path path(p.file);
  if (path.is_relative() && !base_dir.empty()) path = fs::path(base_dir) / path;
  std::ifstream in(path);
  if (!in || fs::is_directory(path)) throw InputError(file_key, "cannot open '" + path.string() + "'");
  auto split = [](const std::string& line) {
    std::vector<std::string> cells;
    std::string cell;
    std::istringstream s(line);
    while (std::getline(s, cell, ',')) {
      const auto b = cell.find_first_not_of(" \t\r");
      const auto e = cell.find_last_not_of(" \t\r");
      cells.push_back(b == std::string::npos ? std::string() : cell.substr(b, e - b + 1));
    }
    return cells;
  };
  std::string line;
  int line_no = 0;
  int ix = -1, iy = -1, ih = -1;
  std::size_t columns = 0;
  p.table_x.clear();
  p.table_y.clear();
  p.table_h.clear();
  while (std::getline(in, line)) {
    ++line_no;
    if (line.find_first_not_of(" \t\r") == std::string::npos || line[line.find_first_not_of(" \t")] == '#')
      continue;
    const auto cells = split(line);
    if (ih < 0) {  // header
      for (std::size_t c = 0; c < cells.size(); ++c) {
        if (cells[c] == "x") ix = static_cast<int>(c);
        else if (cells[c] == "y") iy = static_cast<int>(c);
        else if (cells[c] == "h") ih = static_cast<int>(c);
      }
      if (ix < 0 || ih < 0)
        throw InputError(file_key, "line " + std::to_string(line_no) +
                                       ": expected a header naming the columns x,y,h");
      columns = cells.size();
      continue;
    }
    if (cells.size() != columns)
      throw InputError(file_key, "line " + std::to_string(line_no) + ": expected " +
                                     std::to_string(columns) + " values, got " + std::to_string(cells.size()));
    auto value = [&](int c) {
      const std::string& s = cells[static_cast<std::size_t>(c)];
      char* end = nullptr;
      const double v = std::strtod(s.c_str(), &end);
      if (s.empty() || end != s.c_str() + s.size() || !std::isfinite(v))
        throw InputError(file_key, "line " + std::to_string(line_no) + ": '" + s + "' is not a number");
      return v;
    };
    p.table_x.push_back(value(ix));
    p.table_y.push_back(iy >= 0 ? value(iy) : 0.0);
    p.table_h.push_back(value(ih));
  }
  if (ih < 0) throw InputError(file_key, "the file is empty (expected a header x,y,h and rows)");
  if (p.table_h.size() < 2) throw InputError(file_key, "the table needs at least two rows");
  // Heights are measured from the first point of contact: shift the table's minimum to 0.
  const double h_min = *std::min_element(p.table_h.begin(), p.table_h.end());
  for (double& h : p.table_h) h -= h_min;
}

ProfileSpec parse_profile(const json& j, int dimension, const std::string& base_dir) {
  JsonBlock o(j, "profile");
  const std::string type = o.string("type");
  ProfileSpec p;
  const bool three_d = dimension == 3;
  auto three_d_only = [&](const char* what) {
    if (!three_d)
      throw InputError("profile.type", std::string("'") + what +
                                           "' is a 3-D profile; in 2-D (plane strain) use 'cylinder' or "
                                           "'quadratic' (h = a x^2), or set dimension 3");
  };
  if (type == "sphere") {
    three_d_only("sphere");
    o.allow({"type", "radius"});
    p.type = ProfileType::sphere;
    p.radius = o.positive("radius");
  } else if (type == "ellipsoid") {
    three_d_only("ellipsoid");
    o.allow({"type", "radius_x", "radius_y"});
    p.type = ProfileType::ellipsoid;
    p.radius_x = o.positive("radius_x");
    p.radius_y = o.positive("radius_y");
  } else if (type == "cylinder") {
    if (three_d) o.allow({"type", "radius", "length"});
    else o.allow({"type", "radius"});
    p.type = ProfileType::cylinder;
    p.radius = o.positive("radius");
    if (three_d) p.length = o.has("length") ? o.positive("length") : 0.0;
  } else if (type == "flat_punch") {
    three_d_only("flat_punch");
    o.allow({"type", "radius"});
    p.type = ProfileType::flat_punch;
    p.radius = o.positive("radius");
  } else if (type == "quadratic") {
    p.type = ProfileType::quadratic;
    if (three_d) {
      o.allow({"type", "a", "b"});
      p.a = o.non_negative("a");
      p.b = o.non_negative("b");
      if (p.a == 0.0 && p.b == 0.0)
        throw InputError("profile.a", "a and b cannot both be zero (a flat profile has no contact point; "
                                      "use flat_punch)");
    } else {
      o.allow({"type", "a"});
      p.a = o.positive("a");
    }
  } else if (type == "table") {
    o.allow({"type", "file"});
    p.type = ProfileType::table;
    p.file = o.string("file");
    if (p.file.empty()) throw InputError("profile.file", "must name a CSV file");
    read_table(p, "profile.file", base_dir);
  } else {
    throw InputError("profile.type", "unknown profile type '" + type +
                                         "' (expected sphere, ellipsoid, cylinder, flat_punch, quadratic, table)");
  }
  return p;
}

// ---------------------------------------------------------------- normal, friction, solver, output

FrictionSpec parse_friction(const json& j) {
  JsonBlock o(j, "friction");
  FrictionSpec f;
  f.law = o.choice("law", "", {"coulomb", "tresca", "table"});
  if (f.law == "coulomb") {
    o.allow({"law", "mu"});
    f.mu = o.number("mu");
    if (f.mu < 0.0) throw InputError("friction.mu", "mu must be non-negative, got " + fmt(f.mu));
  } else if (f.law == "tresca") {
    o.allow({"law", "bound"});
    f.bound = o.positive("bound");
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

SolverSpec parse_solver(const json& j) {
  JsonBlock o(j, "solver");
  o.allow({"backend", "tol", "certificate_tol", "max_iter", "fallback", "accept_unconverged", "hessian",
           "operator"});
  SolverSpec s;
  s.backend = o.choice("backend", s.backend, {"auto", "ipopt", "nlopt", "native"});
  if (o.has("tol")) s.tol = o.positive("tol");
  if (o.has("certificate_tol")) s.certificate_tol = o.positive("certificate_tol");
  s.max_iter = o.integer_or("max_iter", s.max_iter);
  if (s.max_iter < 1) throw InputError("solver.max_iter", "must be at least 1, got " + std::to_string(s.max_iter));
  s.fallback = o.boolean_or("fallback", s.fallback);
  s.accept_unconverged = o.boolean_or("accept_unconverged", s.accept_unconverged);
  s.hessian = o.choice("hessian", s.hessian, {"auto", "exact", "limited-memory"});
  s.operator_kind = o.choice("operator", s.operator_kind, {"auto", "dense", "fft"});
  return s;
}

OutputSpec parse_output(const json& j) {
  JsonBlock o(j, "output");
  o.allow({"dir", "fields", "plots"});
  OutputSpec out;
  out.dir = o.string_or("dir", "");
  out.fields = o.boolean_or("fields", true);
  out.plots = o.boolean_or("plots", true);
  return out;
}

// ---------------------------------------------------------------- grid

/// Hertz semi-axes (x, y) of the case's contact, for `extent` grids.
void hertz_semi_axes(const Case& c, bool has_normal, double& ax, double& ay) {
  const ProfileSpec& p = c.profile;
  if (p.type == ProfileType::flat_punch) {
    ax = ay = p.radius;
    return;
  }
  if (p.type == ProfileType::table)
    throw InputError("grid.extent", "a table profile has no Hertz estimate: give explicit grid.x (and grid.y) bounds");
  if (!has_normal)
    throw InputError("grid.extent", "needs normal.force or normal.approach to size the Hertz contact");
  const double E_star = c.materials.E_star();
  const bool approach = c.normal.control == Control::approach;
  const char* approach_2d =
      "with normal.approach the 2-D/line contact width is not fixed by Hertz (the plane-strain approach "
      "depends on a reference length): give explicit grid.x bounds";
  double A = 0.0, B = 0.0;
  p.quadratic_coefficients(A, B);
  if (c.dimension == 2) {
    if (approach) throw InputError("grid.extent", approach_2d);
    ax = hertz::cylinder2d(0.5 / A, c.normal.value, E_star).a;
    ay = ax;
    return;
  }
  if (A == 0.0 || B == 0.0) {
    if (p.type == ProfileType::cylinder && p.length > 0.0) {
      if (approach) throw InputError("grid.extent", approach_2d);
      ax = hertz::cylinder2d(p.radius, c.normal.value / p.length, E_star).a;
      ay = 0.5 * p.length;
      return;
    }
    throw InputError("grid.extent", "the contact of this profile is unbounded along one axis "
                                    "(give the cylinder a length, or explicit grid bounds)");
  }
  double P = c.normal.value;
  if (A == B) {  // axisymmetric: the sphere formulas, P = 4/3 E* sqrt(R) approach^(3/2)
    const double R = 0.5 / A;
    if (approach) P = 4.0 / 3.0 * E_star * std::sqrt(R) * std::pow(c.normal.value, 1.5);
    ax = ay = hertz::sphere(R, P, E_star).a;
    return;
  }
  if (approach) {  // approach ~ P^(2/3): invert from the unit-load solution
    const double d1 = hertz::elliptic(A, B, 1.0, E_star).approach;
    P = std::pow(c.normal.value / d1, 1.5);
  }
  const auto s = hertz::elliptic(A, B, P, E_star);
  ax = s.a;
  ay = s.b;
}

std::vector<double> bounds(const JsonBlock& o, const char* k) {
  const auto v = o.numbers(k);
  if (v.size() != 2) throw InputError(o.key(k), "expected [min, max]");
  if (!(v[1] > v[0])) throw InputError(o.key(k), "expected [min, max] with min < max");
  return v;
}

Grid parse_grid(const json& j, const Case& c, bool has_normal) {
  JsonBlock o(j, "grid");
  const bool three_d = c.dimension == 3;
  o.allow({"nx", "ny", "x", "y", "extent", "allow_edge_contact"});
  (void)o.boolean_or("allow_edge_contact", false);  // read into Case by build_case
  const int nx = o.integer("nx");
  if (nx < 1) throw InputError("grid.nx", "must be at least 1, got " + std::to_string(nx));
  // One element across cannot represent a pressure distribution (a 1 x 1 grid puts the whole
  // load on one uniform element: the peak comes out about 3 times too low).
  if (nx == 1)
    throw InputError("grid.nx", "one element across cannot resolve the contact pressure; use at least 2 (about "
                                "8 or more across the contact for a usable peak pressure)");
  int ny = 1;
  if (three_d) {
    ny = o.integer("ny");
    if (ny < 1) throw InputError("grid.ny", "must be at least 1, got " + std::to_string(ny));
    if (ny == 1)
      throw InputError("grid.ny", "one element across cannot resolve the contact pressure in 3-D; use at least 2 "
                                  "(or dimension 2 for a plane-strain line contact)");
  } else if (o.has("ny")) {
    ny = o.integer("ny");
    if (ny != 1) throw InputError("grid.ny", "must be 1 (or omitted) in 2-D, got " + std::to_string(ny));
  }
  if (static_cast<double>(nx) * ny > 4194304.0)
    throw InputError("grid", "too many elements (" + std::to_string(static_cast<long long>(nx) * ny) +
                                 "; at most 2048 x 2048)");
  const bool has_x = o.has("x"), has_extent = o.has("extent");
  if (has_x && has_extent) throw InputError("grid.extent", "give either extent or x/y bounds, not both");
  if (has_extent) {
    if (three_d && o.has("y")) throw InputError("grid.y", "give either extent or x/y bounds, not both");
    const double k = o.positive("extent");
    double ax = 0.0, ay = 0.0;
    hertz_semi_axes(c, has_normal, ax, ay);
    if (!(std::isfinite(ax) && ax > 0.0 && std::isfinite(ay) && ay > 0.0))
      throw InputError("grid.extent", "the Hertz estimate of the contact size is not finite");
    return Grid::make(c.dimension, nx, ny, -k * ax, k * ax, -k * ay, k * ay);
  }
  if (!has_x) throw InputError("grid.x", "missing required key (give x [min, max]" +
                                             std::string(three_d ? " and y" : "") + ", or extent)");
  const auto x = bounds(o, "x");
  if (!three_d) return Grid::make(2, nx, 1, x[0], x[1], 0.0, 0.0);
  if (!o.has("y")) throw InputError("grid.y", "missing required key (3-D grids need y [min, max])");
  const auto y = bounds(o, "y");
  return Grid::make(3, nx, ny, x[0], x[1], y[0], y[1]);
}

/// The profile must be able to touch inside the grid: its first point of contact lies in the
/// grid and some element has a finite gap. Otherwise the normal problem cannot carry the load.
void check_contact_in_grid(const Case& c) {
  const Grid& g = c.grid;
  const std::vector<double> h = profile_heights(c.profile, g);
  if (std::none_of(h.begin(), h.end(), [](double v) { return std::isfinite(v); }))
    throw InputError("grid", "no element centre lies under the profile (refine the grid or enlarge the punch)");
  const ProfileSpec& p = c.profile;
  double px = 0.0, py = 0.0;
  bool free_x = false, free_y = false;  // the contact is a line along that axis
  double half_len_y = 0.0;              // finite cylinder: the line's half-length
  if (p.type == ProfileType::table) {
    const auto k = static_cast<std::size_t>(std::min_element(p.table_h.begin(), p.table_h.end()) - p.table_h.begin());
    px = p.table_x[k];
    py = p.table_y[k];
    const bool single_row = std::all_of(p.table_y.begin(), p.table_y.end(), [&](double v) { return v == p.table_y[0]; });
    free_y = single_row;
  } else if (p.type == ProfileType::cylinder) {
    free_y = true;
    half_len_y = 0.5 * p.length;
  } else if (p.type == ProfileType::quadratic) {
    free_x = p.a == 0.0;
    free_y = p.b == 0.0;
  }
  const double tx = 1e-12 * (g.x_max() - g.x0), ty = 1e-12 * (g.y_max() - g.y0);
  bool inside = free_x || (px >= g.x0 - tx && px <= g.x_max() + tx);
  if (g.dimension == 3 && !free_y) inside = inside && py >= g.y0 - ty && py <= g.y_max() + ty;
  if (g.dimension == 3 && free_y && half_len_y > 0.0)
    inside = inside && g.y_max() > -half_len_y && g.y0 < half_len_y;
  if (!inside) {
    std::string where = "grid x in [" + fmt(g.x0) + ", " + fmt(g.x_max()) + "]";
    if (g.dimension == 3) where += ", y in [" + fmt(g.y0) + ", " + fmt(g.y_max()) + "]";
    throw InputError("grid", "the contact point lies outside the grid (" + where + " does not contain (" +
                                 fmt(px) + ", " + fmt(py) + "), where the profile first touches): " +
                                 "the contact could not carry the load");
  }
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
    n.value = o.positive("force");
  } else if (o.has("approach")) {
    n.control = Control::approach;
    n.value = o.positive("approach");
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
/// a problem that does not use it is an error naming it. `dynamic` and `finite` take every
/// block until their readers list theirs here.
struct BlockUse {
  const char* block;
  std::vector<ProblemKind> problems;
};
const std::vector<BlockUse>& block_uses() {
  using P = ProblemKind;
  static const std::vector<BlockUse> uses = {
      {"materials", {P::normal, P::tangential, P::paper_cylinder}},
      {"profile", {P::normal, P::tangential, P::paper_cylinder}},
      {"grid", {P::normal, P::tangential, P::paper_cylinder}},
      {"normal", {P::normal, P::tangential, P::paper_cylinder}},
      {"friction", {P::tangential, P::paper_cylinder}},
      {"tangential", {P::tangential}},
      {"body", {P::paper_cylinder}},
      {"loads", {P::paper_cylinder}},
      {"time", {P::paper_cylinder}},
      {"traction_model", {P::paper_cylinder}},
      {"dimensionless", {P::paper_cylinder}},
      {"sweep", {P::paper_cylinder}},
      {"fe_body", {}},
  };
  return uses;
}

void reject_unused_blocks(const JsonBlock& top, ProblemKind problem) {
  if (problem == ProblemKind::dynamic || problem == ProblemKind::finite) return;
  for (const BlockUse& use : block_uses()) {
    if (!top.has(use.block)) continue;
    if (std::find(use.problems.begin(), use.problems.end(), problem) != use.problems.end()) continue;
    std::string users;
    for (ProblemKind p : use.problems) users += std::string(users.empty() ? "" : ", ") + to_string(p);
    throw InputError(use.block, std::string("not used by problem '") + to_string(problem) + "' (remove it" +
                                    (users.empty() ? "" : "; it belongs to problem " + users) + ")");
  }
}

}  // namespace

bool Case::has_block(const std::string& block) const {
  return std::find(blocks.begin(), blocks.end(), block) != blocks.end();
}

Case build_case(const nlohmann::json& document, const std::string& base_dir) {
  JsonBlock top(document, "");
  top.allow({"schema", "name", "description", "problem", "dimension", "materials", "profile", "grid", "normal",
             "friction", "tangential", "fe_body", "body", "loads", "time", "traction_model", "dimensionless",
             "solver", "sweep", "output"});
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
  if (required("materials")) {
    c.materials = parse_materials(top.at("materials"));
    c.allow_large_strain = JsonBlock(top.at("materials"), "materials").boolean_or("allow_large_strain", false);
  }
  const bool has_profile = required("profile");
  if (has_profile) c.profile = parse_profile(top.at("profile"), c.dimension, base_dir);
  const bool has_normal = required("normal");
  if (has_normal) c.normal = read_normal(top.at("normal"), "normal");
  if (top.has("friction") || c.problem == ProblemKind::tangential)
    c.friction = parse_friction(top.at("friction"));
  if (top.has("tangential") || c.problem == ProblemKind::tangential) {
    if (!top.has("tangential")) throw InputError("tangential", "required for a tangential problem (an object)");
    c.tangential = read_tangential(top.at("tangential"), c.dimension, c.normal);
  }
  if (top.has("solver")) c.solver = parse_solver(top.at("solver"));
  if (top.has("output")) c.output = parse_output(top.at("output"));
  if (required("grid")) {
    if (!has_profile) throw InputError("profile", "missing required key (the grid needs a profile)");
    c.grid = parse_grid(top.at("grid"), c, has_normal);
    c.allow_edge_contact = JsonBlock(top.at("grid"), "grid").boolean_or("allow_edge_contact", false);
    check_contact_in_grid(c);
  }
  if (c.problem == ProblemKind::paper_cylinder) c.paper_cylinder = read_paper_cylinder(document, c);

  // Blocks of the dynamic and finite problems: shape only, until their readers are here.
  for (const char* k : {"fe_body", "body", "loads", "time", "dimensionless", "sweep"})
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
