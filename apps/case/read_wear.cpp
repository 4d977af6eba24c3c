// The "wear" block (CASES.md): the law, the bodies, the number of cycles, how often the
// profile is updated, and (project extensions) the step the repeated cycle starts from and the
// rolling radius. It applies to a shift or torsion history (the grid does not move: both worn
// depths are maps on it) and to steady rolling (each pass wears the track and the body's
// circumference along the rows: a map uniform in x); anywhere else it is an error naming "wear".
#include <string>

#include "case_readers.hpp"
#include "errors.hpp"
#include "json_block.hpp"
#include "profile.hpp"

namespace dc {

using namespace case_json;

namespace {

long long positive_count(const JsonBlock& b, const char* k) {
  const json& v = b.at(k);
  if (!v.is_number_integer() || v.get<long long>() < 1 || v.get<long long>() > 1000000000000LL)
    throw InputError(b.key(k), "must be a positive integer (at most 1e12)");
  return v.get<long long>();
}

}  // namespace

WearSpec read_wear(const json& j, const Case& c) {
  if (c.problem != ProblemKind::tangential && c.problem != ProblemKind::dynamic)
    throw InputError("wear", std::string("computed for problems 'tangential' (a shift or torsion history, steady "
                                         "rolling) and 'dynamic', not '") +
                                 to_string(c.problem) + "'");
  JsonBlock w(j, "wear");
  w.allow({"law", "k", "hardness", "coefficient", "bodies", "cycles", "update", "cycle_from_step", "rolling_radius", "gap_feedback"});
  WearSpec s;
  if (!w.has("law")) throw InputError(w.key("law"), "required: \"archard\" or \"energy\"");
  const std::string law = w.choice("law", "", {"archard", "energy"});
  if (law == "archard") {
    s.law.kind = WearLawKind::archard;
    if (w.has("coefficient")) throw InputError(w.key("coefficient"), "belongs to law \"energy\" (Archard takes k and hardness)");
    if (!w.has("k")) throw InputError(w.key("k"), "required for Archard's law (dimensionless, > 0)");
    if (!w.has("hardness")) throw InputError(w.key("hardness"), "required for Archard's law (Pa, > 0)");
    s.law.k = w.positive("k");
    s.law.hardness = w.positive("hardness");
  } else {
    s.law.kind = WearLawKind::energy;
    for (const char* k : {"k", "hardness"})
      if (w.has(k)) throw InputError(w.key(k), "belongs to law \"archard\" (the energy law takes coefficient)");
    if (!w.has("coefficient")) throw InputError(w.key("coefficient"), "required for the energy law (m^3/J, > 0)");
    s.law.coefficient = w.positive("coefficient");
  }
  if (w.has("bodies")) {
    const json& b = w.at("bodies");
    if (!b.is_array() || b.empty()) throw InputError(w.key("bodies"), "expected a non-empty array of \"base\", \"body\"");
    s.base = s.body = false;
    for (const json& name : b) {
      if (name == "base") s.base = true;
      else if (name == "body") s.body = true;
      else throw InputError(w.key("bodies"), "expected \"base\" or \"body\", got " + name.dump());
    }
  }
  if (w.has("cycles")) s.cycles = positive_count(w, "cycles");
  if (w.has("update")) {
    JsonBlock u(w.at("update"), w.key("update"));  // an object (else an error naming wear.update)
    u.allow({"max_depth", "cycles"});
    if (!u.has("max_depth") && !u.has("cycles"))
      throw InputError(w.key("update"), "expected {\"max_depth\": m} or {\"cycles\": n}");
    if (u.has("max_depth")) s.update_max_depth = u.positive("max_depth");
    if (u.has("cycles")) s.update_cycles = positive_count(u, "cycles");
  }
  if (c.accuracy.target) throw InputError("wear", "not with accuracy.target (the worn profile is on the case's grid)");
  // A dynamic run wears over its own steps (apps/runs/dynamic_wear.hpp): no cycles to repeat.
  if (c.problem == ProblemKind::dynamic) {
    for (const char* k : {"cycles", "update", "cycle_from_step", "rolling_radius"})
      if (w.has(k))
        throw InputError(w.key(k), "belongs to a tangential case (a dynamic run wears over its own steps; its "
                                   "rolling radius is body.radius)");
    s.gap_feedback = w.boolean_or("gap_feedback", true);
    return s;
  }
  if (w.has("gap_feedback"))
    throw InputError(w.key("gap_feedback"), "belongs to a dynamic run (a history's and steady rolling's worn depth "
                                            "always enters the gap)");
  // Where the wear applies: a shift or torsion history, or steady rolling, on the case's own grid.
  const TangentialSpec* t = c.tangential ? &*c.tangential : nullptr;
  if (!t) throw InputError("wear", "needs a tangential block: a shift or torsion history, or steady rolling");
  if (t->regime == TangentialRegime::rolling) {
    if (t->has_history)
      throw InputError("wear", "computed for steady rolling or a shift or torsion history, not a rolling history "
                               "(transient rolling: not yet)");
    if (w.has("cycle_from_step")) throw InputError(w.key("cycle_from_step"), "belongs to a history (a rolling pass has no steps)");
    if (w.has("rolling_radius")) {
      s.rolling_radius = w.positive("rolling_radius");
    } else {
      double A = 0.0, B = 0.0;
      try {
        c.profile.quadratic_coefficients(A, B);
      } catch (const InputError&) {
        A = 0.0;
      }
      if (!(A > 0.0))
        throw InputError(w.key("rolling_radius"), "required: the profile has no curvature along x to give the rolling "
                                                  "radius (m, > 0; a cycle is one revolution)");
      s.rolling_radius = 0.5 / A;
    }
    return s;
  }
  if (w.has("rolling_radius")) throw InputError(w.key("rolling_radius"), "belongs to steady rolling");
  if (!t->has_history) throw InputError("wear", "needs a load cycle: tangential.history (its steps are one cycle)");
  const int steps = static_cast<int>(t->history.size());
  if (w.has("cycle_from_step")) {
    s.cycle_from_step = w.integer("cycle_from_step");
    if (s.cycle_from_step < 0 || s.cycle_from_step >= steps)
      throw InputError(w.key("cycle_from_step"), "a step of tangential.history, from 0 to " + std::to_string(steps - 1));
  }
  return s;
}

}  // namespace dc
