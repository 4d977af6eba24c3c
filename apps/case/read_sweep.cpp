// The `sweep` block: one run per value of one key of the case (paper_cylinder, dynamic), each
// run its own case read from the document with that value set.
#include <string>

#include "case_model.hpp"
#include "errors.hpp"

namespace dc {

SweepSpec read_sweep(const nlohmann::json& block) {
  if (block.size() != 1)
    throw InputError("sweep", "give exactly one key to sweep, e.g. {\"loads.moment.y.rate\": [0.1, 0.5]}");
  SweepSpec s{block.begin().key(), block.begin().value()};
  if (!s.values.is_array() || s.values.empty())
    throw InputError("sweep." + s.key, "must be a non-empty array of values");
  return s;
}

std::vector<SweepPoint> sweep_points(const Case& c) {
  if (!c.sweep) return {{"", nlohmann::json(), c}};
  const std::string prefix = "dimensionless.";
  const std::string& key = c.sweep->key;
  const std::string shown = key.rfind(prefix, 0) == 0 ? key.substr(prefix.size()) : key;
  std::vector<SweepPoint> out;
  for (const nlohmann::json& v : c.sweep->values) {
    nlohmann::json doc = c.source;
    doc.erase("sweep");
    apply_override(doc, key + "=" + v.dump());
    out.push_back({shown + " = " + (v.is_string() ? v.get<std::string>() : v.dump()), v, build_case(doc)});
  }
  return out;
}

}  // namespace dc
