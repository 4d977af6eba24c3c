// Loading a case for the subcommands: file, name, overrides, backend, validation.
#include <filesystem>
#include <fstream>
#include <string>
#include <system_error>
#include <vector>

#include <CLI/CLI.hpp>

#include "cli_common.hpp"
#include "errors.hpp"

namespace dc::cli {

Case load_case(const std::string& path, const std::vector<std::string>& overrides, const std::string& backend) {
  nlohmann::json doc = read_case_file(path);
  if (doc.is_object() && !doc.contains("name")) {
    const std::string stem = std::filesystem::path(path).stem().string();
    doc["name"] = stem.empty() ? std::string("case") : stem;
  }
  for (const auto& assignment : overrides) apply_override(doc, assignment);
  if (!backend.empty()) {
    if (!doc.is_object()) throw InputError("case", "expected an object at the top level");
    if (!doc.contains("solver") || doc["solver"].is_null()) doc["solver"] = nlohmann::json::object();
    if (!doc["solver"].is_object()) throw InputError("solver", "expected an object");
    doc["solver"]["backend"] = backend;
  }
  // Relative table paths were resolved against the case file's folder by read_case_file;
  // paths given with --set are relative to the working directory.
  return build_case(doc, ".");
}

std::string prepare_output_dir(const Case& c, const std::string& cli_out) {
  std::string dir = cli_out;
  if (dir.empty()) dir = c.output.dir;
  if (dir.empty()) dir = (std::filesystem::path("out") / c.name).string();
  std::error_code ec;
  std::filesystem::create_directories(dir, ec);
  if (ec || !std::filesystem::is_directory(dir))
    throw InputError(cli_out.empty() ? (c.output.dir.empty() ? "name" : "output.dir") : "--out",
                     "cannot create the output folder '" + dir + "'" + (ec ? ": " + ec.message() : ""));
  return dir;
}

void write_text_file(const std::string& path, const std::string& text) {
  std::ofstream out(path, std::ios::binary | std::ios::trunc);
  if (!out) throw InputError(path, "cannot write");
  out << text;
  out.close();
  if (!out) throw InputError(path, "write failed");
}

const CLI::Validator& non_empty_folder() {
  static const CLI::Validator v(
      [](const std::string& s) { return s.empty() ? std::string("an empty folder name (omit --out for out/<name>)") : std::string(); },
      "FOLDER");
  return v;
}

void not_implemented(ProblemKind kind) {
  throw InputError("problem", std::string("'") + to_string(kind) + "' is not implemented yet");
}

}  // namespace dc::cli
