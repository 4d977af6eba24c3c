#pragma once
// The sensitivity of a tangential contact solution to the rigid-slip increments of its step,
// with the stick/slip set fixed: the Jacobian the in-step Newton needs from the contact, at the
// cost of one conjugate-gradient solve on the stick set per rigid mode (no extra contact solve).
#include <Eigen/Core>
#include <vector>

#include "friction_law.hpp"
#include "gmres.hpp"
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
  /// The same for a steady-rolling solution (slip per element of travel ds = D tau + dx xi m,
  /// D = B22 - S B22 not symmetric: GMRES on the stick set): d R_k / d xi_l per unit creepage / spin.
  /// The normal side of the contact, for dissimilar materials (kappa != 0, (4.2)-(4.3)): the
  /// pressure then follows the traction. All null: the pressure is held (kappa = 0).
  struct Coupling {
    const LinearOperator* C = nullptr;    ///< B31
    const LinearOperator* B21 = nullptr;  ///< kappa B21: tangential displacement of a pressure
    const LinearOperator* B32 = nullptr;  ///< kappa B32: normal displacement of a traction
    bool force_control = false;           ///< the normal load held (else the approach)
  };
  /// The full linearisation of a step's solution, contact and stick/slip sets fixed: stick
  /// elements keep d(ds) = 0, d(ds) = dm + B22 dtau + kappa B21 dp; slipping elements keep
  /// tau = -f(p) ds/|ds|: dtau = -(f/|ds|)(I - s s') d(ds) + f'(p) dp tau/|tau|; with coupling,
  /// on the contact set C dp + kappa B32 dtau = d delta with sum dp = 0 (force control) or
  /// d delta = 0. One GMRES solve per rigid mode (the system is not symmetric).
  Eigen::Matrix3d compute_full(const LinearOperator& Ct, const Coupling& coupling, const FrictionLaw& law,
                               const Grid& grid, const TangentialSolution& s);
  /// Linear-solver iterations (operator applies) of the compute_full calls so far.
  long iterations() const { return iterations_; }
  Eigen::Matrix3d compute_steady(const LinearOperator& D, const LinearOperator& Ct, const Grid& grid,
                                 const TangentialSolution& s);

 private:
  /// Stick-set solve of op_SS x = -m_l: conjugate gradients (symmetric) or GMRES.
  void solve_stick(const LinearOperator& op, bool symmetric, const Grid& grid, const TangentialSolution& s, int l);
  Eigen::Matrix3d assemble(const LinearOperator& op, bool symmetric, const LinearOperator& Ct, const Grid& grid,
                           const TangentialSolution& s);
  /// The slipping elements' response to rigid mode l alone (their traction turns with the slip).
  void slip_response(const LinearOperator& Ct, const Grid& grid, const TangentialSolution& s, int l,
                     std::vector<double>& tau) const;
  std::vector<double> x_, r_, p_, q_, full_, out_;
  long iterations_ = 0;
  std::vector<double> tau0_, wt_, wn_, dp_, b_, slope_, extra_t_, extra_n_, gain_, dir_;
  /// compute_full's solution per rigid mode, the start of the next call's GMRES (the contact and
  /// its stick/slip sets change little from one Newton iterate or step to the next).
  std::vector<double> last_solution_[3];
  GmresWorkspace gmres_work_;
};

}  // namespace dc::dynamics
