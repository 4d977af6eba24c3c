// libFuzzer target: arbitrary bytes as a case file, read and validated as `dyncontact validate`
// does (parse_case_text, build_case, the sweep's cases). Seeded with examples/*.json.
#include <cstddef>
#include <cstdint>
#include <string>

#include "case_model.hpp"
#include "fuzz_support.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string text(reinterpret_cast<const char*>(data), size);
  dc::fuzz::expect_input_errors_only([&] {
    const nlohmann::json doc = dc::parse_case_text(text, "case.json");
    const dc::Case c = dc::build_case(doc, DYNCONTACT_SOURCE_DIR "/examples");
    (void)dc::sweep_points(c);
  });
  return 0;
}
