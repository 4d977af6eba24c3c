// The "normal" block (CASES.md): a force or an approach, into NormalSpec (core/normal_spec.hpp).
#include "case_readers.hpp"

#include <string>

#include "errors.hpp"
#include "json_block.hpp"

namespace dc {

using namespace case_json;

NormalSpec read_normal(const json& j, const std::string& path) {
  JsonBlock o(j, path);
  o.allow({"force", "approach"});
  NormalSpec n;
  if (o.has("force") && o.has("approach"))
    throw InputError(o.key("approach"), "give either force or approach, not both");
  if (o.has("force")) {
    n.control = Control::force;
    n.value = o.positive_at_most("force", 1e15, "N (2-D: N/m)");
  } else if (o.has("approach")) {
    n.control = Control::approach;
    n.value = o.positive_at_most("approach", kMaxLength, "m");
  } else {
    throw InputError(o.key("force"), "missing required key (give force or approach)");
  }
  return n;
}

}  // namespace dc
