#pragma once
// Shared by the libFuzzer targets: an input may be rejected only by dc::InputError (exit 2 of
// the command line); any other exception would be an "internal" exit 4, a defect, so it aborts
// and libFuzzer keeps the input. Crashes, hangs and leaks are found by the sanitizers.
#include <cstdio>
#include <cstdlib>
#include <exception>
#include <string>

#include "errors.hpp"

namespace dc::fuzz {

template <class F>
void expect_input_errors_only(F&& run) {
  try {
    run();
  } catch (const dc::InputError&) {
  } catch (const std::exception& e) {
    std::fprintf(stderr, "fuzz: an input that is not an input error: %s\n", e.what());
    std::abort();
  }
}

/// The text of a bundled example (examples/NAME.json), read once.
std::string example_text(const std::string& name);

}  // namespace dc::fuzz
