#pragma once
// Internal to nlp/, not installed: TangentialProblem::Impl, the operators, plans and loading
// history behind tangential_problem.hpp. Its member functions are defined by job in
// tangential_operators.cpp, _program.cpp, _certificates.cpp, _coupling.cpp (the outer loop
// (4.26)-(4.27)), _rolling.cpp and tangential_problem.cpp (the loading history).
#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <functional>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <tuple>
#include <utility>
#include <vector>

#include "anderson_mixing.hpp"
#include "backend_choice.hpp"
#include "certified_solve.hpp"
#include "native_solvers.hpp"
#include "proportional_predictor.hpp"
#include "steady_rolling_solver.hpp"
#include "support_window.hpp"
#include "tangential_problem.hpp"
#include "vector_ops.hpp"

namespace dc {
namespace tangential_internal {

/// Relative change between two fields (0 when both vanish).
inline double relative_change(const std::vector<double>& a, const std::vector<double>& b) {
  if (a.size() != b.size()) return 1.0;
  double d = 0.0;
  for (std::size_t i = 0; i < a.size(); ++i) d = std::max(d, std::abs(a[i] - b[i]));
  const double s = std::max(max_abs(a), max_abs(b));
  return s > 0.0 ? d / s : 0.0;
}

}  // namespace tangential_internal

/// Operators, plans and the loading history of one grid and material pair.
struct TangentialProblem::Impl {
  Grid grid;
  MaterialPair materials;
  FrictionLaw friction;
  OperatorKind kind;
  std::optional<HalfSpace> half_space;  // empty with given operators
  int comps;                         // tangential components: 1 (2-D) or 2 (3-D)
  std::size_t N;
  bool coupled;                      // kappa != 0: normal and tangential interact (4.26)-(4.27)
  std::shared_ptr<const LinearOperator> C;   // B31
  std::shared_ptr<const LinearOperator> Ct;  // B22
  bool given_operators = false;              // finite contact: C, Ct given, no rolling
  std::unique_ptr<LinearOperator> B21, B32;  // kappa terms (only when coupled)
  std::unique_ptr<LinearOperator> Ct_up, B21_up;  // rolling: upstream displacement
  std::unique_ptr<LinearOperator> D_conv;          // steady rolling: Ct - Ct_up
  std::unique_ptr<LinearOperator> D21_conv;        // its kappa term B21 - B21_up (sensitivities)
  // convected steps: kappa B21 p + B22 tau at the whole-element shifts around a step's travel,
  // (kx, ky) and (kx + 1, ky) (and (kx, ky + 1), (kx + 1, ky + 1) with a lateral travel), as one
  // weighted operator per (kx, ky, lateral), built once and kept
  std::map<std::tuple<int, int, bool>, std::unique_ptr<WeightedConvolutions>> convected;
  std::vector<double> convected_input;                       // (tau_prev, p_prev) stacked
  // kappa B21 p_prev + B22 tau_prev on the grid, left by the step that left (tau_prev, p_prev)
  // (empty: not known): the next step's convected memory (3.8) is interpolated from it
  // (interpolate_convected) instead of applied.
  std::vector<double> displacement_prev;
  // The elements whose interpolated memory needed a value beyond the grid's edge (taken from
  // the nearest element inside): exact only where no friction acts (solve_step checks).
  std::vector<std::size_t> memory_beyond_grid;
  std::vector<double> step_u_prev, step_W, step_w21, step_f, step_tau, step_ds;  // solve_step's
  mutable std::vector<double> displacement_work;             // displacement()'s kappa B21 p
  std::vector<double> final_heights_work;                    // certify_with_final_traction()'s gap
  std::vector<double> shift_source, shift_of_source;         // a traction and its kappa B32 (outer_loop)
  mutable std::vector<double> zero_component;                // step_certificate's y fields in 2-D
  std::vector<double> loop_p_old, loop_tau_old, loop_shift_in, loop_shift_out, pass_heights;  // outer_loop's
  AndersonMixing loop_mixer;                                 // outer_loop's, reset at its start
  std::unique_ptr<NormalProblem> normal;
  std::vector<double> heights;

  // Loading history: the state at the end of the last step.
  std::vector<double> tau_prev, p_prev;      // comps*N, N
  std::array<double, 3> amplitude_prev{};
  std::vector<double> tau_warm;              // warm start of the tangential program
  ProportionalPredictor predictor;           // step() histories with kappa != 0: extrapolated starts
  bool extrapolate = true;                   // set_extrapolation()
  bool windowing = true;                     // set_windowing()
  std::optional<WindowedCompliance> windows;  // Ct on windows of the grid (half-space operators only)
  std::unique_ptr<TangentialPreconditioner> Ct_preconditioner;  // grid_preconditioner()
  bool native_first = false;                 // auto while marching: native first at any size
  bool native_first_always = false;          // auto: native first for every solve (set_native_first)
  bool near_start = false;                   // the next solve starts near its answer (set_near_start)
  std::optional<SparseTangentialForm> sparse;  // a finite body's sparse saddle form (use_sparse_form)
  int exact_hessian_limit = 0;                 // set_exact_hessian_limit (0: SolveOptions' own)
  NativeTangentialWorkspace native_work;       // the native solver's vectors, kept between solves

