#pragma once
// Direct solver of the steady rolling problem: the traction tau that is the same upstream and
// here, so that the slip per step of travel is ((2.19), (4.4)-(4.6))
//   s = b + D tau + sum_k alpha_k m_k,   D = C_t - C_t(upstream) (non-symmetric),
// and the friction law (2.4)-(2.5) holds: |tau| <= f, tau = -f s/|s| where s != 0, s = 0 where
// |tau| < f. The unknown amplitudes alpha_k belong to the resultant-controlled modes:
// sum_e m_k(e).tau_e A = R_k.
// No minimisation principle exists (D is not symmetric), so the law is solved as the
// semismooth equation F(tau) = tau - Pi_{|t|<=f}(tau - r s(tau)) = 0 (Alart-Curnier form) by
// Newton's method with GMRES on the matrix-free operator D.
#include <cstddef>
#include <memory>
#include <string>
#include <vector>

#include "linear_operator.hpp"
#include "quadratic_program.hpp"

namespace dc {

struct SteadyRollingProgram {
  const LinearOperator* D = nullptr;  ///< convective compliance, comps*N square
  int comps = 2;                      ///< tangential components: 1 (2-D) or 2 (3-D)
  std::vector<double> b;              ///< known slip per step (given rigid modes, kappa terms), comps*N
  std::vector<double> bound;          ///< f(p) per element; 0: no traction there
  std::vector<std::vector<double>> modes;  ///< unknown-amplitude modes m_k, comps*N each
  std::vector<double> resultants;          ///< R_k, one per mode
  double area = 1.0;                       ///< element area A (2-D: length)
  std::vector<double> tau0;                ///< starting traction (or empty: zero)
};

struct SteadyRollingOutcome {
  std::vector<double> tau;         ///< comps*N, inside the friction disks
  std::vector<double> amplitudes;  ///< alpha_k, one per mode
  bool success = false;
  int newton_iterations = 0;
  int operator_applies = 0;        ///< applies of D (residuals and Krylov iterations)
  double residual = 0.0;           ///< |F|_inf relative to the largest bound
  std::string message;
};

/// Newton's method with a backtracking search on |F|; options.tol bounds the residual,
/// options.max_iter the Newton iterations. Never throws for non-convergence (success = false).
SteadyRollingOutcome solve_steady_rolling(const SteadyRollingProgram& program, const SolveOptions& options);

class SteadyRollingNewton;
/// The solver's vectors, Krylov basis and iterates kept between solves by a caller that solves
/// many programs of one size (a dynamic run's every step, a creep-force table's points).
class SteadyRollingWorkspace {
 public:
  SteadyRollingWorkspace();
  ~SteadyRollingWorkspace();
  SteadyRollingWorkspace(SteadyRollingWorkspace&&) noexcept;
  SteadyRollingWorkspace& operator=(SteadyRollingWorkspace&&) noexcept;

 private:
  std::unique_ptr<SteadyRollingNewton> newton_;
  friend void solve_steady_rolling(const SteadyRollingProgram&, const SolveOptions&, SteadyRollingWorkspace&,
                                   SteadyRollingOutcome&);
};
/// The same with the caller's workspace into `out` (whose storage it fills again; the result
/// does not depend on what the workspace held).
void solve_steady_rolling(const SteadyRollingProgram& program, const SolveOptions& options,
                          SteadyRollingWorkspace& work, SteadyRollingOutcome& out);

}  // namespace dc
