// The "subsurface" block (CASES.md): depths, bodies, planes.
#include <algorithm>
#include <cmath>
#include <string>

#include "case_readers.hpp"
#include "errors.hpp"
#include "json_block.hpp"

namespace dc {

using namespace case_json;

namespace {

/// "start:stop:count": count depths from start to stop, both included.
std::vector<double> depth_range(const std::string& text) {
  const auto first = text.find(':'), second = text.find(':', first == std::string::npos ? first : first + 1);
  const char* key = "subsurface.depths";
  if (first == std::string::npos || second == std::string::npos)
    throw InputError(key, "expected a list of depths or \"start:stop:count\", got '" + text + "'");
  double start = 0.0, stop = 0.0;
  long count = 0;
  try {
    std::size_t used = 0;
    start = std::stod(text.substr(0, first), &used);
    stop = std::stod(text.substr(first + 1, second - first - 1));
    count = std::stol(text.substr(second + 1), &used);
    if (used != text.size() - second - 1) throw std::invalid_argument("count");
  } catch (const std::exception&) {
    throw InputError(key, "expected \"start:stop:count\" with numbers and a whole count, got '" + text + "'");
  }
  if (!(count >= 2 && count <= 1024)) throw InputError(key, "a count from 2 to 1024, got " + std::to_string(count));
  std::vector<double> depths;
  for (long k = 0; k < count; ++k) depths.push_back(start + (stop - start) * static_cast<double>(k) / (count - 1));
  return depths;
}

}  // namespace

SubsurfaceSpec read_subsurface(const json& j) {
  JsonBlock o(j, "subsurface");
  o.allow({"depths", "bodies", "planes"});
  SubsurfaceSpec s;
  s.enabled = true;
  if (o.has("depths")) {
    const json& d = o.at("depths");
    s.depths = d.is_string() ? depth_range(d.get<std::string>()) : o.numbers("depths");
    if (s.depths.empty()) throw InputError("subsurface.depths", "expected at least one depth");
    for (std::size_t k = 0; k < s.depths.size(); ++k) {
      if (!(s.depths[k] >= 0.0 && std::isfinite(s.depths[k])))
        throw InputError("subsurface.depths", "depths are >= 0 (m below each body's surface), got " + fmt(s.depths[k]));
      if (k > 0 && !(s.depths[k] > s.depths[k - 1]))
        throw InputError("subsurface.depths", "depths must increase, got " + fmt(s.depths[k - 1]) + " then " +
                                                  fmt(s.depths[k]));
    }
  }
  if (o.has("bodies")) {
    const json& b = o.at("bodies");
    if (!b.is_array() || b.empty()) throw InputError("subsurface.bodies", "expected a non-empty array of \"base\", \"body\"");
    s.bodies.clear();
    for (const json& e : b) {
      if (!e.is_string() || (e != "base" && e != "body"))
        throw InputError("subsurface.bodies", "expected \"base\" or \"body\", found " + describe(e));
      if (std::find(s.bodies.begin(), s.bodies.end(), e.get<std::string>()) != s.bodies.end())
        throw InputError("subsurface.bodies", "'" + e.get<std::string>() + "' named twice");
      s.bodies.push_back(e.get<std::string>());
    }
  }
  s.planes = o.boolean_or("planes", true);
  return s;
}

}  // namespace dc
