#include "subsurface_plots.hpp"

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <sstream>

#include "output_files.hpp"

namespace dc::output {
namespace {

/// Plane maps are drawn from at most this many points along the surface.
constexpr int kPlaneCells = 256;

std::string plane_number(double v) { return gnuplot_number(v, 7); }

/// The data of one plane: `along depth von_mises tresca sxz`, one block per depth (gnuplot's
/// grid data for `with image`), the element `index(m)` of the m-th point along the plane.
template <class Index>
std::string plane_data(const SubsurfaceBody& b, int points, const std::vector<double>& coordinate, Index index) {
  const SubsurfaceResult& f = *b.field;
  const std::size_t n = f.grid.size();
  const int step = (points + kPlaneCells - 1) / kPlaneCells;
  std::ostringstream out;
  out << "# along depth von_mises tresca sxz (Pa, m)\n";
  for (std::size_t k = 0; k < f.depths.size(); ++k) {
    for (int m = std::min(step / 2, points - 1); m < points; m += step) {
      const std::size_t e = index(m);
      out << plane_number(coordinate[static_cast<std::size_t>(m)]) << ' ' << plane_number(f.depths[k]) << ' '
          << plane_number(b.measures->von_mises[k * n + e]) << ' ' << plane_number(b.measures->tresca[k * n + e]) << ' '
          << plane_number(f.component(k, kSxz)[e]) << '\n';
    }
    out << '\n';
  }
  return out.str();
}

/// Three stacked maps of `data`: von Mises, Tresca, sigma_xz (a diverging palette: it changes sign).
std::string plane_figure(const std::string& title, const std::string& data, const char* axis, double at) {
  std::ostringstream b;
  char where[64];
  std::snprintf(where, sizeof where, "%.4g", std::abs(at) < 1e-15 ? 0.0 : at * 1e3);
  b << "set multiplot layout 3,1 title \"" << title << " (" << (axis[0] == 'x' ? "y" : "x") << " = " << where
    << " mm)\" noenhanced\n"
    << "set xlabel \"" << axis << " (mm)\"\nset ylabel \"depth (mm)\"\nset autoscale fix\nset yrange [*:*] reverse\n"
    << "set xtics out\nset ytics out\nset cblabel \"MPa\"\n";
  const char* panels[3][3] = {{"3", "von Mises", "0 \"white\", 0.25 \"#fde725\", 0.6 \"#21918c\", 1 \"#440154\""},
                              {"4", "Tresca tau_1", "0 \"white\", 0.25 \"#fde725\", 0.6 \"#21918c\", 1 \"#440154\""},
                              {"5", "orthogonal shear sigma_xz", "-1 \"#2166ac\", 0 \"white\", 1 \"#b2182b\""}};
  for (const auto& p : panels) {
    b << "set title \"" << p[1] << "\" noenhanced\nset palette defined (" << p[2] << ")\n";
    if (p[0][0] == '5')  // symmetric about 0
      b << "stats \"" << data << "\" using 5 nooutput\n"
        << "sxz_range = (STATS_max > -STATS_min ? STATS_max : -STATS_min) * 1e-6\n"
        << "sxz_range = (sxz_range > 0 ? sxz_range : 1)\nset cbrange [-sxz_range:sxz_range]\n";
    else
      b << "set cbrange [0:*]\n";
    b << "plot \"" << data << "\" using ($1*1e3):($2*1e3):($" << p[0] << "*1e-6) with image notitle\n";
  }
  b << "unset multiplot\n";
  return b.str();
}

}  // namespace

std::vector<GnuplotFigure> subsurface_plane_figures(const std::string& dir, const std::string& case_name,
                                                    const std::vector<SubsurfaceBody>& bodies) {
  std::vector<GnuplotFigure> figures;
  for (const SubsurfaceBody& b : bodies) {
    const Grid& g = b.field->grid;
    const FieldExtreme& worst = b.measures->max_von_mises;
    std::vector<double> xs, ys;
    for (int i = 0; i < g.nx; ++i) xs.push_back(g.xc(i));
    for (int j = 0; j < g.ny; ++j) ys.push_back(g.yc(j));
    const std::string title = case_name + ": " + b.name + " below its surface";
    const std::string xz = "subsurface_" + b.name + "_xz.dat";
    write_file_whole((std::filesystem::path(dir) / xz).string(),
                     plane_data(b, g.nx, xs, [&](int i) { return g.index(i, worst.j); }));
    figures.push_back({"subsurface_" + b.name + "_xz", plane_figure(title, xz, "x", g.yc(worst.j))});
    if (g.dimension != 3) continue;
    const std::string yz = "subsurface_" + b.name + "_yz.dat";
    write_file_whole((std::filesystem::path(dir) / yz).string(),
                     plane_data(b, g.ny, ys, [&](int j) { return g.index(worst.i, j); }));
    figures.push_back({"subsurface_" + b.name + "_yz", plane_figure(title, yz, "y", g.xc(worst.i))});
  }
  return figures;
}

}  // namespace dc::output
