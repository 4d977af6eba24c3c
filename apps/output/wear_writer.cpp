#include "wear_writer.hpp"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <filesystem>
#include <sstream>
#include <tuple>

#include "output_files.hpp"

namespace dc::output {

std::string write_wear(const std::string& dir, const Grid& grid, const std::vector<double>& base,
                       const std::vector<double>& body, const std::string& file, const std::string& x_name) {
  const std::string path = (std::filesystem::path(dir) / file).string();
  std::string text = x_name + ",y";
  if (!base.empty()) text += ",base";
  if (!body.empty()) text += ",body";
  text += '\n';
  char line[128];
  for (int j = 0; j < grid.ny; ++j)
    for (int i = 0; i < grid.nx; ++i) {
      const std::size_t e = grid.index(i, j);
      char* at = line;
      bool first = true;
      auto put = [&](double v) {
        if (!first) *at++ = ',';
        first = false;
        at = std::to_chars(at, line + sizeof line, v, std::chars_format::general, 10).ptr;
      };
      put(grid.xc(i));
      put(grid.yc(j));
      if (!base.empty()) put(base[e]);
      if (!body.empty()) put(body[e]);
      *at++ = '\n';
      text.append(line, at);
    }
  write_file_whole(path, text);
  return path;
}

int wear_row(const Grid& grid, const std::vector<double>& base, const std::vector<double>& body) {
  if (grid.dimension == 2) return 0;
  double mass = 0.0, moment = 0.0;
  for (int j = 0; j < grid.ny; ++j)
    for (int i = 0; i < grid.nx; ++i) {
      const std::size_t e = grid.index(i, j);
      const double d = (e < base.size() ? base[e] : 0.0) + (e < body.size() ? body[e] : 0.0);
      mass += d;
      moment += d * grid.yc(j);
    }
  double y = mass > 0.0 ? moment / mass : 0.0;
  // A centroid on a row boundary by symmetry (y = 0 on an even grid) within round-off: the boundary,
  // whose row above is taken, as for y = 0 exactly.
  const double u = (y - grid.y0) / grid.dy;
  if (std::abs(u - std::round(u)) < 1e-6) y = grid.y0 + std::round(u) * grid.dy;
  return std::clamp(static_cast<int>(std::floor((y - grid.y0) / grid.dy)), 0, grid.ny - 1);
}

GnuplotFigure wear_figure(const std::string& dir, const std::string& case_name, const Grid& grid,
                          const std::vector<double>& base, const std::vector<double>& body, const std::string& name,
                          const std::string& x_label) {
  const int j0 = wear_row(grid, base, body);
  auto at = [](const std::vector<double>& v, std::size_t e) { return e < v.size() ? v[e] : 0.0; };
  std::ostringstream data;
  data << "# " << x_label << " base body (m; row j = " << j0 << ")\n";
  for (int i = 0; i < grid.nx; ++i) {
    const std::size_t e = grid.index(i, j0);
    data << gnuplot_number(grid.xc(i)) << ' ' << gnuplot_number(at(base, e)) << ' ' << gnuplot_number(at(body, e)) << '\n';
  }
  write_file_whole((std::filesystem::path(dir) / (name + ".dat")).string(), data.str());
  std::ostringstream b;
  b << "set grid\nset key top right\nset title \"" << case_name << ": worn depth along " << x_label;
  if (grid.dimension == 3) b << " (y = " << gnuplot_number(grid.yc(j0) * 1e3, 4) << " mm)";
  b << "\" noenhanced\nset xlabel \"" << x_label << " (mm)\"\nset ylabel \"worn depth (um)\"\nplot ";
  bool first = true;
  for (const auto& [column, label, v] : {std::tuple{2, "base", &base}, std::tuple{3, "body", &body}}) {
    if (v->empty()) continue;
    b << (first ? "" : ", \\\n     ") << "\"" << name << ".dat\" using ($1*1e3):($" << column
      << "*1e6) with linespoints pt 7 ps 0.5 lw 1.5 title \"" << label << "\"";
    first = false;
  }
  b << "\n";
  return {name, b.str()};
}

}  // namespace dc::output
