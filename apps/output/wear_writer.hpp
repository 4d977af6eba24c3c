#pragma once
// wear.csv (CASES.md "wear"): x,y then the worn depth of each body that wears (columns `base`,
// `body`, m), one row per element in grid order i + nx*j (element centres; 2-D: y = 0).
// Written whole or not at all (output_files.hpp).
#include <string>
#include <vector>

#include "gnuplot_figures.hpp"
#include "grid.hpp"

namespace dc::output {

/// Writes dir/wear.csv; an empty depth map leaves its body's column out. Returns the path.
std::string write_wear(const std::string& dir, const Grid& grid, const std::vector<double>& base,
                       const std::vector<double>& body);

/// The figure `wear_x`: each wearing body's worn depth (um) along the x centre line (the row
/// nearest y = 0), its data written to dir/wear_x.dat; not yet drawn (render_gnuplot).
GnuplotFigure wear_figure(const std::string& dir, const std::string& case_name, const Grid& grid,
                          const std::vector<double>& base, const std::vector<double>& body);

}  // namespace dc::output
