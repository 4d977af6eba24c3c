#pragma once
// The points of a creep-force table: creepages and spin over a grid of values, solved as steady
// rolling, one line (all creepage_x values at one creepage_y and spin) at a time: the first
// point of a line starts from zero traction, each next one from its neighbour's traction
// (warm start). A line is the unit of work spread over threads and ranks (table_ranks.hpp), so
// a point's result never depends on where or in which order the lines ran.
#include <cstddef>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "case_model.hpp"

namespace dc::table {

/// The table's values: rows run over spin, then creepage_y, then creepage_x (fastest).
struct TableAxes {
  std::vector<double> creepage_x, creepage_y, spin;
  std::size_t size() const { return creepage_x.size() * creepage_y.size() * spin.size(); }
  std::size_t lines() const { return creepage_y.size() * spin.size(); }
};

/// One solved point: forces on the body (N; 2-D per unit length), Mz (N m), the forces over the
/// friction capacity sum f(p) A (= mu P for Coulomb friction), the stick elements and the
/// worst certificate residual. status: converged, not_converged, failed (numbers then NaN).
struct TableRow {
  double creepage_x = 0.0, creepage_y = 0.0, spin = 0.0;
  double Fx = 0.0, Fy = 0.0, Mz = 0.0, Fx_mu_P = 0.0, Fy_mu_P = 0.0, certificate = 0.0;
  int n_stick = 0;
  std::string status = "failed";
  std::string message;  ///< why a point failed or did not converge
};

/// Checks that `c` is a steady rolling case (tangential, regime rolling, no history) and that the
/// axes suit its dimension (2-D: creepage_y and spin only 0). Throws InputError naming the key or
/// the option (--lateral, --spin).
void check_table_case(const Case& c, const TableAxes& axes);

/// Solves line `line` (a fresh problem: the result depends on the line alone) and returns its
/// rows as JSON (the transport between ranks; see rows_from_line()).
nlohmann::json solve_table_line(const Case& c, const TableAxes& axes, std::size_t line);

/// The rows of line `line` from solve_table_line()'s result, or all failed with the message of
/// a result {"error": message}.
std::vector<TableRow> rows_from_line(const TableAxes& axes, std::size_t line, const nlohmann::json& result);

}  // namespace dc::table
