#pragma once
// The normal contact problem (4.7): minimise 1/2 p'Cp + (h - delta)'p over p >= 0,
// under force control (sum p A = P, delta its multiplier) or approach control (delta given).
// KKT = (2.2)-(2.3): g = Cp + h - delta >= 0, p >= 0, p g = 0.
#include <memory>
#include <string>
#include <vector>

#include "backend_choice.hpp"
#include "certified_solve.hpp"
#include "grid.hpp"
#include "linear_operator.hpp"
#include "material.hpp"
#include "native_solvers.hpp"
#include "normal_preconditioner.hpp"
#include "normal_spec.hpp"
#include "quadratic_program.hpp"
#include "solver_options.hpp"
#include "solver_report.hpp"

namespace dc {

struct NormalSolution {
  std::vector<double> pressure;  ///< Pa (per element)
  std::vector<double> gap;       ///< deformed gap g (m), >= 0, 0 in contact
  double approach = 0.0;         ///< delta (m); in 2-D relative to the reference length
  double force = 0.0;            ///< sum p A (N; 2-D N/m)
  SolverReport report;
};

/// Back to a default solution, the storage of its fields and report kept (solver_report.hpp).
void reset_keeping_storage(NormalSolution& solution);

/// Set up once per grid/materials (operator, plans), solve many times (warm starts).
class NormalProblem {
 public:
  NormalProblem(const Grid& grid, const MaterialPair& materials, std::vector<double> heights,
                OperatorKind kind = OperatorKind::automatic);
  NormalProblem(std::shared_ptr<const LinearOperator> compliance, const Grid& grid,
                std::vector<double> heights);

  /// Solves with the requested backend ("auto", "ipopt", "nlopt", "native"); `auto` picks by
  /// size and falls back on failure (when options.fallback). Never throws for non-convergence:
  /// the report says so.
  NormalSolution solve(const NormalSpec& control, const SolverOptions& solver,
                       const ProgressCallback& progress = {});
  /// The same into `solution`, whose storage it fills again: a solve repeated at every step of
  /// a run allocates nothing once its vectors and texts are sized.
  void solve(const NormalSpec& control, const SolverOptions& solver, NormalSolution& solution,
             const ProgressCallback& progress = {});
  /// A pressure from another form of this program (a finite body's sparse saddle form) finished
  /// by the active-set polish on it, to a hundredth of solver.certificate_tol: the solution and
  /// its certificate at the polished point (report.polished when the polish improved on it;
  /// the message says by how much).
  NormalSolution polish(const std::vector<double>& pressure, const NormalSpec& control, const SolverOptions& solver);
  /// Certificate of an arbitrary pressure field (for tests and for every solve).
  Certificate certify(const std::vector<double>& pressure, double approach, const NormalSpec& control) const;
  /// Rigid-body shift of the profile between solves (dynamic steps move the body).
  void set_heights(const std::vector<double>& heights);  // copied into the problem's own buffer
  /// Warm start: every converged solve starts the next one (load histories, time steps) from
  /// its pressure. set_warm_start() gives another starting pressure (Pa, one per element; the
  /// next solve starts there), clear_warm_start() makes the next solve cold.
  void set_warm_start(std::vector<double> pressure);
  void clear_warm_start() { warm_start_.clear(); }
  /// `auto` tries the native solver first whatever the size (time steps: every solve is one
  /// warm-started program, where native is the fastest); the others remain its fallbacks.
  void set_native_first(bool on) { native_first_ = on; }
  /// Ipopt with `solver.hessian` auto: the exact Hessian up to this many unknowns instead of
  /// SolveOptions' limit (measured on the half-space's FFT operator; a finite body's condensed
  /// compliance costs a pair of triangular solves per apply, its dense matrix one multi-column
  /// solve). 0: SolveOptions' own.
  void set_exact_hessian_limit(int unknowns) { exact_hessian_limit_ = unknowns; }

  const LinearOperator& compliance() const { return *compliance_; }
  const Grid& grid() const { return grid_; }
  const std::vector<double>& heights() const { return heights_; }

 private:
  /// solve(), or with `given` (a pressure per element) polish() instead of the backends.
  void solve_or_polish(const NormalSpec& control, const SolverOptions& solver, const ProgressCallback& progress,
                       const std::vector<double>* given, NormalSolution& result);

  /// solve()'s program, attempts, results and the native solver's vectors, filled again.
  struct SolveWork {
    QuadraticProgram qp;
    NormalSolution first, trial;
    AttemptLedger<NormalSolution> ledger;
    TimedOutcome run;
    std::vector<std::string> order;
    std::vector<double> w;  // C p of a point
    NativeNormalWorkspace native;
  };
  SolveWork work_;

  std::shared_ptr<const LinearOperator> compliance_;
  Grid grid_;
  std::vector<double> heights_;
  std::vector<double> warm_start_;
  mutable std::vector<double> certify_work_;  // certify()'s C p
  bool native_first_ = false;
  int exact_hessian_limit_ = 0;
  /// The native solver's FFT preconditioner: built at the first native solve, then reused.
  std::shared_ptr<const NormalPreconditioner> preconditioner_;
};

}  // namespace dc
