#include "wear_writer.hpp"

#include <charconv>
#include <filesystem>

#include "output_files.hpp"

namespace dc::output {

std::string write_wear(const std::string& dir, const Grid& grid, const std::vector<double>& base,
                       const std::vector<double>& body) {
  const std::string path = (std::filesystem::path(dir) / "wear.csv").string();
  std::string text = "x,y";
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

}  // namespace dc::output
