#pragma once
// Plots of static results with gnuplot: pressure (and traction) along the centre lines with
// the closed-form curve where one applies, the tractions between -f(p) and f(p) along the
// centre lines (tangential problems: fields.bound given), the pressure map and the contact
// (stick/slip) map. Writes plots.gp + *.dat into the output folder, then runs gnuplot there to produce
// SVG and PNG (pngcairo when available). Without gnuplot: one warning, no plots, no failure.
#include <string>
#include <vector>

#include "case_model.hpp"
#include "gnuplot_figures.hpp"
#include "static_fields.hpp"

namespace dc::output {

/// The figures of `fields` (their data files written into `dir`), not yet drawn.
std::vector<GnuplotFigure> static_plot_figures(const std::string& dir, const Case& c, const StaticFields& fields);

/// Draws static_plot_figures and `more` (e.g. the subsurface planes, subsurface_plots.hpp) in one
/// plots.gp. Returns the image files produced (empty when gnuplot is missing); throws OutputError
/// when one fails (gnuplot_figures.hpp).
std::vector<std::string> write_static_plots(const std::string& dir, const Case& c, const StaticFields& fields,
                                            const std::vector<GnuplotFigure>& more = {});

}  // namespace dc::output
