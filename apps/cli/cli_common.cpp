// Loading a case for the subcommands (file, name, overrides, backend, validation), the output
// folder held to the end, input errors under mpirun.
#include "cli_common.hpp"

#include <filesystem>
#include <memory>
#include <string>
#include <vector>

#include "errors.hpp"
#include "output_folder.hpp"
#include "table_ranks.hpp"

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
  output::OutputFolder folder = output::open_output_folder(c, cli_out);
  static std::vector<std::unique_ptr<output::OutputFolderLock>> held;  // released when the process ends
  held.push_back(std::move(folder.lock));
  return folder.dir;
}

void not_implemented(ProblemKind kind) {
  throw InputError("problem", std::string("'") + to_string(kind) + "' is not implemented yet");
}

int report_input_errors_on_root(const std::function<int()>& command) {
  const bool root = table::launch_rank().root();
  try {
    return command();
  } catch (const InputError&) {
    if (root) throw;
    return runs::kExitBadInput;
  }
}

}  // namespace dc::cli
