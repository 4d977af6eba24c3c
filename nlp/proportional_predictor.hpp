#pragma once
// Starting points of a quasi-static loading history with kappa != 0 ((4.26)-(4.27)) from its
// last two steps. When the load of the next step continues the last change in proportion,
// L_k - L_{k-1} = r (L_{k-1} - L_{k-2}) with 0 < r <= 2 in every controlled value (the same
// controls throughout), the traction and the pressure are extrapolated linearly,
//   tau_k ~ tau_{k-1} + r (tau_{k-1} - tau_{k-2})   (p likewise, kept >= 0),
// which is right to first order in the load increment where the previous step's state is right
// only to zeroth order: the alternation starts with a coupling residual an order or two smaller.
// Only a starting point: the alternation and its certificate decide the step's answer.
#include <vector>

namespace dc {

class ProportionalPredictor {
 public:
  /// A step's load as its controlled values (e.g. the normal force, then the rigid-mode
  /// amplitudes or resultants) and how each is controlled (any code, compared for equality).
  struct Load {
    std::vector<double> values;
    std::vector<int> kinds;
  };

  /// The converged state of a step under `load` (forgets the older of the two kept).
  void record(const Load& load, const std::vector<double>& tau, const std::vector<double>& pressure);
  /// Extrapolates tau and pressure to `load`; false (both untouched) unless two steps are
  /// recorded and `load` continues their change in proportion.
  bool predict(const Load& load, std::vector<double>& tau, std::vector<double>& pressure) const;
  /// Forgets the history (a new history, a reset, a restored or convected state).
  void clear();

  /// The ratio r of the next change to the last one, 0 when the loads are not proportional.
  static double ratio(const Load& older, const Load& last, const Load& next);

 private:
  struct State {
    Load load;
    std::vector<double> tau, pressure;
  };
  std::vector<State> states_;  ///< at most two, oldest first
};

}  // namespace dc
