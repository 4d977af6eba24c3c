#pragma once
// The "tangential" block of a case (CASES.md): the regime, the loads of one step or a loading
// history with memory (read by apps/case/read_tangential.cpp). Each step is a typed load of the
// tangential problem (nlp/tangential_loads.hpp), solved by solve_tangential_case (solve_case.hpp).
#include <vector>

#include "normal_spec.hpp"
#include "tangential_loads.hpp"

namespace dc {

enum class TangentialRegime { shift, torsion, rolling };

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

}  // namespace dc
