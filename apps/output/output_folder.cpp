// The output folder of a run: created, locked and cleared of an earlier run's result files.
#include "output_folder.hpp"

#include <algorithm>
#include <cerrno>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <set>
#include <string>
#include <system_error>
#include <vector>

#include "errors.hpp"
#include "output_files.hpp"

namespace dc::output {
namespace {

bool numbered(const std::string& name, const std::string& stem, const std::string& ext) {
  if (name.size() <= stem.size() + ext.size() || name.rfind(stem, 0) != 0 ||
      name.compare(name.size() - ext.size(), ext.size(), ext) != 0)
    return false;
  const std::string digits = name.substr(stem.size(), name.size() - stem.size() - ext.size());
  return std::all_of(digits.begin(), digits.end(), [](char ch) { return ch >= '0' && ch <= '9'; });
}

}  // namespace

bool is_result_file(const std::string& name) {
  static const std::set<std::string> fixed = {
      "summary.json", "compare.json", "fields.csv", "timeseries.csv", "plots.gp", "plots.log",
      "line_x.dat", "line_y.dat", "map.dat", "reference_x.dat", "reference_y.dat",
      "table.csv", "table.json", "table_Fx.dat", "table_Fy.dat", "body.vtu", "body.pvd",
      "subsurface.vti", "subsurface_base_xz.csv", "subsurface_base_yz.csv", "subsurface_body_xz.csv",
      "subsurface_body_yz.csv", "subsurface_base_xz.dat", "subsurface_base_yz.dat", "subsurface_body_xz.dat",
      "subsurface_body_yz.dat", "subsurface.pvd", "fields.vti", "fields.pvd", "energy.csv", "wear.csv",
      "wear_x.dat", "temperature_x.dat", "wear_body.csv", "wear_s.dat", "wear.pvd", "wear_profiles.csv",
      "wear_evolution.dat"};
  static const char* figures[] = {"pressure_x", "pressure_y", "traction_x", "traction_y", "pressure_map",
                                  "contact_map", "subsurface_base_xz", "subsurface_base_yz", "subsurface_body_xz",
                                  "subsurface_body_yz", "F_bar", "l_bar", "v_bar",
                                  // dynamic
                                  "position", "velocity", "omega", "force", "moment", "creepage", "stick",
                                  "approach", "contact_area", "energy", "table_Fx", "table_Fy",
                                  // heat and wear
                                  "temperature_x", "wear_x", "wear_s", "wear_evolution"};
  if (fixed.count(name)) return true;
  for (const char* f : figures)
    for (const char* ext : {".svg", ".png"})
      if (name == std::string(f) + ext) return true;
  return numbered(name, "fields_", ".csv") || numbered(name, "timeseries_", ".csv") || numbered(name, "body_", ".vtu") ||
         numbered(name, "subsurface_", ".vti") || numbered(name, "fields_", ".vti") ||
         numbered(name, "energy_", ".csv") || numbered(name, "wear_", ".vti");
}

OutputFolder open_output_folder(const Case& c, const std::string& cli_out, const std::string& out_key) {
  namespace fs = std::filesystem;
  OutputFolder folder;
  std::string& dir = folder.dir;
  dir = cli_out;
  if (dir.empty()) dir = c.output.dir;
  if (dir.empty()) dir = (fs::path("out") / c.name).string();
  const std::string key = cli_out.empty() ? (c.output.dir.empty() ? "name" : "output.dir") : out_key;
  std::error_code ec;
  fs::create_directories(dir, ec);
  if (ec || !fs::is_directory(dir))
    throw InputError(key, "cannot create the output folder '" + dir + "'" + (ec ? ": " + ec.message() : ""));
  // One run at a time: locked before anything in the folder is removed or solved.
  folder.lock = std::make_unique<OutputFolderLock>(dir, key);
  // Writable? Found now, not after the solve.
  const fs::path probe = fs::path(dir) / ".dyncontact-write-test";
  {
    std::ofstream out(probe, std::ios::binary | std::ios::trunc);
    if (!out) {
      const int err = errno;
      throw InputError(key, "cannot write into the output folder '" + dir + "': " + std::strerror(err));
    }
  }
  fs::remove(probe, ec);
  // The run owns its folder's result files: those of an earlier run go (only our own names), and
  // so do the temporaries of a run killed while writing (no run can be writing them now: the
  // folder is locked).
  std::vector<fs::path> stale;
  for (const auto& entry : fs::directory_iterator(dir, ec)) {
    std::error_code e2;
    const std::string name = entry.path().filename().string();
    if (entry.is_regular_file(e2) && (is_result_file(name) || name.rfind(kPartialPrefix, 0) == 0))
      stale.push_back(entry.path());
  }
  for (const fs::path& file : stale) {
    fs::remove(file, ec);
    if (ec) throw InputError(key, "cannot remove the earlier result '" + file.string() + "': " + ec.message());
  }
  return folder;
}

}  // namespace dc::output
