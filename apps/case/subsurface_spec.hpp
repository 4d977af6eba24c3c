#pragma once
// The "subsurface" block (CASES.md): the elastic field inside both bodies from the computed
// surface tractions (core/subsurface_field.hpp), at depths below each body's surface.
#include <optional>
#include <string>
#include <vector>

namespace dc {

struct SubsurfaceSpec {
  bool enabled = false;  ///< the block is present
  /// subsurface.depths (m, >= 0, increasing): a list or "start:stop:count"; empty: 32 depths
  /// from 0 to 1.5 x the contact's half-width (its larger one in 3-D), chosen after the solve.
  std::vector<double> depths;
  /// subsurface.bodies: "base" (the half-space below), "body" (above); a rigid one is skipped.
  std::vector<std::string> bodies = {"base", "body"};
  /// subsurface.planes: also the x-z and y-z planes through each body's worst point (CSV).
  bool planes = true;
};

/// materials.<body>.yield: {"von_mises": Y} (uniaxial yield stress) or {"tresca_k": k} (shear
/// yield, Tresca's tau_1 = (sigma_1 - sigma_3)/2 <= k). A body with one gets its utilisation
/// and first-yield load factor (the field computed at the default depths if no block asks).
struct YieldSpec {
  bool von_mises = true;  ///< false: Tresca
  double strength = 0.0;  ///< Y or k (Pa)
};

struct BodyYields {
  std::optional<YieldSpec> body, base;
};

/// materials.<body>.fatigue.dang_van: {"alpha", "beta"} (Dang Van's criterion tau + alpha p_h
/// <= beta, core/dang_van.hpp), evaluated on the rolling passage of the solved load.
struct FatigueSpec {
  double alpha = 0.0, beta = 0.0;  ///< beta in Pa
};

struct BodyFatigue {
  std::optional<FatigueSpec> body, base;
};

}  // namespace dc