  // The last normal solution and what it was solved for: rolling and histories with kappa = 0
  // ask for the same pressure at every step.
  std::optional<NormalSolution> normal_cache;
  std::vector<double> normal_cache_heights;
  NormalSpec normal_cache_load;
  double normal_cache_tol = 0.0;  // a loose alternation's pressure is no answer for an exact one

  // Operators and displacements (tangential_operators.cpp).
  Impl(const Grid& g, const MaterialPair& m, std::vector<double> h, FrictionLaw f, OperatorKind k);
  /// Given compliances (the finite-contact constructor), no coupling.
  Impl(const Grid& g, std::shared_ptr<const LinearOperator> normal_c, std::shared_ptr<const LinearOperator> tangential_c,
       std::vector<double> h, FrictionLaw f);

  /// Rigid-slip mode k at element e, component c: x, y translation, rotation about z.
  /// (Defined here, as n_modes: called per element in the loops of every file.)
  double mode(int k, std::size_t e, int c) const {
    const int i = static_cast<int>(e % grid.nx), j = static_cast<int>(e / grid.nx);
    if (k == 0) return c == 0 ? 1.0 : 0.0;
    if (k == 1) return c == 1 ? 1.0 : 0.0;
    return c == 0 ? -grid.yc(j) : grid.xc(i);
  }
  int n_modes() const { return grid.dimension == 2 ? 1 : 3; }

  /// Relative tangential displacement kappa B21 p + B22 tau (4.2).
  void displacement(const std::vector<double>& p, const std::vector<double>& tau, std::vector<double>& u,
                    const LinearOperator& ct, const LinearOperator* b21) const;
  /// The previous relative displacement convected by (shift_x, shift_y) elements (3.8):
  /// interpolated from displacement_prev when it is known (the elements that needed a value
  /// beyond the grid in memory_beyond_grid), else (or `exact`) one operator apply.
  void convected_displacement(double shift_x, double shift_y, std::vector<double>& u, bool exact = false);
  /// u_prev of (3.8) from displacement_prev, the weighted sum of its whole-element shifts.
  void interpolate_convected(int kx, int ky, double tx, double ty, std::vector<double>& u);
  /// The whole grid's tangential preconditioner (none for given operators or the sparse form).
  const TangentialPreconditioner* grid_preconditioner();

  // The program of one step and its certified solve (tangential_program.cpp).
  struct InnerResult {
    std::vector<double> tau;
    std::array<double, 3> increment{};  // rigid-mode increments of the step (given or solved)
    SolverReport report;
    bool shift_undetermined = false;    // frictionless: a resultant-controlled mode has no unique value
  };
  /// The largest resultant of mode k that friction can carry.
  double resultant_capacity(int k, const std::vector<double>& f) const;
  /// Prescribed resultants below what friction can carry, else gross sliding (InputError).
  void check_resultants(const std::vector<double>& f, const std::array<ModeControl, 3>& modes) const;
  /// The convex program of one step, solved and certified, into `result`.
  void solve_tangential(const std::vector<double>& W, const std::vector<double>& f,
                        const std::array<ModeControl, 3>& modes, const std::array<double, 3>& given_increment,
                        const SolverOptions& solver, const ProgressCallback& progress, InnerResult& result);
  /// solve_tangential's program, attempts, results and certificate vectors, filled again at
  /// every solve (its native solver writes into `run`'s outcome).
  struct ProgramWork {
    QuadraticProgram qp;
    InnerResult first, trial;
    AttemptLedger<InnerResult> ledger;
    TimedOutcome run;
    std::vector<std::string> order;
    std::vector<double> ds, ct_tau;
  };
  ProgramWork program_work;
  NativeSolverInto native_solver = [this](const QuadraticProgram& q, const SolveOptions& o, SolveOutcome& out) {
    solve_tangential_native(q, o, native_work, out);
  };
  InnerResult step_inner;  // solve_step's inner solve
  /// No friction anywhere (f(p) = 0): tau = 0, nothing to solve.
  InnerResult frictionless(const std::array<double, 3>& given_increment, const std::array<ModeControl, 3>& modes,
                           const SolverOptions& solver) const;

