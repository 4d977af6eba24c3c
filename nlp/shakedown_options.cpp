#include "shakedown_options.hpp"

#include <cmath>

#include "number_text.hpp"

namespace dc {

std::string ShakedownOptions::validate() const {
  const auto in_range = [](double v) { return std::isfinite(v) && v >= kMinTol && v <= kMaxTol; };
  if (!in_range(tol)) return "tol: must lie in [1e-16, 0.1], got " + six_digits(tol);
  if (!in_range(certificate_tol))
    return "certificate_tol: must lie in [1e-16, 0.1], got " + six_digits(certificate_tol);
  if (max_iter < 1) return "max_iter: must be at least 1, got " + std::to_string(max_iter);
  if (max_rounds < 1) return "max_rounds: must be at least 1, got " + std::to_string(max_rounds);
  return "";
}

}  // namespace dc
