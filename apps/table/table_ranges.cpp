#include "table_ranges.hpp"

#include <cerrno>
#include <cmath>
#include <algorithm>
#include <cstdlib>
#include <limits>
#include <sstream>

#include "errors.hpp"

namespace dc::table {
namespace {

/// The whole of `s` as a finite number (throws InputError for `option` otherwise).
double to_number(const std::string& option, const std::string& s) {
  const char* begin = s.c_str();
  char* end = nullptr;
  errno = 0;
  const double v = std::strtod(begin, &end);
  if (s.empty() || end == begin || *end != '\0')
    throw InputError(option, "'" + s + "' is not a number (give start:stop:count or a list a,b,c)");
  if (errno == ERANGE || !std::isfinite(v)) throw InputError(option, "'" + s + "' is not a finite number");
  return v;
}

std::vector<std::string> split(const std::string& text, char sep) {
  std::vector<std::string> parts;
  std::string part;
  std::istringstream in(text);
  while (std::getline(in, part, sep)) parts.push_back(part);
  if (!text.empty() && text.back() == sep) parts.emplace_back();
  return parts;
}

}  // namespace

std::vector<double> parse_table_range(const std::string& option, const std::string& text) {
  if (text.empty()) throw InputError(option, "empty range (give start:stop:count or a list a,b,c)");
  if (text.find(':') != std::string::npos) {
    const std::vector<std::string> p = split(text, ':');
    if (p.size() != 3) throw InputError(option, "'" + text + "': a range is start:stop:count");
    const double start = to_number(option, p[0]), stop = to_number(option, p[1]);
    const double count = to_number(option, p[2]);
    if (count != std::floor(count) || count < 1 || count > kMaxTableValues)
      throw InputError(option, "'" + text + "': count must be a whole number from 1 to " +
                                   std::to_string(kMaxTableValues));
    const int n = static_cast<int>(count);
    if (n == 1 && start != stop) throw InputError(option, "'" + text + "': one value needs start = stop");
    std::vector<double> values(n);
    // Weighted from both ends (exact at start and stop, symmetric about a range's middle); a value
    // within round-off of zero is zero, so a range through 0 holds the zero-creepage point itself.
    const double scale = std::max(std::abs(start), std::abs(stop));
    for (int i = 0; i < n; ++i) {
      const double w = n == 1 ? 0.0 : static_cast<double>(i) / (n - 1);
      const double v = (1.0 - w) * start + w * stop;
      values[i] = std::abs(v) <= 64.0 * std::numeric_limits<double>::epsilon() * scale ? 0.0 : v;
    }
    return values;
  }
  std::vector<double> values;
  for (const std::string& s : split(text, ',')) values.push_back(to_number(option, s));
  if (values.size() > static_cast<std::size_t>(kMaxTableValues))
    throw InputError(option, "more than " + std::to_string(kMaxTableValues) + " values");
  return values;
}

}  // namespace dc::table
