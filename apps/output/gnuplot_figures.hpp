#pragma once
// Figures drawn by gnuplot: each figure is a gnuplot block (after `reset`) written once per
// terminal (SVG, then PNG with pngcairo when available) into dir/plots.gp, which is then run
// in `dir`. Without gnuplot: one warning per process, no images, no failure. Each image is drawn
// to a temporary name, checked (gnuplot's exit status; not empty; an SVG ends with </svg>, a
// PNG with its IEND chunk) and only then renamed into place (output_files.hpp).
#include <string>
#include <vector>

namespace dc::output {

struct GnuplotFigure {
  std::string stem;  ///< image file name without extension
  std::string body;  ///< gnuplot commands (title, axes, plot ...)
};

/// A number for a gnuplot data file: %.<digits>g, "?" (the scripts' missing value) when not finite.
std::string gnuplot_number(double v, int digits = 9);

/// Writes plots.gp for `figures` and runs gnuplot in `dir`; returns the images produced (none
/// without gnuplot). Throws OutputError naming the image when one fails.
std::vector<std::string> render_gnuplot(const std::string& dir, const std::string& case_name,
                                        const std::vector<GnuplotFigure>& figures);

}  // namespace dc::output
