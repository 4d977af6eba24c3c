#pragma once
// The surface files of a static run (CASES.md "Files"), written alike by `dyncontact solve` and
// Python's solve(out=...): fields.csv and fields.vti of the final state; a history's steps also
// fields_<k>.csv and fields_<k>.vti in the series fields.pvd (each step's summary entry names its
// csv); a wear run's wear.csv, its worn depths also in the images (wear_base, wear_body), and
// the worn depth's evolution over the profile updates (wear_series_writer.hpp).
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "grid.hpp"
#include "static_fields.hpp"
#include "wear_series_writer.hpp"

namespace dc::output {

struct StaticFieldFiles {
  const std::vector<StaticFields>* steps = nullptr;  ///< the states solved; the last is the result
  bool fields = true;                               ///< output.fields: false writes only wear.csv
  bool history = false;                             ///< write every step, not only the last
  bool power_column = false;                        ///< fields.csv's work column (output.power)
  const std::vector<double>* worn_base = nullptr;   ///< each body's worn depth (m); null or empty: none
  const std::vector<double>* worn_body = nullptr;
  const std::vector<WornState>* wear_series = nullptr;  ///< the worn depth after the updates; null: none
};

/// Writes them into `dir`; adds their names to `files` (fields, fields_steps, fields_vti,
/// fields_series, wear, wear_series, wear_profiles) and each step's csv to summary["steps"][k]["fields"].
void write_static_field_files(const std::string& dir, const Grid& grid, const StaticFieldFiles& what,
                              nlohmann::json& files, nlohmann::json& summary);

}  // namespace dc::output
