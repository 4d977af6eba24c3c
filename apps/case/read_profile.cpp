// The "profile" block (CASES.md): the body's shape, and the CSV table of a table profile.
#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "case_readers.hpp"
#include "errors.hpp"
#include "json_block.hpp"

namespace dc {

using namespace case_json;

namespace {

/// Reads the table file of a table profile (relative to `base_dir`).
void read_table(ProfileSpec& p, const std::string& file_key, const std::string& base_dir) {
  namespace fs = std::filesystem;
  fs::path path(p.file);
  if (path.is_relative() && !base_dir.empty()) path = fs::path(base_dir) / path;
  std::ifstream in(path);
  if (!in || fs::is_directory(path)) throw InputError(file_key, "cannot open '" + path.string() + "'");
  read_profile_table(in, p, file_key);
}

}  // namespace

void read_profile_table(std::istream& in, ProfileSpec& p, const std::string& file_key) {
  auto split = [](const std::string& line) {
    std::vector<std::string> cells;
    std::string cell;
    std::istringstream s(line);
    while (std::getline(s, cell, ',')) {
      const auto b = cell.find_first_not_of(" \t\r");
      const auto e = cell.find_last_not_of(" \t\r");
      cells.push_back(b == std::string::npos ? std::string() : cell.substr(b, e - b + 1));
    }
    return cells;
  };
  std::string line;
  int line_no = 0;
  int ix = -1, iy = -1, ih = -1;
  std::size_t columns = 0;
  p.table_x.clear();
  p.table_y.clear();
  p.table_h.clear();
  while (std::getline(in, line)) {
    ++line_no;
    if (line.find_first_not_of(" \t\r") == std::string::npos || line[line.find_first_not_of(" \t")] == '#')
      continue;
    const auto cells = split(line);
    if (ih < 0) {  // header
      for (std::size_t c = 0; c < cells.size(); ++c) {
        if (cells[c] == "x") ix = static_cast<int>(c);
        else if (cells[c] == "y") iy = static_cast<int>(c);
        else if (cells[c] == "h") ih = static_cast<int>(c);
      }
      if (ix < 0 || ih < 0)
        throw InputError(file_key, "line " + std::to_string(line_no) +
                                       ": expected a header naming the columns x,y,h");
      columns = cells.size();
      continue;
    }
    if (cells.size() != columns)
      throw InputError(file_key, "line " + std::to_string(line_no) + ": expected " +
                                     std::to_string(columns) + " values, got " + std::to_string(cells.size()));
    auto value = [&](int c) {
      const std::string& s = cells[static_cast<std::size_t>(c)];
      char* end = nullptr;
      const double v = std::strtod(s.c_str(), &end);
      if (s.empty() || end != s.c_str() + s.size() || !std::isfinite(v))
        throw InputError(file_key, "line " + std::to_string(line_no) + ": '" + s + "' is not a number");
      return v;
    };
    p.table_x.push_back(value(ix));
    p.table_y.push_back(iy >= 0 ? value(iy) : 0.0);
    p.table_h.push_back(value(ih));
  }
  if (ih < 0) throw InputError(file_key, "the file is empty (expected a header x,y,h and rows)");
  if (p.table_h.size() < 2) throw InputError(file_key, "the table needs at least two rows");
  // Heights are measured from the first point of contact: shift the table's minimum to 0.
  const double h_min = *std::min_element(p.table_h.begin(), p.table_h.end());
  for (double& h : p.table_h) h -= h_min;
}

ProfileSpec read_profile(const json& j, int dimension, const std::string& base_dir) {
  JsonBlock o(j, "profile");
  const std::string type = o.string("type");
  ProfileSpec p;
  const bool three_d = dimension == 3;
  auto three_d_only = [&](const char* what) {
    if (!three_d)
      throw InputError("profile.type", std::string("'") + what +
                                           "' is a 3-D profile; in 2-D (plane strain) use 'cylinder' or "
                                           "'quadratic' (h = a x^2), or set dimension 3");
  };
  if (type == "sphere") {
    three_d_only("sphere");
    o.allow({"type", "radius"});
    p.type = ProfileType::sphere;
    p.radius = o.positive_at_most("radius", kMaxLength, "m");
  } else if (type == "ellipsoid") {
    three_d_only("ellipsoid");
    o.allow({"type", "radius_x", "radius_y"});
    p.type = ProfileType::ellipsoid;
    p.radius_x = o.positive_at_most("radius_x", kMaxLength, "m");
    p.radius_y = o.positive_at_most("radius_y", kMaxLength, "m");
  } else if (type == "cylinder") {
    if (three_d) o.allow({"type", "radius", "length"});
    else o.allow({"type", "radius"});
    p.type = ProfileType::cylinder;
    p.radius = o.positive_at_most("radius", kMaxLength, "m");
    if (three_d) p.length = o.has("length") ? o.positive_at_most("length", kMaxLength, "m") : 0.0;
  } else if (type == "flat_punch") {
    three_d_only("flat_punch");
    o.allow({"type", "radius", "inner_radius"});
    p.type = ProfileType::flat_punch;
    p.radius = o.positive_at_most("radius", kMaxLength, "m");
    if (o.has("inner_radius")) {  // an annular punch inner_radius <= r < radius
      p.inner_radius = o.non_negative("inner_radius");
      if (!(p.inner_radius < p.radius))
        throw InputError(o.key("inner_radius"), "an annular punch's inner_radius must be below its radius " +
                                                    fmt(p.radius) + " m, got " + fmt(p.inner_radius));
    }
  } else if (type == "quadratic") {
    p.type = ProfileType::quadratic;
    if (three_d) {
      o.allow({"type", "a", "b"});
      p.a = o.non_negative("a");
      p.b = o.non_negative("b");
      if (p.a == 0.0 && p.b == 0.0)
        throw InputError("profile.a", "a and b cannot both be zero (a flat profile has no contact point; "
                                      "use flat_punch)");
    } else {
      o.allow({"type", "a"});
      p.a = o.positive("a");
    }
  } else if (type == "table") {
    o.allow({"type", "file"});
    p.type = ProfileType::table;
    p.file = o.string("file");
    if (p.file.empty()) throw InputError("profile.file", "must name a CSV file");
    read_table(p, "profile.file", base_dir);
  } else {
    throw InputError("profile.type", "unknown profile type '" + type +
                                         "' (expected sphere, ellipsoid, cylinder, flat_punch, quadratic, table)");
  }
  return p;
}

}  // namespace dc
