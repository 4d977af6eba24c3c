// The "output" block (CASES.md): the folder, which files, snapshots.
#include "case_readers.hpp"

#include <string>

#include "errors.hpp"
#include "json_block.hpp"

namespace dc {

using namespace case_json;

OutputSpec read_output(const json& j) {
  JsonBlock o(j, "output");
  o.allow({"dir", "fields", "plots", "snapshot_every", "power"});
  OutputSpec out;
  out.snapshot_every = o.integer_or("snapshot_every", 0);
  if (out.snapshot_every < 0) throw InputError("output.snapshot_every", "must be 0 (none) or a number of steps");
  out.dir = o.string_or("dir", "");
  out.fields = o.boolean_or("fields", true);
  out.plots = o.boolean_or("plots", true);
  out.power = o.boolean_or("power", false);
  return out;
}

}  // namespace dc
