#pragma once
// The typed loads of the tangential problem (tangential_problem.hpp): the rigid-mode controls of
// a quasi-static step (shift, torsion) or of rolling (creepage, spin), each an amplitude or a
// resultant, with the step's normal load. The case layer reads them from the "tangential" block
// (apps/case/read_tangential.cpp).
#include <array>
#include <vector>

#include "normal_spec.hpp"

namespace dc {

/// Control of one rigid mode (x, y, rotation z): amplitude or resultant.
struct ModeControl {
  enum class Kind { amplitude, resultant } kind = Kind::amplitude;
  double value = 0.0;
};

/// One quasi-static load step (shift / torsion): the normal load and the rigid modes.
/// Amplitudes are TOTAL rigid displacements (m, m, rad) since the unloaded state.
struct TangentialLoad {
  NormalSpec normal;
  std::array<ModeControl, 3> modes{};  ///< x shift (m) | F_x (N); y shift | F_y; angle (rad) | M_z (N m)
};

/// Steady rolling: creepages (rigid slip velocity / V) and spin (1/m), or resultants.
struct RollingLoad {
  NormalSpec normal;
  std::array<ModeControl, 3> modes{};  ///< cx (-) | F_x; cy (-) | F_y; spin phi (1/m) | M_z
  double velocity = 1.0;               ///< rolling speed V (m/s), along +x
  int max_steps = 0;                   ///< steady_rolling() marching: at most this many steps; 0: 10 * nx (roll(): unused)
  /// steady_rolling(): automatic: Newton on the steady equations (backends auto/native), marching
  /// when it gives up or for the convex-program backends; newton / marching: only that method.
  enum class Method { automatic, newton, marching } method = Method::automatic;
  /// steady_rolling() by Newton: the starting traction (tau_x of every element, then tau_y in
  /// 3-D), e.g. a neighbouring point's of a creep-force table; empty (or another size): zero.
  std::vector<double> warm_start;
};

}  // namespace dc
