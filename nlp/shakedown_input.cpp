#include "shakedown_input.hpp"

#include <algorithm>
#include <cmath>

namespace dc {

std::string StressHistory::validate() const {
  if (depths.empty()) return "depths: at least one depth needed";
  if (positions.empty()) return "positions: at least one position needed";
  if (stress.size() != depths.size() * positions.size())
    return "stress: " + std::to_string(depths.size() * positions.size()) +
           " samples needed (depths x positions), got " + std::to_string(stress.size());
  for (std::size_t k = 0; k < stress.size(); ++k)
    for (const double v : stress[k])
      if (!std::isfinite(v)) return "stress: non-finite value at sample " + std::to_string(k);
  return "";
}

std::string ResidualModel::validate() const {
  for (std::size_t k = 0; k < free.size(); ++k) {
    const VoigtComponent c = free[k];
    if (c == VoigtComponent::zz || c == VoigtComponent::yz || c == VoigtComponent::xz)
      return std::string("free: ") + to_string(c) +
             " is not self-equilibrated for a residual stress of depth only (it must vanish)";
    const auto before = free.begin() + static_cast<std::ptrdiff_t>(k);
    if (std::find(free.begin(), before, c) != before)
      return std::string("free: ") + to_string(c) + " listed twice";
  }
  return "";
}

}  // namespace dc
