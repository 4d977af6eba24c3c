#pragma once
// The files of a creep-force table (CASES.md): table.csv (one row per point, in input order),
// table.json (the case, the ranges, the failed points) and the plots Fx(creepage_x),
// Fy(creepage_y) over the friction capacity.
#include <string>
#include <vector>

#include "case_model.hpp"
#include "table_points.hpp"

namespace dc::table {

/// table.csv content: creepage_x, creepage_y, spin, Fx, Fy, Mz, Fx_mu_P, Fy_mu_P, n_stick,
/// certificate, status (failed points: nan for the numbers).
std::string table_csv(const std::vector<TableRow>& rows);

/// table.json content: {"case", "ranges", "columns", "points", "failed": [{row, creepage_x,
/// creepage_y, spin, status, message}]} (rows counted from 0 in table.csv's order).
nlohmann::json table_json(const Case& c, const TableAxes& axes, const std::vector<TableRow>& rows);

/// The plots (output/gnuplot_figures.hpp) Fx/(mu P) against creepage_x and Fy/(mu P) against
/// creepage_y, one curve per line of the table (at most 8, evenly chosen); returns the images.
std::vector<std::string> table_plots(const std::string& dir, const Case& c, const TableAxes& axes,
                                     const std::vector<TableRow>& rows);

}  // namespace dc::table
