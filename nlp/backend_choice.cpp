#include "backend_choice.hpp"

#include <algorithm>

#include "errors.hpp"

namespace dc {

std::vector<std::string> backend_order(const std::string& requested, std::size_t unknowns, bool fallback) {
  std::vector<std::string> order;
  if (requested == "auto") {
    order = unknowns <= kAutoIpoptLimit ? std::vector<std::string>{"ipopt", "native", "nlopt"}
                                        : std::vector<std::string>{"native", "ipopt", "nlopt"};
  } else if (requested == "ipopt" || requested == "nlopt" || requested == "native") {
    order = {requested};
    for (const char* other : {"native", "ipopt", "nlopt"})
      if (requested != other) order.emplace_back(other);
  } else {
    throw InputError("solver.backend", "unknown backend '" + requested + "' (auto, ipopt, nlopt, native)");
  }
  if (!fallback) order.resize(1);
  return order;
}

}  // namespace dc
