#pragma once
// timeseries.csv of a "dynamic" run (a header line, one row per accepted step) and its figures,
// one per plotted quantity. The run that fills it: runs/dynamic_run.hpp (simulate_dynamic).
#include <ostream>
#include <string>
#include <utility>
#include <vector>

#include "case_model.hpp"
#include "dynamic_simulation.hpp"
#include "gnuplot_figures.hpp"

namespace dc::output {

/// timeseries.csv's header line.
inline constexpr const char* kTimeseriesColumns =
    "t,x,y,z,vx,vy,vz,wx,wy,wz,Fx,Fy,Fz,Mx,My,Mz,creepage,stick_fraction,approach,contact_area,n_contact,"
    "n_stick,n_slip,kinetic_energy,certificate,newton_iterations,contact_solves,alternations\n";

/// Appends the row of an accepted step to timeseries.csv's text.
void append_timeseries_row(std::ostream& out, const dynamics::DynamicSample& s);

/// A plotted quantity of timeseries.csv: its figure's file stem, axis label and columns
/// (1-based column number, legend).
struct DynamicPlotSeries {
  const char* stem;
  const char* ylabel;
  std::vector<std::pair<int, const char*>> columns;
};
/// The figures a dynamic run draws, one per quantity (the contact area's label by dimension).
std::vector<DynamicPlotSeries> dynamic_plot_series(int dimension);

/// One figure per plotted quantity, every run's curves in it (`runs`: time series file and
/// label; one run without a label for a single run).
std::vector<GnuplotFigure> timeseries_figures(const Case& c, const std::vector<std::pair<std::string, std::string>>& runs);

}  // namespace dc::output
