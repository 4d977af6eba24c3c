#include "plot_writer.hpp"


#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <iostream>
#include <sstream>
#include <string>

#include "analytic_reference.hpp"
#include "gnuplot_figures.hpp"
#include "output_files.hpp"

namespace dc::output {
namespace {

/// Map images are drawn from at most this many cells per axis.
constexpr int kMapCells = 256;

std::string num(double v) { return gnuplot_number(v); }

double field(const std::vector<double>& v, std::size_t e) { return e < v.size() ? v[e] : 0.0; }

bool any_nonzero(const std::vector<double>& v) {
  return std::any_of(v.begin(), v.end(), [](double x) { return x != 0.0; });
}

}  // namespace

std::vector<GnuplotFigure> static_plot_figures(const std::string& dir, const Case& c, const StaticFields& f) {
  namespace fs = std::filesystem;
  const Grid& g = c.grid;
  const auto ref = analytic_reference(c);
  const std::string ref_label = !ref ? "" : (ref->kind == "boussinesq_flat_punch" ? "Boussinesq" : "Hertz");
  // With a friction bound (tangential problems) the tractions get their own figures, with +-f(p);
  // otherwise nonzero tractions are drawn with the pressure.
  const bool friction = !f.bound.empty();
  const bool traction = !friction && (any_nonzero(f.tx) || any_nonzero(f.ty));
  auto path = [&](const char* name) { return (fs::path(dir) / name).string(); };

  // Centre lines: the row nearest y = 0 and the column nearest x = 0.
  auto nearest = [](double origin, double step, int n, double at) {
    return std::clamp(static_cast<int>(std::floor((at - origin) / step)), 0, n - 1);
  };
  const int j0 = g.dimension == 2 ? 0 : nearest(g.y0, g.dy, g.ny, 0.0);
  const int i0 = nearest(g.x0, g.dx, g.nx, 0.0);
  {
    std::ostringstream s;
    s << "# x p tx ty f  (row j = " << j0 << ", y = " << num(g.yc(j0)) << ")\n";
    for (int i = 0; i < g.nx; ++i) {
      const std::size_t e = g.index(i, j0);
      s << num(g.xc(i)) << ' ' << num(field(f.p, e)) << ' ' << num(field(f.tx, e)) << ' ' << num(field(f.ty, e))
        << ' ' << num(field(f.bound, e)) << '\n';
    }
    write_file_whole(path("line_x.dat"), s.str());
  }
  if (g.dimension == 3) {
    std::ostringstream s;
    s << "# y p tx ty f  (column i = " << i0 << ", x = " << num(g.xc(i0)) << ")\n";
    for (int j = 0; j < g.ny; ++j) {
      const std::size_t e = g.index(i0, j);
      s << num(g.yc(j)) << ' ' << num(field(f.p, e)) << ' ' << num(field(f.tx, e)) << ' ' << num(field(f.ty, e))
        << ' ' << num(field(f.bound, e)) << '\n';
    }
    write_file_whole(path("line_y.dat"), s.str());
    // The maps are images of at most kMapCells x kMapCells: on finer grids every k-th element
    // (the middle of each k x k block) - a 900 x 650 figure shows no more, and gnuplot spent
    // seconds reading 512^2 rows; fields.csv holds every element.
    const int kx = (g.nx + kMapCells - 1) / kMapCells, ky = (g.ny + kMapCells - 1) / kMapCells;
    std::ostringstream m;
    m << "# x y p state";
    if (kx > 1 || ky > 1) m << "  (every " << kx << " x " << ky << " elements: the map is drawn from at most " << kMapCells << " per axis)";
    m << "\n";
    for (int j = std::min(ky / 2, g.ny - 1); j < g.ny; j += ky) {
      for (int i = std::min(kx / 2, g.nx - 1); i < g.nx; i += kx) {
        const std::size_t e = g.index(i, j);
        m << num(g.xc(i)) << ' ' << num(g.yc(j)) << ' ' << num(field(f.p, e)) << ' '
          << (e < f.state.size() ? f.state[e] : 0) << '\n';
      }
      m << '\n';
    }
    write_file_whole(path("map.dat"), m.str());
  }
  if (ref) {  // the closed form, finely sampled along both centre lines
    const int n = 801;
    std::ostringstream sx, sy;
    const double yl = g.dimension == 2 ? 0.0 : g.yc(j0), xl = g.xc(i0);
    const double cut = ref->kind == "boussinesq_flat_punch" ? 0.995 : 2.0;  // the punch's rim is singular
    for (int k = 0; k < n; ++k) {
      const double x = g.x0 + (g.x_max() - g.x0) * k / (n - 1);
      const bool in = std::hypot(x, yl) < cut * ref->semi_axis_x;
      sx << num(x) << ' ' << (in ? num(ref->pressure(x, yl)) : std::string("?")) << '\n';
      if (g.dimension == 3) {
        const double y = g.y0 + (g.y_max() - g.y0) * k / (n - 1);
        const bool in_y = std::hypot(xl, y) < cut * ref->semi_axis_y;
        sy << num(y) << ' ' << (in_y ? num(ref->pressure(xl, y)) : std::string("?")) << '\n';
      }
    }
    write_file_whole(path("reference_x.dat"), sx.str());
    if (g.dimension == 3) write_file_whole(path("reference_y.dat"), sy.str());
  }

  // Lengths in mm, stresses in MPa. Each figure is a block emitted once per terminal
  // (SVG, then PNG), each starting from `reset`.
  using Figure = GnuplotFigure;
  std::vector<Figure> figures;
  auto short_num = [](double v) {
    char b[32];
    std::snprintf(b, sizeof b, "%.4g", std::abs(v) < 1e-12 ? 0.0 : v);
    return std::string(b);
  };
  auto line_plot = [&](const char* stem, const char* data, const char* refdata, const char* axis, double at,
                       const char* other) {
    std::ostringstream b;
    b << "set grid\nset key top right\n"
      << "set title \"" << c.name << ": " << (traction ? "tractions" : "pressure") << " along " << axis;
    if (g.dimension == 3) b << " (" << other << " = " << short_num(at * 1e3) << " mm)";
    b << "\" noenhanced\n"
      << "set xlabel \"" << axis << " (mm)\"\nset ylabel \"" << (traction ? "traction" : "pressure") << " (MPa)\"\n"
      << "plot \"" << data << "\" using ($1*1e3):($2*1e-6) with linespoints pt 7 ps 0.5 lw 1.5 title \"p, computed\"";
    if (ref) b << ", \\\n     \"" << refdata << "\" using ($1*1e3):($2*1e-6) with lines lw 2 dt 2 title \"p, " << ref_label << "\"";
    if (traction)
      b << ", \\\n     \"" << data << "\" using ($1*1e3):($3*1e-6) with linespoints pt 5 ps 0.4 title \"t_x\""
        << ", \\\n     \"" << data << "\" using ($1*1e3):($4*1e-6) with linespoints pt 9 ps 0.4 title \"t_y\"";
    b << "\n";
    figures.push_back({stem, b.str()});
  };
  // Tangential: t_x, t_y along a centre line between the friction bounds -f(p) and f(p).
  auto traction_plot = [&](const char* stem, const char* data, const char* axis, double at, const char* other) {
    std::ostringstream b;
    b << "set grid\nset key top right\n"
      << "set title \"" << c.name << ": tractions along " << axis;
    if (g.dimension == 3) b << " (" << other << " = " << short_num(at * 1e3) << " mm)";
    b << "\" noenhanced\n"
      << "set xlabel \"" << axis << " (mm)\"\nset ylabel \"traction (MPa)\"\n"
      << "plot \"" << data << "\" using ($1*1e3):($5*1e-6) with lines lw 2 lc rgb \"#808080\" title \"f(p)\""
      << ", \\\n     \"" << data << "\" using ($1*1e3):(-$5*1e-6) with lines lw 2 dt 2 lc rgb \"#808080\" title \"-f(p)\""
      << ", \\\n     \"" << data << "\" using ($1*1e3):($3*1e-6) with linespoints pt 7 ps 0.5 lw 1.5 title \"t_x\"";
    if (g.dimension == 3)
      b << ", \\\n     \"" << data << "\" using ($1*1e3):($4*1e-6) with linespoints pt 5 ps 0.5 lw 1.5 title \"t_y\"";
    b << "\n";
    figures.push_back({stem, b.str()});
  };
  line_plot("pressure_x", "line_x.dat", "reference_x.dat", "x", g.yc(j0), "y");
  if (!f.temperature_base.empty() && !f.temperature_body.empty()) {  // the flash temperature along x
    std::ostringstream s;
    s << "# x T_base T_body (K, rise; row j = " << j0 << ")\n";
    for (int i = 0; i < g.nx; ++i) {
      const std::size_t e = g.index(i, j0);
      s << num(g.xc(i)) << ' ' << num(field(f.temperature_base, e)) << ' ' << num(field(f.temperature_body, e)) << '\n';
    }
    write_file_whole(path("temperature_x.dat"), s.str());
    std::ostringstream b;
    b << "set grid\nset key top left\nset title \"" << c.name << ": flash temperature along x";
    if (g.dimension == 3) b << " (y = " << short_num(g.yc(j0) * 1e3) << " mm)";
    b << "\" noenhanced\nset xlabel \"x (mm)\"\nset ylabel \"temperature rise (K)\"\n"
      << "plot \"temperature_x.dat\" using ($1*1e3):2 with linespoints pt 7 ps 0.5 lw 1.5 title \"base\""
      << ", \\\n     \"temperature_x.dat\" using ($1*1e3):3 with linespoints pt 5 ps 0.4 lw 1.5 title \"body\"\n";
    figures.push_back({"temperature_x", b.str()});
  }
  if (friction) traction_plot("traction_x", "line_x.dat", "x", g.yc(j0), "y");
  if (g.dimension == 3) {
    line_plot("pressure_y", "line_y.dat", "reference_y.dat", "y", g.xc(i0), "x");
    if (friction) traction_plot("traction_y", "line_y.dat", "y", g.xc(i0), "x");
    const double aspect = (g.y_max() - g.y0) / (g.x_max() - g.x0);
    std::ostringstream frame;
    frame << "set xlabel \"x (mm)\"\nset ylabel \"y (mm)\"\n"
          << (aspect > 0.4 && aspect < 2.5 ? "set size ratio -1\n" : "")
          << "set xrange [" << num(g.x0 * 1e3) << ":" << num(g.x_max() * 1e3) << "]\nset yrange ["
          << num(g.y0 * 1e3) << ":" << num(g.y_max() * 1e3) << "]\nset xtics out\nset ytics out\n";
    std::ostringstream pm;
    pm << "set title \"" << c.name << ": contact pressure (MPa)\" noenhanced\n"
       << frame.str()
       << "set palette defined (0 \"white\", 0.1 \"#fde725\", 0.5 \"#21918c\", 1 \"#440154\")\n"
       << "plot \"map.dat\" using ($1*1e3):($2*1e3):($3*1e-6) with image notitle\n";
    figures.push_back({"pressure_map", pm.str()});
    std::ostringstream cm;
    cm << frame.str();
    if (!friction) {  // normal contact (also a finite body's)
      cm << "set title \"" << c.name << ": contact map\" noenhanced\n"
         << "set palette maxcolors 2\nset palette defined (0 \"#f0f0f0\", 1 \"#2c7bb6\")\n"
         << "set cbrange [-0.5:1.5]\nset cbtics (\"free\" 0, \"contact\" 1)\n";
    } else {
      cm << "set title \"" << c.name << ": stick/slip map\" noenhanced\n"
         << "set palette maxcolors 3\nset palette defined (0 \"#f0f0f0\", 1 \"#2c7bb6\", 2 \"#d7191c\")\n"
         << "set cbrange [-0.5:2.5]\nset cbtics (\"free\" 0, \"stick\" 1, \"slip\" 2)\n";
    }
    cm << "plot \"map.dat\" using ($1*1e3):($2*1e3):4 with image notitle\n";
    figures.push_back({"contact_map", cm.str()});
  }
  return figures;
}

std::vector<std::string> write_static_plots(const std::string& dir, const Case& c, const StaticFields& f,
                                            const std::vector<GnuplotFigure>& more) {
  std::vector<GnuplotFigure> figures = static_plot_figures(dir, c, f);
  figures.insert(figures.end(), more.begin(), more.end());
  return render_gnuplot(dir, c.name, figures);
}

}  // namespace dc::output
