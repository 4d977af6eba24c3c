// The dynamic blocks (CASES.md: body, loads, time, normal_model, contact_model) read into
// DynamicSpec.
#include <algorithm>
#include <cmath>

#include "case_model.hpp"
#include "case_readers.hpp"
#include "errors.hpp"
#include "json_block.hpp"

namespace dc {

using namespace case_json;

namespace {

/// [x, y, z], each component of magnitude at most `max` (`unit` for the message).
std::array<double, 3> vector3(const JsonBlock& o, const char* k, double max, const char* unit) {
  const auto v = o.numbers(k);
  if (v.size() != 3) throw InputError(o.key(k), "must be [x, y, z]");
  for (int i = 0; i < 3; ++i)
    if (!(std::abs(v[i]) <= max))
      throw InputError(o.key(k) + "[" + std::to_string(i) + "]",
                       "must be at most " + fmt(max) + " " + unit + " in magnitude, got " + fmt(v[i]));
  return {v[0], v[1], v[2]};
}

// Physical ranges of the rigid body (beyond them the arithmetic, not the physics, decides).
constexpr double kMaxMass = 1e15, kMinMass = 1e-15;   // kg (2-D: kg/m)
constexpr double kMaxInertia = 1e15;                  // kg m^2
constexpr double kMaxSpeed = 1e4;                     // m/s
constexpr double kMaxOmega = 1e7;                     // rad/s

void read_body(const JsonBlock& body, const Case& c, DynamicSpec& s) {
  body.allow({"mass", "inertia", "radius", "initial"});
  // An fe_body's mass, inertia and radius come from its mesh (given ones are checked against it).
  s.has_mass = body.has("mass") || !s.fe_body;
  s.has_inertia = body.has("inertia") || !s.fe_body;
  s.has_radius = body.has("radius");
  if (s.has_mass) s.mass = body.bounded("mass", kMinMass, kMaxMass, "kg");
  if (s.has_inertia && body.at("inertia").is_number()) {
    const double i = body.positive_at_most("inertia", kMaxInertia, "kg m^2");
    s.inertia = {i, i, i};
  } else if (s.has_inertia) {
    s.inertia = vector3(body, "inertia", kMaxInertia, "kg m^2");
    for (int k = 0; k < 3; ++k)
      if (!(s.inertia[k] > 0.0))
        throw InputError("body.inertia[" + std::to_string(k) + "]", "principal moments must be positive");
  }
  if (body.has("radius")) {
    s.radius = body.positive_at_most("radius", kMaxLength, "m");
  } else if (!s.fe_body && (c.profile.type == ProfileType::sphere || c.profile.type == ProfileType::cylinder)) {
    s.radius = c.profile.radius;  // a ball or a wheel: the centre of mass at the centre
  } else if (!s.fe_body) {
    throw InputError("body.radius", "missing required key (the height of the centre of mass over the lowest point "
                                    "of the profile; only a sphere or cylinder profile implies it)");
  }
  if (body.has("initial")) {
    const JsonBlock init = body.child("initial");
    init.allow({"position", "velocity", "omega"});
    if (init.has("position")) {
      s.position = vector3(init, "position", kMaxLength, "m");
      s.has_position = true;
    }
    if (init.has("velocity")) s.velocity = vector3(init, "velocity", kMaxSpeed, "m/s");
    if (init.has("omega")) s.omega = vector3(init, "omega", kMaxOmega, "rad/s");
  }
  if (!s.has_position) s.position = {0.0, 0.0, s.radius};  // fe_body: set from the mesh's radius
  if (c.dimension == 2) {
    // Plane strain: motion in the x-z plane, rotation about y only.
    if (s.velocity[1] != 0.0) throw InputError("body.initial.velocity[1]", "a 2-D body moves in the x-z plane (0)");
    if (s.omega[0] != 0.0 || s.omega[2] != 0.0)
      throw InputError("body.initial.omega", "a 2-D body turns about y only ([0, w, 0])");
  }
}

void read_loads(const JsonBlock& loads, const Case& c, DynamicSpec& s) {
  loads.allow({"force", "moment"});
  static const char* axes[] = {"x", "y", "z"};
  for (const char* block : {"force", "moment"}) {
    if (!loads.has(block)) continue;
    const JsonBlock b = loads.child(block);
    b.allow({"x", "y", "z"});
    auto& out = std::string(block) == "force" ? s.force : s.moment;
    for (int k = 0; k < 3; ++k)
      if (b.has(axes[k])) out[k] = read_value_rate(b, axes[k]);
  }
  if (c.dimension == 2) {
    auto zero = [](const ValueRate& v) { return v.value == 0.0 && v.rate == 0.0; };
    if (!zero(s.force[1])) throw InputError("loads.force.y", "a 2-D case has no load along y");
    if (!zero(s.moment[0]) || !zero(s.moment[2]))
      throw InputError("loads.moment", "a 2-D case takes a moment about y only");
  }
}

/// A finite body's dynamic contact is shift and torsion only (2.16), as the paper restricts
/// case (a): nothing that rolls it or convects its contact.
void check_shift_torsion(const JsonBlock& top, DynamicSpec& s) {
  const char* why = " (a finite body's contact is shift and torsion only, (2.16))";
  if (top.has("profile"))
    throw InputError("profile", "not used with an fe_body: its mesh's face gives the gap");
  if (top.has("contact_model"))
    throw InputError("contact_model", std::string("not taken with an fe_body: no convected or steady rolling "
                                                  "contact") + why);
  if (s.omega[0] != 0.0 || s.omega[1] != 0.0)
    throw InputError("body.initial.omega", std::string("an fe_body turns about z only ([0, 0, w]): rolling") + why);
  for (int k = 0; k < 2; ++k)
    if (s.moment[k].value != 0.0 || s.moment[k].rate != 0.0)
      throw InputError(std::string("loads.moment.") + (k == 0 ? "x" : "y"),
                       std::string("an fe_body takes a moment about z only: rolling") + why);
  if (s.normal_model == NormalModel::quasi_static)
    throw InputError("normal_model", "an fe_body's normal contact follows its height ('dynamic')");
  s.contact_model = ContactModel::transient;
}

/// time.adaptive and its tolerances and bounds (docs/dynamics.md "Adaptive time steps"): rtol
/// 1e-4, atol 1e-9 (m/s), dt_min the larger of 1e-6 dt and 1e-13 t_end, dt_max the larger of
/// dt and t_end / 10 unless given.
void read_adaptive(const JsonBlock& time, DynamicSpec& s) {
  s.adaptive = time.boolean_or("adaptive", false);
  if (!s.adaptive) {
    for (const char* k : {"rtol", "atol", "dt_min", "dt_max"})
      if (time.has(k)) throw InputError(time.key(k), "is used only with time.adaptive: true");
    return;
  }
  // Below 1e-8 the step's Newton and contact tolerances (~1e-9 of the speeds) decide the error.
  s.rtol = time.has("rtol") ? time.bounded("rtol", 1e-8, 0.1, "(a share of the state)") : 1e-4;
  s.atol = time.has("atol") ? time.positive_at_most("atol", 1.0, "m/s") : 1e-9;
  s.dt_min = time.has("dt_min") ? time.positive("dt_min") : std::max(1e-6 * s.dt, 1e-13 * s.t_end);
  s.dt_max = time.has("dt_max") ? time.positive("dt_max") : std::max(s.dt, 0.1 * s.t_end);
  // A shorter step would not move the time (its round-off is ~1e-16 t_end).
  if (!(s.dt_min >= 1e-13 * s.t_end))
    throw InputError(time.key("dt_min"), "must be at least 1e-13 time.t_end (the time's resolution), got " +
                                             fmt(s.dt_min));
  if (!(s.dt_min <= s.dt))
    throw InputError(time.key("dt_min"), "must be at most time.dt (the first step), got " + fmt(s.dt_min));
  if (!(s.dt_max >= s.dt))
    throw InputError(time.key("dt_max"), "must be at least time.dt (the first step), got " + fmt(s.dt_max));
}

void read_time(const JsonBlock& time, DynamicSpec& s) {
  time.allow({"dt", "t_end", "scheme", "energy_tolerance", "allow_coarse_dt", "adaptive", "rtol", "atol", "dt_min",
              "dt_max"});
  s.dt = time.positive("dt");
  s.t_end = time.positive("t_end");
  if (time.has("energy_tolerance")) {
    s.energy_tolerance = time.positive("energy_tolerance");
    if (!(s.energy_tolerance <= 1.0)) throw InputError(time.key("energy_tolerance"), "must be at most 1 (a share of the energy)");
  }
  s.allow_coarse_dt = time.boolean_or("allow_coarse_dt", false);
  if (s.t_end / s.dt > 1e8) throw InputError("time.dt", "over 1e8 steps to time.t_end");
  s.bdf2 = time.choice("scheme", "bdf2", {"bdf1", "bdf2"}) == "bdf2";
  read_adaptive(time, s);
}

}  // namespace

DynamicSpec read_dynamic(const nlohmann::json& document, const Case& c) {
  const JsonBlock top(document, "");
  DynamicSpec s;
  s.fe_body = top.has("fe_body");
  for (const char* k : {"materials", "profile", "grid", "body", "time"})
    if (!top.has(k) && !(s.fe_body && std::string(k) == "profile"))
      throw InputError(k, "missing required key (a dynamic case needs it)");
  read_body(top.child("body"), c, s);
  if (top.has("loads")) read_loads(top.child("loads"), c, s);
  read_time(top.child("time"), s);
  const std::string normal = top.choice("normal_model", "dynamic", {"dynamic", "quasi_static"});
  s.normal_model = normal == "dynamic" && c.dimension == 3 ? NormalModel::dynamic : NormalModel::quasi_static;
  if (s.normal_model == NormalModel::quasi_static && !(-s.force[2].value > 0.0))
    throw InputError("loads.force.z", "a quasi-static normal model (and every 2-D case) needs a vertical load "
                                      "pressing the body down: value < 0");
  const std::string contact = top.choice("contact_model", "auto", {"transient", "steady", "auto"});
  s.contact_model = contact == "transient" ? ContactModel::transient
                    : contact == "steady"  ? ContactModel::steady
                                           : ContactModel::automatic;
  if (s.fe_body) check_shift_torsion(top, s);
  return s;
}


}  // namespace dc
