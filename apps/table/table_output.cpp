#include "table_output.hpp"

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <functional>
#include <sstream>

#include "gnuplot_figures.hpp"
#include "output_files.hpp"

namespace dc::table {
namespace {

/// A number for table.csv: 12 significant digits, nan when not finite.
std::string cell(double v) {
  if (!std::isfinite(v)) return "nan";
  char b[32];
  std::snprintf(b, sizeof b, "%.12g", v);
  return b;
}

/// At most `max` indices of [0, n), evenly chosen, first and last included.
std::vector<std::size_t> pick(std::size_t n, std::size_t max) {
  std::vector<std::size_t> out;
  if (n <= max) {
    for (std::size_t i = 0; i < n; ++i) out.push_back(i);
    return out;
  }
  for (std::size_t k = 0; k < max; ++k) out.push_back(k * (n - 1) / (max - 1));
  return out;
}

/// One gnuplot figure of `value` (Fx_mu_P or Fy_mu_P) against one axis, a data block per curve.
struct Curves {
  std::ostringstream data;
  std::vector<std::string> titles;
  void add(const std::string& title, const std::vector<std::pair<double, double>>& points) {
    for (const auto& [x, y] : points)
      if (std::isfinite(y)) data << cell(x) << ' ' << cell(y) << '\n';
    data << "\n\n";
    titles.push_back(title);
  }
  std::string body(const std::string& file, const std::string& title, const std::string& xlabel,
                   const std::string& ylabel) const {
    std::ostringstream g;
    g << "set title \"" << title << "\"\nset xlabel \"" << xlabel << "\"\nset ylabel \"" << ylabel
      << "\"\nset grid\nset key outside right\nset yrange [-1.1:1.1]\n"
      << "set arrow from graph 0, first 1 to graph 1, first 1 nohead dt 2\n"
      << "set arrow from graph 0, first -1 to graph 1, first -1 nohead dt 2\nplot ";
    for (std::size_t i = 0; i < titles.size(); ++i)
      g << (i ? ", \\\n     " : "") << "\"" << file << "\" index " << i << " using 1:2 with linespoints title \""
        << titles[i] << "\"";
    g << "\n";
    return g.str();
  }
};

std::string label(const char* name, double value) {
  char b[64];
  std::snprintf(b, sizeof b, "%s = %.3g", name, value);
  return b;
}

}  // namespace

std::string table_csv(const std::vector<TableRow>& rows) {
  std::ostringstream out;
  out << "creepage_x,creepage_y,spin,Fx,Fy,Mz,Fx_mu_P,Fy_mu_P,n_stick,certificate,status\n";
  for (const TableRow& r : rows)
    out << cell(r.creepage_x) << ',' << cell(r.creepage_y) << ',' << cell(r.spin) << ',' << cell(r.Fx) << ','
        << cell(r.Fy) << ',' << cell(r.Mz) << ',' << cell(r.Fx_mu_P) << ',' << cell(r.Fy_mu_P) << ','
        << (r.status == "failed" ? std::string("nan") : std::to_string(r.n_stick)) << ',' << cell(r.certificate)
        << ',' << r.status << '\n';
  return out.str();
}

nlohmann::json table_json(const Case& c, const TableAxes& axes, const std::vector<TableRow>& rows) {
  nlohmann::json failed = nlohmann::json::array();
  for (std::size_t i = 0; i < rows.size(); ++i) {
    const TableRow& r = rows[i];
    if (r.status == "converged") continue;
    failed.push_back({{"row", i},
                      {"creepage_x", r.creepage_x},
                      {"creepage_y", r.creepage_y},
                      {"spin", r.spin},
                      {"status", r.status},
                      {"message", r.message}});
  }
  return {{"case", c.source},
          {"ranges", {{"creepage_x", axes.creepage_x}, {"creepage_y", axes.creepage_y}, {"spin", axes.spin}}},
          {"columns",
           {"creepage_x", "creepage_y", "spin", "Fx", "Fy", "Mz", "Fx_mu_P", "Fy_mu_P", "n_stick", "certificate",
            "status"}},
          {"units",
           {{"creepage_x", "-"}, {"creepage_y", "-"}, {"spin", "1/m"}, {"Fx", c.dimension == 2 ? "N/m" : "N"},
            {"Fy", "N"}, {"Mz", "N m"}, {"Fx_mu_P", "-"}, {"Fy_mu_P", "-"}}},
          {"points", rows.size()},
          {"failed", failed}};
}

std::vector<std::string> table_plots(const std::string& dir, const Case& c, const TableAxes& axes,
                                     const std::vector<TableRow>& rows) {
  const std::size_t nx = axes.creepage_x.size(), ny = axes.creepage_y.size(), ns = axes.spin.size();
  auto at = [&](std::size_t ix, std::size_t iy, std::size_t is) -> const TableRow& {
    return rows[(is * ny + iy) * nx + ix];
  };
  // One figure against one creepage (values `along`), one curve per combination of the other
  // creepage (`other`, named `other_name`) and the spin; `value(k, i_other, is)` the row's force.
  auto figure = [&](const std::vector<double>& along, const std::vector<double>& other, const char* other_name,
                    const std::function<double(std::size_t, std::size_t, std::size_t)>& value,
                    const std::string& stem, const std::string& title, const std::string& xlabel,
                    const std::string& ylabel) {
    Curves curves;
    for (std::size_t line : pick(other.size() * ns, 8)) {
      const std::size_t io = line % other.size(), is = line / other.size();
      std::vector<std::pair<double, double>> pts;
      for (std::size_t k = 0; k < along.size(); ++k) pts.emplace_back(along[k], value(k, io, is));
      curves.add(label(other_name, other[io]) + (ns > 1 ? ", " + label("phi", axes.spin[is]) : ""), pts);
    }
    const std::string file = stem + ".dat";
    output::write_file_whole((std::filesystem::path(dir) / file).string(), curves.data.str());
    return output::GnuplotFigure{stem, curves.body(file, title, xlabel, ylabel)};
  };
  std::vector<output::GnuplotFigure> figures;
  if (nx > 1)
    figures.push_back(figure(
        axes.creepage_x, axes.creepage_y, "eta",
        [&](std::size_t k, std::size_t io, std::size_t is) { return at(k, io, is).Fx_mu_P; }, "table_Fx",
        "Longitudinal creep force", "creepage xi (-)", "F_x / (mu P)"));
  if (ny > 1)
    figures.push_back(figure(
        axes.creepage_y, axes.creepage_x, "xi",
        [&](std::size_t k, std::size_t io, std::size_t is) { return at(io, k, is).Fy_mu_P; }, "table_Fy",
        "Lateral creep force", "creepage eta (-)", "F_y / (mu P)"));
  if (figures.empty()) return {};
  return output::render_gnuplot(dir, c.name, figures);
}

}  // namespace dc::table
