#include "wear_law.hpp"

#include <algorithm>
#include <cmath>

namespace dc {

double WearLaw::depth(double p, double tx, double ty, double sx, double sy) const {
  if (kind == WearLawKind::archard) return p > 0.0 ? k * p * std::hypot(sx, sy) / hardness : 0.0;
  return coefficient * std::max(0.0, -(tx * sx + ty * sy));
}

const char* to_string(WearLawKind kind) { return kind == WearLawKind::archard ? "archard" : "energy"; }

}  // namespace dc
