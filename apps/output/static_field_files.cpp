#include "static_field_files.hpp"

#include <filesystem>

#include "fields_vti.hpp"
#include "fields_writer.hpp"
#include "wear_writer.hpp"

namespace dc::output {

void write_static_field_files(const std::string& dir, const Grid& grid, const StaticFieldFiles& what,
                              nlohmann::json& files, nlohmann::json& summary) {
  static const std::vector<double> none;
  const std::vector<double>& base = what.worn_base ? *what.worn_base : none;
  const std::vector<double>& body = what.worn_body ? *what.worn_body : none;
  const std::vector<NamedMap> worn = {{"wear_base", &base}, {"wear_body", &body}};
  const std::vector<StaticFields>& steps = *what.steps;
  if (what.fields && what.history) {  // one file per step; fields.csv is the last
    nlohmann::json per_step = nlohmann::json::array();
    std::vector<PvdEntry> images;
    for (std::size_t k = 0; k < steps.size(); ++k) {
      const std::string name = "fields_" + std::to_string(k) + ".csv";
      write_fields(dir, grid, steps[k], name, what.power_column);
      images.push_back({static_cast<double>(k), write_fields_vti(dir, grid, steps[k], "fields_" + std::to_string(k) + ".vti")});
      per_step.push_back(name);
      summary["steps"][k]["fields"] = name;
    }
    write_pvd((std::filesystem::path(dir) / "fields.pvd").string(), images);  // once, after its files
    files["fields_steps"] = per_step;
    files["fields_series"] = "fields.pvd";
  }
  if (what.fields) {
    write_fields(dir, grid, steps.back(), "fields.csv", what.power_column);
    files["fields"] = "fields.csv";
    files["fields_vti"] = write_fields_vti(dir, grid, steps.back(), "fields.vti", worn);
  }
  if (!base.empty() || !body.empty()) {  // the worn depth of each body (wear_writer.hpp)
    write_wear(dir, grid, base, body);
    files["wear"] = "wear.csv";
    if (what.wear_series) write_wear_series(dir, grid, *what.wear_series, {!base.empty(), !body.empty()}, files);
  }
}

}  // namespace dc::output
