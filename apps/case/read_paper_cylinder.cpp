// The paper_cylinder blocks (CASES.md, docs/paper_cylinder.md) read into PaperCylinderSpec,
// and the expansion of its sweep into one case per value.
#include <limits>

#include "case_readers.hpp"
#include "case_model.hpp"
#include "errors.hpp"
#include "json_block.hpp"

namespace dc {

using namespace case_json;

namespace {

void read_dimensionless(const JsonBlock& d, PaperCylinderSpec& s) {
  d.allow({"gamma_bar", "M0_bar", "eta", "epsilon", "v_bar0", "t_bar_end", "T_bar", "mu"});
  auto get = [&](const char* k, std::optional<double>& out) {
    if (d.has(k)) out = d.number(k);
  };
  get("gamma_bar", s.gamma_bar);
  get("M0_bar", s.M0_bar);
  get("epsilon", s.epsilon);
  get("v_bar0", s.v_bar0);
  get("t_bar_end", s.t_bar_end);
  get("T_bar", s.T_bar);
  get("mu", s.mu);
  if (d.has("eta")) {
    const json& e = d.at("eta");
    if (e.is_string() && e.get<std::string>() == "inf") s.eta = std::numeric_limits<double>::infinity();
    else s.eta = d.number("eta");
  }
}

/// body, loads, time of the dimensional inputs; the model's own limits on the derived
/// parameters are checked where they are converted (apps/runs/paper_cylinder_run).
void read_dimensional(const JsonBlock& top, const Case& c, PaperCylinderSpec& s) {
  PaperCylinderBody& b = s.body;
  const JsonBlock body = top.child("body");
  body.allow({"mass", "inertia", "radius", "initial"});
  b.mass = body.number("mass");
  b.radius = body.number("radius");
  const json& inertia = body.at("inertia");
  b.inertia_y = inertia.is_array() && inertia.size() == 3 ? finite_number(inertia[1], "body.inertia[1]")
                                                          : body.number("inertia");
  if (!(b.mass > 0.0)) throw InputError("body.mass", "must be positive");
  if (!(b.radius > 0.0)) throw InputError("body.radius", "must be positive");
  if (!(b.inertia_y > 0.0))
    throw InputError("body.inertia", "the moment of inertia about the axis (y) must be positive");
  const JsonBlock init = body.child("initial");
  init.allow({"position", "velocity", "omega"});
  auto vec = [&](const char* k, std::array<double, 3>& out) {
    if (!init.has(k)) return;
    const auto v = init.numbers(k);
    if (v.size() != 3) throw InputError(init.key(k), "must be [x, y, z]");
    out = {v[0], v[1], v[2]};
  };
  vec("position", b.position);
  vec("velocity", b.velocity);
  vec("omega", b.omega);
  b.has_position = init.has("position");
  if (!(b.velocity[0] > 0.0))
    throw InputError("body.initial.velocity[0]", "the cylinder must be rolling in +x (V0 > 0)");

  const JsonBlock loads = top.child("loads");
  loads.allow({"force", "moment"});
  const JsonBlock force = loads.child("force");
  force.allow({"x", "z"});
  b.force_z = read_value_rate(force, "z");
  if (force.has("x")) b.force_x = read_value_rate(force, "x");
  const JsonBlock moment = loads.child("moment");
  moment.allow({"y"});
  b.moment_y = read_value_rate(moment, "y");
  if (b.force_z.rate != 0.0) throw InputError("loads.force.z.rate", "the paper's model keeps the normal load constant");
  if (b.force_x.rate != 0.0) throw InputError("loads.force.x.rate", "the paper's model takes a constant T_ex");
  if (!(-b.force_z.value > 0.0))
    throw InputError("loads.force.z.value", "must press the cylinder onto the half-plane (< 0)");
  if (!c.friction || c.friction->law != FrictionLawKind::coulomb)
    throw InputError("friction", "the paper's model needs Coulomb friction {\"law\": \"coulomb\", \"mu\": ...}");
  if (!top.has("materials")) throw InputError("materials", "missing required key");

  const JsonBlock time = top.child("time");
  time.allow({"dt", "t_end", "scheme"});
  b.t_end = time.number("t_end");
  b.dt = time.number("dt");
  if (!(b.t_end > 0.0)) throw InputError("time.t_end", "must be positive");
  if (!(b.dt > 0.0)) throw InputError("time.dt", "must be positive");
}

bool scheme_is_bdf2(const JsonBlock& top) {
  if (!top.has("time") || !top.at("time").is_object() || !top.at("time").contains("scheme")) return false;
  const json& v = top.at("time").at("scheme");
  const std::string s = v.is_string() ? v.get<std::string>() : "";
  if (s != "bdf1" && s != "bdf2") throw InputError("time.scheme", "must be \"bdf1\" or \"bdf2\"");
  return s == "bdf2";
}

}  // namespace

PaperCylinderSpec read_paper_cylinder(const json& document, const Case& c) {
  const JsonBlock top(document, "");
  PaperCylinderSpec s;
  s.dimensional = !top.has("dimensionless") && top.has("body");
  s.bdf2 = scheme_is_bdf2(top);
  if (s.dimensional) {
    read_dimensional(top, c, s);
  } else {
    if (!top.has("dimensionless"))
      throw InputError("dimensionless",
                       "required: the paper's dimensionless inputs, or the dimensional blocks body, loads, time");
    for (const char* k : {"body", "loads"})
      if (top.has(k))
        throw InputError(k, "not used with dimensionless inputs (give either \"dimensionless\" or body, loads, time)");
    read_dimensionless(top.child("dimensionless"), s);
    if (top.has("time")) {
      const JsonBlock time = top.child("time");
      time.allow({"dt", "scheme"});
      if (time.has("dt")) {
        s.dt = time.number("dt");
        if (!(*s.dt > 0.0))
          throw InputError("time.dt", "must be positive (a step of t_bar for dimensionless inputs)");
      }
    }
  }
  s.traction_model = top.choice("traction_model", s.traction_model, {"numerical", "carter_poritsky"});
  if (c.sweep && !s.dimensional && c.sweep->key.rfind("dimensionless.", 0) != 0)
    throw InputError("sweep." + c.sweep->key, "with dimensionless inputs, sweep a dimensionless.* key");
  return s;
}

}  // namespace dc
