#pragma once
// The tangential problem (3.25)/(4.8) on top of the normal problem (4.7), with the outer
// loops for dissimilar materials (4.26)-(4.27) and pressure-dependent friction (3.31)-(3.32).
//
// Unknown tau (traction on the body, (2.1)) per element, |tau| <= f(p). Over one step the slip
// increment is ds = W + C_t tau ((3.8), (4.4)) with
//   W = rigid slip + kappa B21(p) - (relative tangential displacement of the previous step,
//       taken at the upstream material point when rolling),
// and tau minimises 1/2 tau'C_t tau + W'tau (KKT = friction law (2.4)-(2.5)).
// The rigid slip has three modes: x and y translation and rotation about z through the grid
// origin: s_rigid(x, y) = (a_x - a_z y, a_y + a_z x). Each mode is controlled either by its
// amplitude or by its resultant (F_x, F_y, M_z = sum (x tau_y - y tau_x) A); a prescribed
// resultant becomes an equality row and the amplitude its multiplier.
//
// Sign convention: tau and the reported forces are tractions ON THE BODY (tau+ of the paper);
// under a rigid shift of the body in +x the force is negative. Kalker's F_x = -G c^2 C11 xi.
// The paper's gap function (4.8)/(4.24) is written for the substrate's traction tau- = -tau+:
// g = sum [f(p)|ds| + tau+ . ds] A >= 0, = 0 exactly at the solution (4.25).
#include <array>
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <limits>
#include <vector>

#include "friction_law.hpp"
#include "linear_operator.hpp"
#include "normal_problem.hpp"
#include "solver_report.hpp"
#include "tangential_loads.hpp"

