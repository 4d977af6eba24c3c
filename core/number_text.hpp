#pragma once
// Numbers in messages (input errors, limits): six significant digits, as printf's %g.
#include <sstream>
#include <string>

namespace dc {

inline std::string six_digits(double v) {
  std::ostringstream s;
  s.precision(6);
  s << v;
  return s.str();
}

}  // namespace dc
