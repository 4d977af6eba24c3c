#include <string>

#include <CLI/CLI.hpp>

#include "commands.hpp"

namespace dc::cli {

const CLI::Validator& non_empty_folder() {
  static const CLI::Validator v(
      [](const std::string& s) { return s.empty() ? std::string("an empty folder name (omit --out for out/<name>)") : std::string(); },
      "FOLDER");
  return v;
}

}  // namespace dc::cli
