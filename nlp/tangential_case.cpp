// The "tangential" block of a case (CASES.md) turned into load steps and solved.
#include <cmath>
#include <functional>
#include <set>

#include "errors.hpp"
#include "profile.hpp"
#include "tangential_problem.hpp"

namespace dc {
namespace {

using nlohmann::json;

double number_at(const json& v, const std::string& key) {
  if (!v.is_number()) throw InputError(key, "must be a number");
  const double x = v.get<double>();
  if (!std::isfinite(x)) throw InputError(key, "must be finite");
  return x;
}

/// [x, y] (3-D) or x / [x] / [x, 0] (2-D).
std::array<double, 2> pair_at(const json& v, const std::string& key, int dimension) {
  if (v.is_number()) {
    if (dimension == 3) throw InputError(key, "needs two components [x, y] in 3-D");
    return {number_at(v, key), 0.0};
  }
  if (!v.is_array() || v.empty() || v.size() > 2) throw InputError(key, "must be an array [x, y]");
  std::array<double, 2> out{number_at(v[0], key + "[0]"), v.size() > 1 ? number_at(v[1], key + "[1]") : 0.0};
  if (dimension == 3 && v.size() != 2) throw InputError(key, "needs two components [x, y] in 3-D");
  if (dimension == 2 && out[1] != 0.0) throw InputError(key + "[1]", "a 2-D problem has no y component");
  return out;
}

NormalSpec normal_at(const json& v, const std::string& key) {
  if (!v.is_object()) throw InputError(key, "must be an object {\"force\": ...} or {\"approach\": ...}");
  NormalSpec n;
  for (auto it = v.begin(); it != v.end(); ++it)
    if (it.key() != "force" && it.key() != "approach") throw InputError(key + "." + it.key(), "unknown key");
  if (v.contains("force") == v.contains("approach")) throw InputError(key, "give exactly one of force, approach");
  n.control = v.contains("force") ? Control::force : Control::approach;
  n.value = number_at(v.contains("force") ? v["force"] : v["approach"], key + (v.contains("force") ? ".force" : ".approach"));
  if (!(n.value > 0.0)) throw InputError(key, "the normal force or approach must be positive");
  return n;
}

/// Reads the rigid-mode controls of one step from `v` into `modes` (keys not given keep their
/// previous control). Quasi-static: shift/force, angle/moment. Rolling: creepage/force, spin.
void read_modes(const json& v, const std::string& prefix, bool rolling, int dimension,
                std::array<ModeControl, 3>& modes) {
  const char* amplitude_key = rolling ? "creepage" : "shift";
  if (v.contains(amplitude_key) && v.contains("force"))
    throw InputError(prefix + "force", std::string("give either force or ") + amplitude_key + ", not both");
  if (v.contains("force")) {
    const auto f = pair_at(v["force"], prefix + "force", dimension);
    modes[0] = {ModeControl::Kind::resultant, f[0]};
    if (dimension == 3) modes[1] = {ModeControl::Kind::resultant, f[1]};
  }
  if (v.contains(amplitude_key)) {
    const auto s = pair_at(v[amplitude_key], prefix + amplitude_key, dimension);
    modes[0] = {ModeControl::Kind::amplitude, s[0]};
    modes[1] = {ModeControl::Kind::amplitude, s[1]};
  }
  const bool has_angle = v.contains(rolling ? "spin" : "angle");
  if (has_angle && v.contains("moment")) throw InputError(prefix + "moment", "give either angle/spin or moment");
  if ((has_angle || v.contains("moment")) && dimension == 2)
    throw InputError(prefix + (has_angle ? (rolling ? "spin" : "angle") : "moment"), "not defined in 2-D");
  if (has_angle) modes[2] = {ModeControl::Kind::amplitude, number_at(v[rolling ? "spin" : "angle"], prefix + (rolling ? "spin" : "angle"))};
  if (v.contains("moment")) modes[2] = {ModeControl::Kind::resultant, number_at(v["moment"], prefix + "moment")};
}

void check_keys(const json& v, const std::string& prefix, const std::set<std::string>& allowed) {
  for (auto it = v.begin(); it != v.end(); ++it)
    if (!allowed.count(it.key()))
      throw InputError(prefix + it.key(), "unknown key");
}

/// The steps of tangential.history, in order, each an object with keys from `allowed` only and
/// read by `read(step, "tangential.history[k].", load)` into the previous step's load (the first
/// into `load`), so a step keeps what it does not set. All are read before any is solved.
template <class Load>
std::vector<Load> read_history(const json& t, const std::set<std::string>& allowed, Load load,
                               const std::function<void(const json&, const std::string&, Load&)>& read) {
  if (!t["history"].is_array() || t["history"].empty())
    throw InputError("tangential.history", "must be a non-empty array of steps");
  std::vector<Load> out;
  for (std::size_t k = 0; k < t["history"].size(); ++k) {
    const json& s = t["history"][k];
    const std::string prefix = "tangential.history[" + std::to_string(k) + "].";
    if (!s.is_object()) throw InputError(prefix.substr(0, prefix.size() - 1), "each step must be an object");
    check_keys(s, prefix, allowed);
    read(s, prefix, load);
    out.push_back(load);
  }
  return out;
}

/// One step of a rolling history: the load, and the distance rolled under it.
struct RollingStep {
  RollingLoad load;
  double distance = 0.0;
};

}  // namespace

std::vector<TangentialSolution> solve_tangential_case(const Case& c, const ProgressCallback& progress) {
  const json& t = c.tangential;
  if (!t.is_object()) throw InputError("tangential", "required for a tangential problem (an object)");
  if (!c.friction) throw InputError("friction", "required for a tangential problem");
  if (!t.contains("regime") || !t["regime"].is_string())
    throw InputError("tangential.regime", "required: \"shift\", \"torsion\" or \"rolling\"");
  const std::string regime = t["regime"].get<std::string>();
  if (regime != "shift" && regime != "torsion" && regime != "rolling")
    throw InputError("tangential.regime", "unknown regime '" + regime + "' (shift, torsion, rolling)");
  const bool rolling = regime == "rolling";
  check_keys(t, "tangential.",
             rolling ? std::set<std::string>{"regime", "force", "creepage", "spin", "moment", "velocity", "max_steps", "history"}
                     : std::set<std::string>{"regime", "force", "shift", "angle", "moment", "history"});

  OperatorKind kind = OperatorKind::automatic;
  if (c.solver.operator_kind == "dense") kind = OperatorKind::dense;
  if (c.solver.operator_kind == "fft") kind = OperatorKind::fft;
  TangentialProblem problem(c.grid, c.materials, profile_heights(c.profile, c.grid),
                            FrictionLaw::from_spec(*c.friction), kind);
  std::vector<TangentialSolution> out;
  if (rolling) {
    RollingLoad load;
    load.normal = c.normal;
    read_modes(t, "tangential.", true, c.dimension, load.modes);
    if (t.contains("velocity")) load.velocity = number_at(t["velocity"], "tangential.velocity");
    if (t.contains("max_steps")) {
      if (t.contains("history"))
        throw InputError("tangential.max_steps", "steady rolling only: a rolling history rolls each step's distance");
      if (!t["max_steps"].is_number_integer() || t["max_steps"].get<int>() < 1)
        throw InputError("tangential.max_steps", "must be a positive integer");
      load.max_steps = t["max_steps"].get<int>();
    }
    if (!t.contains("history")) {
      out.push_back(problem.steady_rolling(load, c.solver, progress));
      return out;
    }
    // Transient rolling (project extension): each step rolls its distance from the state the
    // previous step left (memory kept); distance 0 is a quasi-static step (e.g. Cattaneo's).
    const auto steps = read_history<RollingStep>(
        t, {"force", "creepage", "spin", "moment", "normal", "distance"}, {load, 0.0},
        [&](const json& s, const std::string& prefix, RollingStep& step) {
          if (s.contains("normal")) step.load.normal = normal_at(s["normal"], prefix + "normal");
          read_modes(s, prefix, true, c.dimension, step.load.modes);
          if (!s.contains("distance")) throw InputError(prefix + "distance", "required in a rolling step (m)");
          step.distance = number_at(s["distance"], prefix + "distance");
          if (step.distance < 0.0) throw InputError(prefix + "distance", "must be >= 0 (m)");
        });
    for (const RollingStep& step : steps) out.push_back(problem.roll(step.load, step.distance, c.solver, progress));
    return out;
  }
  TangentialLoad load;
  load.normal = c.normal;
  read_modes(t, "tangential.", false, c.dimension, load.modes);
  if (!t.contains("history")) {
    out.push_back(problem.step(load, c.solver, progress));
    return out;
  }
  const auto steps = read_history<TangentialLoad>(
      t, {"force", "shift", "angle", "moment", "normal"}, load,
      [&](const json& s, const std::string& prefix, TangentialLoad& step) {
        if (s.contains("normal")) step.normal = normal_at(s["normal"], prefix + "normal");
        read_modes(s, prefix, false, c.dimension, step.modes);
      });
  for (const TangentialLoad& step : steps) out.push_back(problem.step(step, c.solver, progress));
  return out;
}

}  // namespace dc
