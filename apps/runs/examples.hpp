#pragma once
// Bundled example cases (`dyncontact example NAME`): the same text as the files in examples/.
#include <string>
#include <vector>

namespace dc::runs {

struct BundledExample {
  const char* name;
  const char* summary;  ///< one line for `dyncontact example --list`
  const char* text = nullptr;  ///< the case file, byte for byte as examples/<name>.json
};

const std::vector<BundledExample>& bundled_examples();
/// nullptr when no example has that name.
const BundledExample* find_example(const std::string& name);

}  // namespace dc::runs