namespace dc {

struct OuterLoopReport {
  int iterations = 0;      ///< outer (p, tau) iterations
  double last_change = 0;  ///< relative change of (p, tau) in the last iteration
  /// kappa != 0: max |kappa B32 (tau - tau_in)| / (C_00 max p), the gap error the last
  /// tangential update leaves in the normal problem (the loop stops below certificate_tol / 100,
  /// and the pressure's certificate is that of the final tau)
  double coupling_residual = 0;
  /// kappa != 0: the coupling residual of the first pass (how far the starting point was)
  double first_residual = 0;
  bool converged = true;
};

struct TangentialSolution {
  NormalSolution normal;             ///< pressure, gap, approach, force and its report
  std::vector<double> tx, ty;        ///< tau (Pa), per element (2-D: ty = 0)
  std::vector<double> sx, sy;        ///< slip increment ds of the step (m) (rolling: per dx of travel)
  std::vector<double> bound;         ///< f(p) (Pa)
  std::vector<int> state;            ///< 0 free, 1 stick, 2 slip
  std::array<double, 3> amplitudes{};  ///< rigid modes (given or solved): shift x, y (m), angle (rad);
                                       ///< rolling: creepage x, y (-), spin (1/m)
  std::array<double, 3> resultants{};  ///< F_x, F_y (N; 2-D N/m), M_z (N m)
  int n_stick = 0, n_slip = 0;
  double stick_area = 0.0;           ///< m^2 (2-D: stick length, m)
  SolverReport report;               ///< the tangential solve; certificate has all residuals
  OuterLoopReport outer;             ///< (4.26)-(4.27) / (3.31)-(3.32)
  int marching_steps = 0;            ///< rolling: marching steps of dx (steady: to the steady state; 0: by Newton)
  int newton_iterations = 0;         ///< steady rolling by Newton: its iterations (all outer passes)
  bool rolling = false;              ///< amplitudes are creepages / spin (steady or transient rolling), not shifts
  double distance = 0.0;             ///< roll(): distance rolled, marching_steps * dx (m)
  bool shift_undetermined = false;   ///< no friction (mu = 0): the resultant-controlled rigid modes have no unique value
  /// Steady rolling: sum_e tau_e . (C - S C)(tau, p)_e A, the work of the steady slip's elastic
  /// part (2.19) per step of travel dx (J; 2-D J/m). With the rigid part's, sum_k alpha_k R_k dx,
  /// it makes up sum tau . ds A: the creep forces' power -(F_x xi + F_y eta + M_z phi) V is the
  /// frictional dissipation -sum tau . ds A V / dx plus this V / dx, the upwind scheme's part
  /// (O(dx): zero in the continuum, where the operator's convective form is antisymmetric).
  /// NaN for other solutions.
  double convective_elastic_work = std::numeric_limits<double>::quiet_NaN();
  /// roll() over a distance: the frictional work of all its marching steps, the sum of each
  /// one's frictional_work(step, area) (J; 2-D J/m; the fields above are the last step's). NaN
  /// for other solutions.
  double marched_frictional_work = std::numeric_limits<double>::quiet_NaN();
};

/// The frictional work of a solution's slip, -sum_e tau_e . ds_e A (J; 2-D J/m): >= 0 by the
/// friction law (2.4)-(2.5), zero where the contact sticks (rolling: per dx of travel).
double frictional_work(const TangentialSolution& s, double area);

/// Back to a default solution, the storage of its fields and reports kept (solver_report.hpp).
void reset_keeping_storage(TangentialSolution& solution);

/// A solution's traction in RollingLoad::warm_start's layout (tau_x of every element, then tau_y
/// in 3-D): the start of a steady-rolling solve at nearby data (a neighbouring table point, the
/// next dynamic step).
std::vector<double> rolling_warm_start(const TangentialSolution& solution, int dimension);
/// The same into `start` (its storage kept).
void rolling_warm_start(const TangentialSolution& solution, int dimension, std::vector<double>& start);

/// The loading history of a TangentialProblem (the state its next step starts from): saved
/// before a trial step and restored when the step is not accepted (dynamic steps).
struct TangentialMemory {
  std::vector<double> tau, pressure, warm_start;
  std::array<double, 3> amplitudes{};
  /// The relative displacement kappa B21 p + B22 tau of (tau, pressure) on the grid, as the
  /// step that left them computed it (empty: not known; a convected step then applies the
  /// operators to find it).
  std::vector<double> displacement;
};

struct SparseBlock;  // sparse_block.hpp

/// The sparse saddle form of a finite body (nlp/finite/saddle_form.hpp): the body's share of
/// the compliances kept as its sparse equilibrium rows, solved by the backends that take them.
struct SparseTangentialForm {
  /// The half-space's share of the tangential compliance: the program's Q.
  std::shared_ptr<const LinearOperator> halfspace;
  /// The body's rows for tractions in units of traction_unit (Pa), an objective in units of
  /// energy_unit (A tau'C tau) and resultants of the order of force_scale (N).
  std::function<SparseBlock(double traction_unit, double energy_unit, double force_scale)> body_rows;
  /// The normal problem by the sparse form on the given heights.
  std::function<NormalSolution(const std::vector<double>& heights, const NormalSpec& load, const SolverOptions& solver)>
      normal;
  /// The backends to try, in order, for a requested one.
  std::function<std::vector<std::string>(Backend requested, bool fallback)> backends;
  int exact_hessian_limit = 0;  ///< Ipopt: the exact Hessian up to this many tractions
  /// With backend `auto`, a step the backends above fail on is solved on the condensed program
  /// (the given compliances, the body's rows eliminated) by the native solver, then NLopt,
  /// reported as "native (condensed program)" or "nlopt (condensed program)" with fallback_used.
  bool condensed_fallback = false;
};

/// Set up once (operators, plans), then step: the state (previous relative displacement)
/// is kept between steps, so a sequence of loads is a loading history with memory.
class TangentialProblem {
 public:
  TangentialProblem(const Grid& grid, const MaterialPair& materials, std::vector<double> heights,
                    FrictionLaw friction, OperatorKind kind = OperatorKind::automatic);
  /// Given compliances (finite contact: half-space plus a finite body, nlp/finite/): normal
  /// (N x N) and tangential (2N x 2N in 3-D). No normal-tangential coupling (kappa = 0: the
  /// Goodman approximation) and quasi-static steps only (rolling throws InputError).
  TangentialProblem(const Grid& grid, std::shared_ptr<const LinearOperator> normal_compliance,
                    std::shared_ptr<const LinearOperator> tangential_compliance, std::vector<double> heights,
                    FrictionLaw friction);
  /// Movable, not copyable: a problem holds one loading history (a copy sharing it would
  /// silently step both).
  TangentialProblem(const TangentialProblem&) = delete;
  TangentialProblem& operator=(const TangentialProblem&) = delete;
  TangentialProblem(TangentialProblem&&) noexcept = default;
  TangentialProblem& operator=(TangentialProblem&&) noexcept = default;
  ~TangentialProblem() = default;

