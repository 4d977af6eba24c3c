#include "wear_series_writer.hpp"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <sstream>

#include "output_files.hpp"
#include "pvd_collection.hpp"
#include "vti_image.hpp"
#include "wear_writer.hpp"

namespace dc::output {
namespace {

std::string number(double v) {
  std::ostringstream s;
  s.precision(10);
  s << v;
  return s.str();
}

}  // namespace

void write_wear_series(const std::string& dir, const Grid& grid, const std::vector<WornState>& series,
                       WornBodies bodies, nlohmann::json& files) {
  if (series.empty() || !(bodies.base || bodies.body)) return;
  const std::filesystem::path folder(dir);
  std::vector<PvdEntry> images;
  for (std::size_t k = 0; k < series.size(); ++k) {
    VtiImage image = surface_image(grid);
    std::vector<float> depth(grid.size(), 0.0f);
    for (std::size_t e = 0; e < depth.size() && e < series[k].depth.size(); ++e)
      depth[e] = static_cast<float>(series[k].depth[e]);
    if (bodies.base) image.add("wear_base", 1, depth);
    if (bodies.body) image.add("wear_body", 1, depth);
    const std::string name = "wear_" + std::to_string(k) + ".vti";
    write_file_whole((folder / name).string(), image.text());
    images.push_back({static_cast<double>(series[k].cycles), name});
  }
  write_pvd((folder / "wear.pvd").string(), images);
  files["wear_series"] = "wear.pvd";

  const int j0 = wear_row(grid, series.back().depth, {});  // the last state's track
  std::string text = "cycles,x";
  if (bodies.base) text += ",base";
  if (bodies.body) text += ",body";
  text += '\n';
  for (const WornState& s : series)
    for (int i = 0; i < grid.nx; ++i) {
      const std::size_t e = grid.index(i, j0);
      const std::string d = number(e < s.depth.size() ? s.depth[e] : 0.0);
      text += std::to_string(s.cycles) + ',' + number(grid.xc(i));
      if (bodies.base) text += ',' + d;
      if (bodies.body) text += ',' + d;
      text += '\n';
    }
  write_file_whole((folder / "wear_profiles.csv").string(), text);
  files["wear_profiles"] = "wear_profiles.csv";
}

GnuplotFigure wear_evolution_figure(const std::string& dir, const std::string& case_name, const Grid& grid,
                                    const std::vector<WornState>& series) {
  const int j0 = wear_row(grid, series.back().depth, {});
  constexpr std::size_t kCurves = 8;
  std::vector<std::size_t> drawn;  // evenly spread, the last included
  const std::size_t n = series.size();
  for (std::size_t c = 0; c < std::min(kCurves, n); ++c)
    drawn.push_back(n <= kCurves ? c : (n - 1) - (std::min(kCurves, n) - 1 - c) * (n - 1) / (kCurves - 1));
  std::ostringstream data;
  data << "# x (m) then the worn depth (m) along row " << j0 << " after each drawn state; blocks by state\n";
  for (std::size_t b = 0; b < drawn.size(); ++b) {
    const WornState& s = series[drawn[b]];
    data << "# cycles " << s.cycles << '\n';
    for (int i = 0; i < grid.nx; ++i) {
      const std::size_t e = grid.index(i, j0);
      data << gnuplot_number(grid.xc(i)) << ' ' << gnuplot_number(e < s.depth.size() ? s.depth[e] : 0.0) << '\n';
    }
    data << "\n\n";
  }
  write_file_whole((std::filesystem::path(dir) / "wear_evolution.dat").string(), data.str());
  std::ostringstream p;
  p << "set grid\nset key top center\nset title \"" << case_name << ": worn depth along x after the updates";
  if (grid.dimension == 3) p << " (y = " << gnuplot_number(grid.yc(j0) * 1e3, 4) << " mm)";
  p << "\" noenhanced\nset xlabel \"x (mm)\"\nset ylabel \"worn depth (um)\"\nplot ";
  for (std::size_t b = 0; b < drawn.size(); ++b)
    p << (b == 0 ? "" : ", \\\n     ") << "\"wear_evolution.dat\" index " << b
      << " using ($1*1e3):($2*1e6) with lines lw 1.5 title \"" << series[drawn[b]].cycles << " cycles\"";
  p << "\n";
  return {"wear_evolution", p.str()};
}

}  // namespace dc::output
