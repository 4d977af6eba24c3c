// The "tangential" block (CASES.md): regime, rigid-mode controls, rolling speed and the
// loading history, read into TangentialSpec. Every bad input names its key path.
#include "case_readers.hpp"

#include "errors.hpp"
#include "json_block.hpp"

namespace dc {

using namespace case_json;

namespace {

/// [x, y] (3-D) or x / [x] / [x, 0] (2-D).
std::array<double, 2> pair_at(const json& v, const std::string& key, int dimension) {
  if (v.is_number()) {
    if (dimension == 3) throw InputError(key, "needs two components [x, y] in 3-D");
    return {finite_number(v, key), 0.0};
  }
  if (!v.is_array() || v.empty() || v.size() > 2) throw InputError(key, "must be an array [x, y]");
  std::array<double, 2> out{finite_number(v[0], key + "[0]"), v.size() > 1 ? finite_number(v[1], key + "[1]") : 0.0};
  if (dimension == 3 && v.size() != 2) throw InputError(key, "needs two components [x, y] in 3-D");
  if (dimension == 2 && out[1] != 0.0) throw InputError(key + "[1]", "a 2-D problem has no y component");
  return out;
}

/// Reads the rigid-mode controls of one step into `modes` (keys not given keep their previous
/// control). Quasi-static: shift/force, angle/moment. Rolling: creepage/force, spin/moment.
void read_modes(const JsonBlock& v, bool rolling, int dimension, std::array<ModeControl, 3>& modes) {
  const char* amplitude_key = rolling ? "creepage" : "shift";
  const char* angle_key = rolling ? "spin" : "angle";
  if (v.has(amplitude_key) && v.has("force"))
    throw InputError(v.key("force"), std::string("give either force or ") + amplitude_key + ", not both");
  if (v.has("force")) {
    const auto f = pair_at(v.at("force"), v.key("force"), dimension);
    modes[0] = {ModeControl::Kind::resultant, f[0]};
    if (dimension == 3) modes[1] = {ModeControl::Kind::resultant, f[1]};
  }
  if (v.has(amplitude_key)) {
    const auto s = pair_at(v.at(amplitude_key), v.key(amplitude_key), dimension);
    modes[0] = {ModeControl::Kind::amplitude, s[0]};
    modes[1] = {ModeControl::Kind::amplitude, s[1]};
  }
  const bool has_angle = v.has(angle_key);
  if (has_angle && v.has("moment")) throw InputError(v.key("moment"), "give either angle/spin or moment");
  if ((has_angle || v.has("moment")) && dimension == 2)
    throw InputError(v.key(has_angle ? angle_key : "moment"), "not defined in 2-D");
  if (has_angle) modes[2] = {ModeControl::Kind::amplitude, v.number(angle_key)};
  if (v.has("moment")) modes[2] = {ModeControl::Kind::resultant, v.number("moment")};
}

/// The steps of tangential.history, each an object read by `read` into a copy of the previous
/// step (the first into `first`), so a step keeps what it does not set.
template <class Step, class Read>
std::vector<Step> read_history(const JsonBlock& t, Step first, const Read& read) {
  const json& h = t.at("history");
  if (!h.is_array() || h.empty()) throw InputError("tangential.history", "must be a non-empty array of steps");
  std::vector<Step> out;
  for (std::size_t k = 0; k < h.size(); ++k) {
    const std::string path = "tangential.history[" + std::to_string(k) + "]";
    if (!h[k].is_object()) throw InputError(path, "each step must be an object");
    read(JsonBlock(h[k], path), first);
    out.push_back(first);
  }
  return out;
}

double rolling_velocity(const JsonBlock& t) {
  if (!t.has("velocity")) return 1.0;
  const double v = t.number("velocity");
  if (!(v > 0.0)) throw InputError("tangential.velocity", "the rolling speed must be positive");
  return v;
}

}  // namespace

std::vector<NormalSpec> TangentialSpec::step_normals() const {
  std::vector<NormalSpec> out;
  if (!has_history) out.push_back(regime == TangentialRegime::rolling ? rolling.normal : load.normal);
  for (const auto& s : history) out.push_back(s.normal);
  for (const auto& s : rolling_history) out.push_back(s.load.normal);
  return out;
}

const char* to_string(TangentialRegime regime) {
  switch (regime) {
    case TangentialRegime::shift: return "shift";
    case TangentialRegime::torsion: return "torsion";
    case TangentialRegime::rolling: return "rolling";
  }
  return "unknown";
}

TangentialSpec read_tangential(const json& j, int dimension, const NormalSpec& normal) {
  JsonBlock t(j, "tangential");
  TangentialSpec spec;
  if (!t.has("regime") || !t.at("regime").is_string())
    throw InputError("tangential.regime", "required: \"shift\", \"torsion\" or \"rolling\"");
  const std::string regime = t.string("regime");
  if (regime == "shift") spec.regime = TangentialRegime::shift;
  else if (regime == "torsion") spec.regime = TangentialRegime::torsion;
  else if (regime == "rolling") spec.regime = TangentialRegime::rolling;
  else throw InputError("tangential.regime", "unknown regime '" + regime + "' (shift, torsion, rolling)");
  spec.has_history = t.has("history");

  if (spec.regime != TangentialRegime::rolling) {
    t.allow({"regime", "force", "shift", "angle", "moment", "history"});
    spec.load.normal = normal;
    read_modes(t, false, dimension, spec.load.modes);
    if (spec.has_history)
      spec.history = read_history(t, spec.load, [&](const JsonBlock& s, TangentialLoad& step) {
        s.allow({"force", "shift", "angle", "moment", "normal"});
        if (s.has("normal")) step.normal = read_normal(s.at("normal"), s.key("normal"));
        read_modes(s, false, dimension, step.modes);
      });
    return spec;
  }

  t.allow({"regime", "force", "creepage", "spin", "moment", "velocity", "max_steps", "history"});
  RollingLoad& load = spec.rolling;
  load.normal = normal;
  read_modes(t, true, dimension, load.modes);
  load.velocity = rolling_velocity(t);
  if (t.has("max_steps")) {
    if (spec.has_history)
      throw InputError("tangential.max_steps", "steady rolling only: a rolling history rolls each step's distance");
    if (!t.at("max_steps").is_number_integer() || t.at("max_steps").get<long long>() < 1 ||
        t.at("max_steps").get<long long>() > 1000000000)
      throw InputError("tangential.max_steps", "must be a positive integer");
    load.max_steps = static_cast<int>(t.at("max_steps").get<long long>());
  }
  // Transient rolling (project extension): each step rolls its distance from the state the
  // previous step left (memory kept); distance 0 is a quasi-static step (e.g. Cattaneo's).
  if (spec.has_history)
    spec.rolling_history = read_history(t, RollingStep{load, 0.0}, [&](const JsonBlock& s, RollingStep& step) {
      s.allow({"force", "creepage", "spin", "moment", "normal", "distance"});
      if (s.has("normal")) step.load.normal = read_normal(s.at("normal"), s.key("normal"));
      read_modes(s, true, dimension, step.load.modes);
      if (!s.has("distance")) throw InputError(s.key("distance"), "required in a rolling step (m)");
      step.distance = s.number("distance");
      if (step.distance < 0.0) throw InputError(s.key("distance"), "must be >= 0 (m)");
    });
  return spec;
}

}  // namespace dc
