#include "fields_writer.hpp"

#include <cstdio>
#include <filesystem>
#include <string>

#include "cli_common.hpp"

namespace dc::cli {

std::string write_fields(const std::string& dir, const Grid& grid, const StaticFields& f, const std::string& file) {
  const std::string path = (std::filesystem::path(dir) / file).string();
  auto at = [](const std::vector<double>& v, std::size_t e) { return e < v.size() ? v[e] : 0.0; };
  std::string text = "x,y,p,tx,ty,sx,sy,state\n";
  text.reserve(text.size() + grid.size() * 96);
  char line[256];
  for (int j = 0; j < grid.ny; ++j)
    for (int i = 0; i < grid.nx; ++i) {
      const std::size_t e = grid.index(i, j);
      const int state = e < f.state.size() ? f.state[e] : 0;
      std::snprintf(line, sizeof line, "%.10g,%.10g,%.10g,%.10g,%.10g,%.10g,%.10g,%d\n", grid.xc(i), grid.yc(j),
                    at(f.p, e), at(f.tx, e), at(f.ty, e), at(f.sx, e), at(f.sy, e), state);
      text += line;
    }
  write_text_file(path, text);
  return path;
}

}  // namespace dc::cli
