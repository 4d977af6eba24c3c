#pragma once
// The worn profile's evolution over a wear run's profile updates (docs/wear_energy.md "Outputs
// of a wear run"): the worn depth after each kept update as ParaView images wear_<k>.vti in the
// series wear.pvd (time value: the cycles done; point arrays wear_base / wear_body, m), the
// depth along x on the row through the last state's wear (wear_row, as the figure wear_x) after each in
// wear_profiles.csv (`cycles,x,base,body`), and the figure wear_evolution drawing up to eight of
// those profiles. Files written whole (output_files.hpp).
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "gnuplot_figures.hpp"
#include "grid.hpp"

namespace dc::output {

/// The worn depth of one body (m per element of the grid) after `cycles` cycles.
struct WornState {
  long long cycles = 0;
  std::vector<double> depth;
};

/// Which bodies wear (each takes the state's depth).
struct WornBodies {
  bool base = false, body = false;
};

/// Writes the images, wear.pvd and wear_profiles.csv into `dir` and names them in `files`
/// (wear_series, wear_profiles); nothing for an empty series.
void write_wear_series(const std::string& dir, const Grid& grid, const std::vector<WornState>& series,
                       WornBodies bodies, nlohmann::json& files);

/// The figure wear_evolution (data wear_evolution.dat): the worn depth along the x centre line
/// after up to eight of the states, evenly spread over the series and ending with the last.
GnuplotFigure wear_evolution_figure(const std::string& dir, const std::string& case_name, const Grid& grid,
                                    const std::vector<WornState>& series);

}  // namespace dc::output
