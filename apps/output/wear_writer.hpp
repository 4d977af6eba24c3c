#pragma once
// wear.csv (CASES.md "wear"): x,y then the worn depth of each body that wears (columns `base`,
// `body`, m), one row per element in grid order i + nx*j (element centres; 2-D: y = 0).
// Written whole or not at all (output_files.hpp).
#include <string>
#include <vector>

#include "gnuplot_figures.hpp"
#include "grid.hpp"

namespace dc::output {

/// Writes dir/`file` (default wear.csv); an empty depth map leaves its body's column out; the
/// first column is named `x_name` (a dynamic run's body map: its arc length "s"). Returns the path.
std::string write_wear(const std::string& dir, const Grid& grid, const std::vector<double>& base,
                       const std::vector<double>& body, const std::string& file = "wear.csv",
                       const std::string& x_name = "x");

/// The row the wear is drawn along: the one through the worn depth's centroid across the grid
/// (base and body summed; a scar symmetric about y = 0, the row nearest y = 0, as without wear;
/// a track worn off y = 0, the track's), 0 in 2-D.
int wear_row(const Grid& grid, const std::vector<double>& base, const std::vector<double>& body);

/// The figure `name` (default wear_x): each wearing body's worn depth (um) along x on wear_row,
/// its data written to dir/<name>.dat; `x_label` the abscissa
/// (mm); not yet drawn (render_gnuplot).
GnuplotFigure wear_figure(const std::string& dir, const std::string& case_name, const Grid& grid,
                          const std::vector<double>& base, const std::vector<double>& body,
                          const std::string& name = "wear_x", const std::string& x_label = "x");

}  // namespace dc::output
