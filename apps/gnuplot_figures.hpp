#pragma once
// Figures drawn by gnuplot: each figure is a gnuplot block (after `reset`) written once per
// terminal (SVG, then PNG with pngcairo when available) into dir/plots.gp, which is then run
// in `dir`. Without gnuplot: one warning per process, no images, no failure.
#include <string>
#include <vector>

namespace dc::cli {

struct GnuplotFigure {
  std::string stem;  ///< image file name without extension
  std::string body;  ///< gnuplot commands (title, axes, plot ...)
};

/// Writes plots.gp for `figures` and runs gnuplot in `dir`; returns the images produced.
std::vector<std::string> render_gnuplot(const std::string& dir, const std::string& case_name,
                                        const std::vector<GnuplotFigure>& figures);

}  // namespace dc::cli
