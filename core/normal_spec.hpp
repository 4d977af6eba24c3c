#pragma once
// The normal load of a case (CASES.md "normal"): a force or an approach.
#include <string>

#include <nlohmann/json.hpp>

namespace dc {

enum class Control { force, approach };

struct NormalSpec {
  Control control = Control::force;
  double value = 0.0;  ///< force (N; 2-D N/m) or approach (m)
};

/// Reads {"force": P} or {"approach": d} at `path` ("normal", "tangential.history[2].normal").
NormalSpec read_normal(const nlohmann::json& j, const std::string& path);

}  // namespace dc