  /// One quasi-static step (shift/torsion/loading history).
  TangentialSolution step(const TangentialLoad& load, const SolverOptions& solver,
                          const ProgressCallback& progress = {});
  /// Steady rolling: Newton's method on the steady equations (steady_rolling_solver.hpp) or
  /// marching in time (dt = dx / V) until the traction stops changing; either way proven by the
  /// friction law and the gap function (4.24) of the steady slip.
  TangentialSolution steady_rolling(const RollingLoad& load, const SolverOptions& solver,
                                    const ProgressCallback& progress = {});
  /// The same into `solution`, whose storage the Newton path fills again (a dynamic run's steady
  /// model at every step).
  void steady_rolling(const RollingLoad& load, const SolverOptions& solver, TangentialSolution& solution,
                      const ProgressCallback& progress = {});
  /// Transient rolling: marches in +x from the CURRENT state (memory kept, no reset) over
  /// `distance` (m, >= 0): n = round(distance / dx) marching steps of dt = dx / V, at least one
  /// when distance > 0, each the convective step of steady_rolling() ((2.14), (3.8), (4.4)-(4.6)).
  /// Returns the state after the last step, amplitudes as creepages / spin of that step,
  /// marching_steps = n, distance = n dx. distance = 0 is one quasi-static step of the same
  /// controls instead (no convection, marching_steps = 0, amplitudes the rigid shift (m, m, rad)
  /// of that step): a prescribed force is then Cattaneo's shift, a creepage applies no slip.
  /// The total rigid slip accumulates in the state (a later step() shift counts from it).
  /// Throws InputError("tangential.distance") when distance < 0 or not finite.
  TangentialSolution roll(const RollingLoad& load, double distance, const SolverOptions& solver,
                          const ProgressCallback& progress = {});
  /// Forget the loading history (back to the unloaded state).
  void reset();
  /// `auto` tries the native solvers first for every solve, whatever the size (time stepping:
  /// every solve is warm-started, where they are the fastest); the others remain fallbacks.
  void set_native_first(bool on);
  /// Ipopt on these programs with `solver.hessian` auto: the exact Hessian up to this many grid
  /// elements (the normal problem's unknowns; the tangential program's, two per element in 3-D)
  /// instead of SolveOptions' limit (measured on the half-space's FFT operator). A finite body's
  /// condensed compliance costs a pair of triangular solves per apply, which limited memory
  /// spends by the thousand, and its dense matrix one multi-column solve.
  void set_exact_hessian_limit(int elements);
  /// Solve the normal problem and the tangential program by the sparse form (given compliances
  /// only): the certificates stay those of the condensed compliances.
  void use_sparse_form(SparseTangentialForm form);
  /// Keep the loading history but forget the starting points the next step would reuse (the
  /// last traction and pressure): the next step starts cold. For comparisons and tests.
  void forget_starting_points();
  /// kappa != 0, step(): a history whose load continues the last change in proportion starts
  /// from the state extrapolated from its last two steps (nlp/proportional_predictor.hpp); on by
  /// default, off: from the last step's state. For comparisons and tests.
  void set_extrapolation(bool on);
  /// The tangential program posed on the smallest window of the grid that holds f(p) > 0
  /// (nlp/support_window.hpp; the same program, a smaller transform); on by default for the
  /// half-space's own compliances. For comparisons and tests.
  void set_windowing(bool on);

