#pragma once
// Plots of static results with gnuplot: pressure (and traction) along the centre lines with
// the closed-form curve where one applies, the tractions between -f(p) and f(p) along the
// centre lines (tangential problems: fields.bound given), the pressure map and the contact
// (stick/slip) map. Writes plots.gp + *.dat into the output folder, then runs gnuplot there to produce
// SVG and PNG (pngcairo when available). Without gnuplot: one warning, no plots, no failure.
#include <string>
#include <vector>

#include "case_model.hpp"
#include "static_fields.hpp"

namespace dc::output {

/// Returns the image files produced (empty when gnuplot is missing); throws OutputError when
/// one fails (gnuplot_figures.hpp).
std::vector<std::string> write_static_plots(const std::string& dir, const Case& c, const StaticFields& fields);

}  // namespace dc::output
