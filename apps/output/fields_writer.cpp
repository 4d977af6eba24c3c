#include "fields_writer.hpp"

#include <algorithm>
#include <charconv>
#include <filesystem>
#include <string>

#include "output_files.hpp"

namespace dc::output {

std::string write_fields(const std::string& dir, const Grid& grid, const StaticFields& f, const std::string& file,
                         bool work_column) {
  const std::string path = (std::filesystem::path(dir) / file).string();
  auto at_or_zero = [](const std::vector<double>& v, std::size_t e) { return e < v.size() ? v[e] : 0.0; };
  // The frictional power density (W/m^2) where the step has a rate, else the step's work per area.
  const bool work = work_column && !f.dissipation.empty();
  const char* work_header = f.dissipation_rate > 0.0 ? ",power" : ",dissipation";
  // The flash temperature when computed: the hotter surface's rise per element (K).
  const bool temperature = !f.temperature_base.empty() && !f.temperature_body.empty();
  std::string text = std::string("x,y,p,tx,ty,sx,sy,state") + (work ? work_header : "") +
                     (temperature ? ",temperature\n" : "\n");
  text.reserve(text.size() + grid.size() * 96);
  // std::to_chars(..., general, 10) writes what printf's %.10g does, several times faster.
  char line[256];
  auto put = [&](char*& at, double v, char sep) {
    at = std::to_chars(at, line + sizeof line, v, std::chars_format::general, 10).ptr;
    *at++ = sep;
  };
  for (int j = 0; j < grid.ny; ++j)
    for (int i = 0; i < grid.nx; ++i) {
      const std::size_t e = grid.index(i, j);
      const int state = e < f.state.size() ? f.state[e] : 0;
      char* at = line;
      for (double v : {grid.xc(i), grid.yc(j), at_or_zero(f.p, e), at_or_zero(f.tx, e), at_or_zero(f.ty, e),
                       at_or_zero(f.sx, e), at_or_zero(f.sy, e)})
        put(at, v, ',');
      at = std::to_chars(at, line + sizeof line, state).ptr;
      if (work) {
        *at++ = ',';
        const double w = at_or_zero(f.dissipation, e);
        at = std::to_chars(at, line + sizeof line, f.dissipation_rate > 0.0 ? w * f.dissipation_rate : w,
                           std::chars_format::general, 10).ptr;
      }
      if (temperature) {
        *at++ = ',';
        at = std::to_chars(at, line + sizeof line, std::max(at_or_zero(f.temperature_base, e), at_or_zero(f.temperature_body, e)),
                           std::chars_format::general, 10).ptr;
      }
      *at++ = '\n';
      text.append(line, at);
    }
  write_file_whole(path, text);
  return path;
}

}  // namespace dc::output
