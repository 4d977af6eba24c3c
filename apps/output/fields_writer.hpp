#pragma once
// fields.csv of static problems: x,y,p,tx,ty,sx,sy,state (one row per element, grid order
// i + nx*j; element centres; 2-D: y = 0). state 0 free, 1 stick, 2 slip; a normal problem
// writes 1 for every element in contact (p above the contact threshold). `work_column` (output.power)
// with friction: a last column `power` (W/m^2, -tau . ds / dt: rolling and dynamic steps) or
// `dissipation` (J/m^2, -tau . ds of a quasi-static step); then, when the flash temperature was
// computed (StaticFields::temperature_base), `temperature`: the hotter surface's rise (K).
#include <string>

#include "grid.hpp"
#include "static_fields.hpp"

namespace dc::output {

/// Writes dir/`file` (fields.csv; fields_<k>.csv for the steps of a history); returns the path.
std::string write_fields(const std::string& dir, const Grid& grid, const StaticFields& fields,
                         const std::string& file = "fields.csv",
                         bool work_column = false);

}  // namespace dc::output