  // Slip, resultants and certificates (tangential_certificates.cpp).
  /// The slip increment of a step (3.8): ds = W + rigid + Ct tau.
  std::vector<double> slip_increment(const std::vector<double>& W, const std::vector<double>& tau,
                                     const std::array<double, 3>& increment) const;
  /// The same into ds, and Ct tau into ct_tau (no allocation once they are sized).
  void slip_increment(const std::vector<double>& W, const std::vector<double>& tau,
                      const std::array<double, 3>& increment, std::vector<double>& ds,
                      std::vector<double>& ct_tau) const;
  /// ds += W + rigid slip of the increments (3.8).
  void add_rigid_and_load(const std::vector<double>& W, const std::array<double, 3>& increment,
                          std::vector<double>& ds) const;
  /// The slip increment (3.8) of a traction that vanishes outside `window`, into ds.
  void windowed_slip_increment(const std::vector<double>& W, const std::vector<double>& tau,
                               const SupportWindow& window, const LinearOperator& ct_window,
                               const std::array<double, 3>& increment, std::vector<double>& ds) const;
  mutable std::vector<double> window_tau_work, window_ds_work;  // windowed_slip_increment's
  /// Resultants F_x, F_y, M_z of a traction field.
  std::array<double, 3> resultants(const std::vector<double>& tau) const;
  /// The tangential certificate of a step: friction law, gap function, prescribed resultants.
  Certificate step_certificate(const std::vector<double>& tau, const std::vector<double>& ds,
                               const std::vector<double>& f, const std::array<ModeControl, 3>& modes) const;
  /// Fills a solution's fields, states, resultants and certificate.
  void finish(TangentialSolution& sol, const std::vector<double>& tau, const std::vector<double>& ds,
              const std::vector<double>& f, const std::array<ModeControl, 3>& modes, const SolverOptions& solver) const;

  // The outer loop (4.26)-(4.27) / (3.31)-(3.32) and one step (tangential_coupling.cpp).
  /// The inner solve of a pass: (p, f(p), tau, the pass's solver) -> tau updated; false: give up.
  using InnerSolve = std::function<bool(const std::vector<double>& p, const std::vector<double>& f,
                                        std::vector<double>& tau, const SolverOptions& pass)>;
  /// The normal problem at the heights h, from normal_cache when it was solved for the same.
  const NormalSolution& solve_normal(const std::vector<double>& h, const NormalSpec& load, const SolverOptions& solver);
  /// The outer loop around `inner` (false: the inner solve gave up).
  bool outer_loop(TangentialSolution& sol, const NormalSpec& normal_load, const SolverOptions& solver,
                  std::vector<double>& tau, std::vector<double>& f, bool inexact, const InnerSolve& inner);
  /// The pressure's certificate with the gap (4.26) of the final tau.
  void certify_with_final_traction(TangentialSolution& sol, const std::vector<double>& shift_out,
                                   const NormalSpec& normal_load);
  /// The solver of an inexact alternation: tolerance `tol`.
  static SolverOptions loose_pass(const SolverOptions& solver, double tol);
  /// One step with the outer loop into `sol` (its storage kept); `shift` (elements) the travel.
  void solve_step(const NormalSpec& normal_load, const std::array<ModeControl, 3>& modes,
                  const std::array<double, 3>& given_increment, const std::array<double, 2>& shift,
                  const SolverOptions& solver, const ProgressCallback& progress, TangentialSolution& sol);

  // Rolling (tangential_rolling.cpp).
  /// Steady rolling by Newton inside the outer loop into `sol`; false when Newton gives up
  /// (why_not).
  bool steady_rolling_direct(const RollingLoad& load, const std::array<double, 3>& given_increment,
                             const SolverOptions& solver, const ProgressCallback& progress, std::string& why_not,
                             TangentialSolution& sol);
  /// steady_rolling_direct's program, outcome and solver, filled again at every solve.
  struct SteadyWork {
    SteadyRollingProgram program;
    SteadyRollingOutcome outcome;
    SteadyRollingWorkspace solver;
    std::vector<int> unknown_modes;
    std::vector<double> w_here, w_up;
  };
  SteadyWork steady_work;
  struct March {
    TangentialSolution sol;  ///< the last step; amplitudes = rigid-mode increments of that step
    int steps = 0;           ///< marching steps done
    bool steady = false;     ///< stopped because a step changed tau by less than steady_tol
    int first_unconverged = 0;  ///< the first step that was not certified (1-based), 0: none
    double frictional_work = 0.0;  ///< of every step done, -sum tau . ds A each (J)
  };
  /// Rolling in +x from the current state: up to `max_steps` marching steps.
  March march(const RollingLoad& load, int max_steps, double steady_tol, const SolverOptions& solver,
              const ProgressCallback& progress);

  // The loading history (tangential_problem.cpp).
  void reset();
};

}  // namespace dc