  /// One step of a moving contact ((3.8), dynamic problems): the rigid-slip increments of the
  /// step given (x, y (m), rotation about z (rad)), the previous relative displacement taken
  /// `travel` = (travel_x, travel_y) (m, either sign) downstream - the material now at (x, y)
  /// was at (x + travel_x, y + travel_y) when the step began; not a whole number of elements:
  /// bilinear interpolation between the four neighbouring whole-element shifts (linear along x
  /// when travel_y = 0; their operators are built once per shift pair and kept). 2-D: travel_y
  /// must be 0 (InputError("travel") otherwise). The normal load is `normal` on the current
  /// heights. The memory advances (restore() to undo).
  TangentialSolution convected_step(const NormalSpec& normal, const std::array<double, 3>& increment,
                                    const std::array<double, 2>& travel, const SolverOptions& solver);
  /// The same into `solution`, whose storage it fills again (a dynamic run's every step).
  void convected_step(const NormalSpec& normal, const std::array<double, 3>& increment,
                      const std::array<double, 2>& travel, const SolverOptions& solver, TangentialSolution& solution);
  TangentialMemory memory() const;
  /// The same into `into`, reusing its vectors (a dynamic run's commit of every step).
  void save_memory(TangentialMemory& into) const;
  void restore(const TangentialMemory& memory);
  /// The same for the loading history alone: the next solve still starts from the traction of
  /// the last one (another trial of the same step starts near it, not at the last step's).
  void restore_history(const TangentialMemory& memory);
  /// The next solve's warm start is the answer of a solve at nearby data (another Newton trial
  /// of the step, or the last accepted time step): its alternation (4.26)-(4.27) starts with an
  /// exact pass instead of a loose one (a loose pass would return the start unchanged). Holds
  /// for one solve.
  void set_near_start(bool near);
  /// The body's gap profile on the grid (a moving body changes it between steps).
  void set_heights(const std::vector<double>& heights);  // copied into the problem's own buffer
  /// B22, the tangential compliance (sensitivities of a solution with its active set fixed).
  const LinearOperator& tangential_compliance() const;
  /// B31, the normal compliance.
  const LinearOperator& normal_compliance() const;
  /// kappa != 0 (dissimilar materials, (4.2)-(4.3)): the tangential displacement of a pressure,
  /// kappa B21, and the normal displacement of a traction, kappa B32; null when kappa = 0.
  const LinearOperator* tangential_from_normal() const;
  const LinearOperator* normal_from_tangential() const;
  /// Steady rolling's convective compliance B22 - S B22 (one element of travel), built on first use.
  const LinearOperator& convective_compliance();
  /// Its kappa term kappa (B21 - S B21), built on first use; null when kappa = 0.
  const LinearOperator* convective_from_normal();

  const Grid& grid() const { return grid_; }
  /// Certificate of a traction field for given slip increments and bounds (every solve, tests):
  /// friction law (2.4)-(2.5) as the fixed point tau = proj(tau - ds / c_t), relative to the
  /// traction level T = traction_scale(); gap function (4.24) relative to sum f A times the slip
  /// level max(max |ds|, c_t T). `compliance` c_t: slip per unit traction of one element (m/Pa).
  static Certificate certify_friction(const Grid& grid, const std::vector<double>& tx,
                                      const std::vector<double>& ty, const std::vector<double>& sx,
                                      const std::vector<double>& sy, const std::vector<double>& bound,
                                      double compliance);
  /// The traction level of a solution: max |tau| over the elements where friction acts.
  static double traction_scale(const std::vector<double>& tx, const std::vector<double>& ty,
                               const std::vector<double>& bound);

 private:
  struct Impl;
  std::shared_ptr<Impl> impl_;
  Grid grid_;
};

}  // namespace dc
