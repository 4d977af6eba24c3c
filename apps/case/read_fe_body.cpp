// The "fe_body" block (CASES.md): the finite-element body's shape or mesh file, mesh sizes,
// materials (isotropic, cubic or 21 anisotropic constants) per region, density. Read into
// FeBodySpec (core/fe_body_spec.hpp); the finite blocks of problem "finite".
#include <algorithm>
#include <cmath>
#include <filesystem>

#include "case_readers.hpp"
#include "errors.hpp"
#include "fe_body_spec.hpp"
#include "json_block.hpp"

namespace dc {

using namespace case_json;

namespace {

/// {"E", "nu"} | {"cubic": [C11, C12, C44]} | {"C": [21 values]}, with the block's density.
fe::BodyMaterial read_body_material(const JsonBlock& m, double density) {
  m.allow({"E", "nu", "cubic", "C", "density"});
  fe::BodyMaterial out;
  out.density = m.has("density") ? m.positive("density") : density;
  const int given = (m.has("E") || m.has("nu") ? 1 : 0) + (m.has("cubic") ? 1 : 0) + (m.has("C") ? 1 : 0);
  if (given != 1) throw InputError(m.path(), "give one of {E, nu}, cubic [C11, C12, C44] or C [21 constants]");
  if (m.has("C")) {
    const auto v = m.numbers("C");
    if (v.size() != 21)
      throw InputError(m.key("C"), "needs the 21 constants of the Voigt upper triangle, got " + std::to_string(v.size()));
    std::array<double, 21> a{};
    std::copy(v.begin(), v.end(), a.begin());
    out.C = fe::anisotropic_stiffness(a, m.key("C"));
  } else if (m.has("cubic")) {
    const auto v = m.numbers("cubic");
    if (v.size() != 3) throw InputError(m.key("cubic"), "needs [C11, C12, C44]");
    out.C = fe::cubic_stiffness(v[0], v[1], v[2], m.key("cubic"));
  } else {
    out.C = fe::isotropic_stiffness(m.number("E"), m.number("nu"), m.path());
  }
  return out;
}

std::array<int, 3> read_elements(const JsonBlock& b) {
  std::array<int, 3> out{8, 8, 8};
  if (!b.has("elements")) return out;
  const json& v = b.at("elements");
  if (v.is_number()) {
    out.fill(b.integer("elements"));
  } else {
    const auto n = b.numbers("elements");
    if (n.size() != 3) throw InputError(b.key("elements"), "needs one number or three [nx, ny, nz]");
    for (int i = 0; i < 3; ++i) {
      if (n[i] != std::floor(n[i]))
        throw InputError(b.key("elements") + "[" + std::to_string(i) + "]", "divisions are whole numbers, got " + fmt(n[i]));
      out[i] = static_cast<int>(std::clamp(n[i], -1.0, 1001.0));
    }
  }
  for (int n : out)
    if (n < 1 || n > 1000) throw InputError(b.key("elements"), "divisions must lie in 1..1000");
  return out;
}

}  // namespace

FeBodySpec read_fe_body(const json& block, const std::string& case_dir) {
  const JsonBlock b(block, "fe_body");
  b.allow({"shape", "size", "radius", "height", "mesh", "elements", "contact_size", "refine_radius", "material",
           "regions", "density", "program", "tilt", "load_line"});
  FeBodySpec s;
  s.program = b.choice("program", s.program, {"condensed", "sparse"});
  const std::string shape = b.choice("shape", "hemisphere", {"block", "cylinder", "hemisphere", "mesh"});
  if (shape == "block") {
    s.shape = FeShape::block;
    const auto v = b.numbers("size");
    if (v.size() != 3) throw InputError(b.key("size"), "needs [lx, ly, height]");
    for (int i = 0; i < 3; ++i) {
      if (!(v[i] > 0.0)) throw InputError(b.key("size"), "every length must be positive");
      s.size[i] = v[i];
    }
  } else if (shape == "cylinder") {
    s.shape = FeShape::cylinder;
    s.radius = b.positive("radius");
    s.height = b.positive("height");
  } else if (shape == "hemisphere") {
    s.shape = FeShape::hemisphere;
    s.radius = b.positive("radius");
  } else {
    s.shape = FeShape::mesh;
    const std::filesystem::path p(b.string("mesh"));
    s.mesh_file = (p.is_absolute() ? p : std::filesystem::path(case_dir) / p).string();
    if (!std::filesystem::is_regular_file(s.mesh_file))
      throw InputError(b.key("mesh"), "file '" + s.mesh_file + "' not found");
  }
  if (b.has("tilt") && b.has("load_line"))
    throw InputError(b.key("load_line"), "give either a tilt or a load line (whose moment rows make the tilt free)");
  for (const char* key : {"tilt", "load_line"})
    if (b.has(key)) {
      const auto v = b.numbers(key);
      if (v.size() != 2) throw InputError(b.key(key), "needs two numbers [x, y]");
      // A tilt of the body's face (rad): the half-space model holds for small slopes only.
      if (std::string(key) == "tilt" && !(std::abs(v[0]) <= 0.1 && std::abs(v[1]) <= 0.1))
        throw InputError(b.key(key), "each tilt must be at most 0.1 rad in magnitude (the half-space model needs "
                                     "small slopes), got [" + fmt(v[0]) + ", " + fmt(v[1]) + "]");
      if (std::string(key) == "tilt") s.tilt = {v[0], v[1]};
      else s.load_line = std::array<double, 2>{v[0], v[1]};
    }
  s.elements = read_elements(b);
  s.contact_size = b.has("contact_size") ? b.positive("contact_size") : 0.0;
  if (b.has("refine_radius")) {
    s.refine_radius = b.number("refine_radius");
    if (!(*s.refine_radius >= 0.0)) throw InputError(b.key("refine_radius"), "must be a length >= 0");
  }
  const double density = b.positive("density");
  s.material = read_body_material(b.child("material"), density);
  if (b.has("regions")) {
    const json& r = b.at("regions");
    if (!r.is_array()) throw InputError(b.key("regions"), "must be an array of {z_below, material}");
    for (std::size_t k = 0; k < r.size(); ++k) {
      const JsonBlock rb(r[k], "fe_body.regions[" + std::to_string(k) + "]");
      rb.allow({"z_below", "material"});
      s.regions.push_back({rb.positive("z_below"), read_body_material(rb.child("material"), density)});
    }
  }
  return s;
}

void read_finite_blocks(const json& document, Case& c, const std::string& base_dir) {
  const JsonBlock top(document, "");
  // A dynamic case with an fe_body: the body's motion sets the approach (no normal block).
  const bool dynamic = c.problem == ProblemKind::dynamic;
  const std::string problem = dynamic ? "'dynamic' with an fe_body" : "'finite'";
  for (const char* k : {"materials", "fe_body", "grid", "normal"})
    if (!top.has(k) && !(dynamic && std::string(k) == "normal"))
      throw InputError(k, "missing required block for problem " + problem);
  if (dynamic && top.has("normal"))
    throw InputError("normal", "not used by a dynamic fe_body (its motion sets the approach)");
  if (c.dimension != 3) throw InputError("dimension", "problem " + problem + " is 3-D");
  c.fe_body = read_fe_body(top.at("fe_body"), base_dir);
  if (JsonBlock(top.at("grid"), "grid").has("extent"))
    throw InputError("grid.extent", "problem " + problem + " needs the grid's x and y bounds (no Hertz estimate of its size)");
  c.grid = read_grid(top.at("grid"), c, true);
  c.allow_edge_contact = JsonBlock(top.at("grid"), "grid").boolean_or("allow_edge_contact", false);
  if (dynamic && (c.fe_body->load_line || c.fe_body->tilt != std::array<double, 2>{0.0, 0.0}))
    throw InputError(c.fe_body->load_line ? "fe_body.load_line" : "fe_body.tilt",
                     "a dynamic body's tilt is its motion's: not given");
  if (dynamic && c.fe_body->program != "condensed")
    throw InputError("fe_body.program", "a dynamic fe_body takes the condensed program (each step a warm-started "
                                        "solve with the kept factor)");
  if (c.tangential && c.tangential->regime == TangentialRegime::rolling)
    throw InputError("tangential.regime", "rolling is not available for a finite body (shift or torsion)");
  if (c.tangential && !c.friction) throw InputError("friction", "required with a tangential block");
  if (c.fe_body->load_line && (c.tangential || c.fe_body->program == "sparse" || c.normal.control != Control::force))
    throw InputError("fe_body.load_line", "the moment rows of a load line go with a normal force on the condensed "
                                          "program (no tangential block, no approach, program 'condensed')");
}

}  // namespace dc
