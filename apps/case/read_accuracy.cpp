// The "accuracy" block (CASES.md): estimate, target, quantities and the refinement's budgets.
#include <algorithm>
#include <string>

#include "case_readers.hpp"
#include "errors.hpp"
#include "json_block.hpp"

namespace dc {

using namespace case_json;

const std::vector<AccuracyQuantityName>& accuracy_quantity_names() {
  static const std::vector<AccuracyQuantityName> names = {
      {"max_pressure", true, true, false},      {"approach", true, true, false},
      {"normal_force", true, true, false},      {"contact_area", true, true, false},
      {"contact_half_width", true, true, false}, {"tangential_force", false, true, false},
      {"Fx", false, true, false},               {"Fy", false, true, false},
      {"twisting_moment", false, true, false},  {"Mz", false, true, false},
      {"rigid_shift", false, true, false},      {"creepage", false, true, false},
      {"stick_area", false, true, false},       {"slip_area", false, true, false},
      {"stick_fraction", false, true, false},   {"max_normal_force", false, false, true},
      {"max_approach", false, false, true},     {"max_contact_area", false, false, true},
      {"contact_time", false, false, true},     {"rebound_velocity", false, false, true},
  };
  return names;
}

AccuracySpec read_accuracy(const json& j, ProblemKind problem, int dimension) {
  JsonBlock o(j, "accuracy");
  o.allow({"estimate", "target", "quantities", "max_elements", "max_seconds"});
  AccuracySpec a;
  a.estimate = o.boolean_or("estimate", problem != ProblemKind::dynamic || o.has("target"));
  if (o.has("target")) {
    a.target = o.positive("target");
    if (*a.target >= 0.5) throw InputError("accuracy.target", "a relative error below 0.5 (e.g. 1e-3), got " + fmt(*a.target));
    if (*a.target < 1e-7)
      throw InputError("accuracy.target", "below 1e-7 the solver's own tolerance, not the grid, limits the error; got " +
                                              fmt(*a.target));
    if (!a.estimate) throw InputError("accuracy.estimate", "a target needs the error estimate (remove estimate: false)");
  }
  if (o.has("quantities")) {
    const json& q = o.at("quantities");
    if (!q.is_array() || q.empty()) throw InputError("accuracy.quantities", "expected a non-empty array of names");
    for (const json& e : q) {
      if (!e.is_string()) throw InputError("accuracy.quantities", "expected names, found " + describe(e));
      const std::string name = e.get<std::string>();
      const auto& names = accuracy_quantity_names();
      auto of_problem = [&](const AccuracyQuantityName& n) {
        return problem == ProblemKind::dynamic ? n.dynamic : problem == ProblemKind::tangential ? n.tangential : n.normal;
      };
      const auto it = std::find_if(names.begin(), names.end(), [&](const auto& n) { return name == n.name; });
      std::string list;
      for (const auto& n : names)
        if (of_problem(n)) list += (list.empty() ? "" : ", ") + std::string(n.name);
      if (it == names.end() || !of_problem(*it))
        throw InputError("accuracy.quantities", "unknown quantity '" + name + "' for problem " + to_string(problem) +
                                                    " (expected one of: " + list + ")");
      // 3-D contacts report contact_half_width_x and _y, not one half-width (no estimate of it).
      if (name == "contact_half_width" && dimension != 2)
        throw InputError("accuracy.quantities", "'contact_half_width' is a result of 2-D (line) contacts; in 3-D name "
                                                "contact_area or max_pressure");
      a.quantities.push_back(name);
    }
  }
  if (o.has("max_elements")) {
    const double m = o.number("max_elements");
    if (!(m >= 64 && m <= 4194304.0 && m == static_cast<long long>(m)))
      throw InputError("accuracy.max_elements", "an integer from 64 to 4194304 (2048 x 2048), got " + fmt(m));
    a.max_elements = static_cast<long long>(m);
  }
  if (o.has("max_seconds")) a.max_seconds = o.positive("max_seconds");
  if (!a.target && (o.has("max_elements") || o.has("max_seconds")))
    throw InputError(o.has("max_elements") ? "accuracy.max_elements" : "accuracy.max_seconds",
                     "a budget of the refinement to a target: give accuracy.target too");
  return a;
}

}  // namespace dc
