#pragma once
// Plots of the subsurface field (CASES.md "subsurface"): per body, the von Mises stress, Tresca's
// maximum shear tau_1 = (sigma_1 - sigma_3)/2 and the orthogonal shear sigma_xz as maps over the
// x-z plane through the body's largest von Mises stress (3-D also the y-z plane), depth downwards,
// stresses in MPa and lengths in mm. Drawn with the static plots (plot_writer.hpp) in one plots.gp.
#include <string>
#include <vector>

#include "gnuplot_figures.hpp"
#include "subsurface_writer.hpp"

namespace dc::output {

/// Writes subsurface_<body>_<plane>.dat into `dir` and returns the figures
/// subsurface_<body>_xz (3-D also _yz), three panels each.
std::vector<GnuplotFigure> subsurface_plane_figures(const std::string& dir, const std::string& case_name,
                                                    const std::vector<SubsurfaceBody>& bodies);

}  // namespace dc::output
