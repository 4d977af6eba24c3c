#pragma once
// The "tangential" block of a case (CASES.md), read into typed loads: the rigid-mode controls
// of a quasi-static step (shift, torsion) or of rolling (creepage, spin), and the loading
// history with memory. The tangential problem (nlp/) takes these and never sees JSON.
#include <array>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "normal_spec.hpp"

namespace dc {

enum class TangentialRegime { shift, torsion, rolling };

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

/// One step of a rolling history: the load, and the distance rolled under it (m, >= 0).
struct RollingStep {
  RollingLoad load;
  double distance = 0.0;
};

/// The whole block. Without a history: one step, `load` (shift/torsion) or `rolling`.
/// With one: `history` (shift/torsion) or `rolling_history`, each step starting from the
/// previous one's controls (a step keeps what it does not set).
struct TangentialSpec {
  TangentialRegime regime = TangentialRegime::shift;
  TangentialLoad load;                    ///< shift / torsion: the block's own controls
  RollingLoad rolling;                    ///< rolling: the block's own controls, velocity, max_steps
  bool has_history = false;
  std::vector<TangentialLoad> history;    ///< shift / torsion with a history
  std::vector<RollingStep> rolling_history;  ///< rolling with a history (transient rolling)

  /// The normal load of each step (one without a history).
  std::vector<NormalSpec> step_normals() const;
};

const char* to_string(TangentialRegime regime);

/// Reads the block at "tangential" for a case of `dimension` whose normal load is `normal`.
/// Throws InputError naming the key path (tangential.history[1].shift) and the reason.
TangentialSpec read_tangential(const nlohmann::json& j, int dimension, const NormalSpec& normal);

}  // namespace dc
