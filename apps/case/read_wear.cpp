// The "wear" block (CASES.md): the law, the bodies, the number of cycles, how often the
// profile is updated, and (project extension) the step the repeated cycle starts from. It
// applies to a shift or torsion history (the grid does not move: both worn depths are maps on
// it); anywhere else it is an error naming "wear".
#include <string>

#include "case_readers.hpp"
#include "errors.hpp"
#include "json_block.hpp"

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
  if (c.problem != ProblemKind::tangential)
    throw InputError("wear", std::string("computed for problem 'tangential' (a shift or torsion history), not '") +
                                 to_string(c.problem) + "'");
  JsonBlock w(j, "wear");
  w.allow({"law", "k", "hardness", "coefficient", "bodies", "cycles", "update", "cycle_from_step"});
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
  // Where the wear applies: a shift or torsion history solved on the case's own grid.
  const TangentialSpec* t = c.tangential ? &*c.tangential : nullptr;
  if (!t || t->regime == TangentialRegime::rolling)
    throw InputError("wear", "computed for a shift or torsion history, not a rolling one (the worn surface would move)");
  if (!t->has_history) throw InputError("wear", "needs a load cycle: tangential.history (its steps are one cycle)");
  if (c.accuracy.target) throw InputError("wear", "not with accuracy.target (the worn profile is on the case's grid)");
  const int steps = static_cast<int>(t->history.size());
  if (w.has("cycle_from_step")) {
    s.cycle_from_step = w.integer("cycle_from_step");
    if (s.cycle_from_step < 0 || s.cycle_from_step >= steps)
      throw InputError(w.key("cycle_from_step"), "a step of tangential.history, from 0 to " + std::to_string(steps - 1));
  }
  return s;
}

}  // namespace dc
