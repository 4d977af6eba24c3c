// libFuzzer target: `--set` overrides on the bundled examples. The first byte picks the example,
// the rest is split at newlines into assignments (path=value), applied in order, then the case
// is validated (build_case). Seeded with assignments such as normal.force=200.
#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include "case_model.hpp"
#include "fuzz_support.hpp"

namespace {

const std::vector<nlohmann::json>& examples() {
  static const std::vector<nlohmann::json> docs = [] {
    std::vector<nlohmann::json> d;
    for (const char* name : {"hertz-sphere", "cattaneo-sphere", "carter-2d", "rolling-sphere", "torsion-sphere",
                             "paper-cylinder", "paper-cylinder-si", "flat-punch"})
      d.push_back(dc::parse_case_text(dc::fuzz::example_text(name), name));
    return d;
  }();
  return docs;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  if (size == 0) return 0;
  nlohmann::json doc = examples()[data[0] % examples().size()];
  const std::string text(reinterpret_cast<const char*>(data) + 1, size - 1);
  dc::fuzz::expect_input_errors_only([&] {
    std::size_t start = 0;
    while (start <= text.size()) {
      const std::size_t end = std::min(text.find('\n', start), text.size());
      dc::apply_override(doc, text.substr(start, end - start));
      start = end + 1;
    }
    (void)dc::sweep_points(dc::build_case(doc, DYNCONTACT_SOURCE_DIR "/examples"));
  });
  return 0;
}
