#pragma once
// The normal load (CASES.md "normal"): a force or an approach.

namespace dc {

enum class Control { force, approach };

struct NormalSpec {
  Control control = Control::force;
  double value = 0.0;  ///< force (N; 2-D N/m) or approach (m)
};

}  // namespace dc
