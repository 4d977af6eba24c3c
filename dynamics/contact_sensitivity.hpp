#pragma once
// The sensitivity of a tangential contact solution to the rigid-slip increments of its step,
// with the stick/slip set fixed: the Jacobian the in-step Newton needs from the contact, at the
// cost of one conjugate-gradient solve on the stick set per rigid mode (no extra contact solve).
#include <Eigen/Core>
#include <vector>

#include "grid.hpp"
#include "linear_operator.hpp"
#include "tangential_problem.hpp"

namespace dc::dynamics {

/// Work buffers reused from step to step (no allocation once sized).
class TangentialSensitivity {
 public:
  /// G(k, l) = d R_k / d a_l: R = (F_x, F_y, M_z) the resultants of the rigid modes (x, y shift,
  /// rotation about z through the grid origin), a their increments over the step (m, m, rad).
  /// Stick elements keep ds = 0: Ct_SS d tau_S = -m_S (conjugate gradients on the stick set);
  /// slip elements keep |tau| = f and turn with the slip: d tau = -(I - s s') d(ds) / (|ds|/f + c_ee)
  /// (c_ee the element's own compliance: a barely slipping element is no stiffer than a stuck one).
  /// 2-D: only G(0, 0) is non-zero.
  Eigen::Matrix3d compute(const LinearOperator& Ct, const Grid& grid, const TangentialSolution& s);

 private:
  std::vector<double> x_, r_, p_, q_, full_, out_;
};

}  // namespace dc::dynamics
