#include "tangential_problem.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <map>
#include <limits>
#include <numeric>
#include <optional>
#include <stdexcept>

#include "active_set_polish.hpp"
#include "anderson_mixing.hpp"
#include "support_window.hpp"
#include "backend_choice.hpp"
#include "certified_solve.hpp"
#include "errors.hpp"
#include "fault_injection.hpp"
#include "native_solvers.hpp"
#include "proportional_predictor.hpp"
#include "scaled_operator.hpp"
#include "sparse_block.hpp"
#include "steady_rolling_solver.hpp"
#include "vector_ops.hpp"

namespace dc {
namespace {

/// Relative change between two fields (0 when both vanish).
double relative_change(const std::vector<double>& a, const std::vector<double>& b) {
  if (a.size() != b.size()) return 1.0;
  double d = 0.0;
  for (std::size_t i = 0; i < a.size(); ++i) d = std::max(d, std::abs(a[i] - b[i]));
  const double s = std::max(max_abs(a), max_abs(b));
  return s > 0.0 ? d / s : 0.0;
}

}  // namespace

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
  // convected steps: Ct and kappa B21 shifted by whole elements (kx, ky), built once per shift
  // pair and kept (a step interpolates between at most four of them)
  struct ShiftedCompliance {
    std::unique_ptr<LinearOperator> ct, b21;
  };
  std::map<std::pair<int, int>, ShiftedCompliance> shifted;
  std::vector<double> convected_row_work, convected_x_work;  // convected_displacement's buffers
  mutable std::vector<double> displacement_work;             // displacement()'s kappa B21 p
  std::vector<double> final_heights_work;                    // certify_with_final_traction()'s gap
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
  std::optional<SparseTangentialForm> sparse;  // a finite body's sparse saddle form (use_sparse_form)
  int exact_hessian_limit = 0;                 // set_exact_hessian_limit (0: SolveOptions' own)
  NativeTangentialWorkspace native_work;       // the native solver's vectors, kept between solves

  Impl(const Grid& g, const MaterialPair& m, std::vector<double> h, FrictionLaw f, OperatorKind k)
      : grid(g), materials(m), friction(std::move(f)), kind(k), half_space(std::in_place, g, m),
        comps(g.dimension == 2 ? 1 : 2), N(g.size()), coupled(m.kappa() != 0.0),
        heights(std::move(h)) {
    C = half_space->normal(kind);
    Ct = half_space->tangential(kind);
    if (coupled) {
      B21 = half_space->tangential_from_normal(kind);
      B32 = half_space->normal_from_tangential(kind);
    }
    normal = std::make_unique<NormalProblem>(C, grid, heights);
    reset();
  }

  /// Given compliances (the finite-contact constructor), no coupling.
  Impl(const Grid& g, std::shared_ptr<const LinearOperator> normal_c, std::shared_ptr<const LinearOperator> tangential_c,
       std::vector<double> h, FrictionLaw f)
      : grid(g), materials{Elastic::make_rigid(), Elastic::make_rigid()}, friction(std::move(f)),
        kind(OperatorKind::automatic),
        comps(g.dimension == 2 ? 1 : 2), N(g.size()), coupled(false), given_operators(true), heights(std::move(h)) {
    C = std::move(normal_c);
    Ct = std::move(tangential_c);
    if (Ct->rows() != comps * N || Ct->cols() != comps * N)
      throw std::invalid_argument("tangential problem: the tangential compliance does not fit the grid");
    normal = std::make_unique<NormalProblem>(C, grid, heights);
    reset();
  }

  void reset() {
    tau_prev.assign(comps * N, 0.0);
    p_prev.assign(N, 0.0);
    amplitude_prev = {0.0, 0.0, 0.0};
    tau_warm.clear();
    predictor.clear();
  }

  /// Rigid-slip mode k at element e, component c: x, y translation, rotation about z.
  double mode(int k, std::size_t e, int c) const {
    const int i = static_cast<int>(e % grid.nx), j = static_cast<int>(e / grid.nx);
    if (k == 0) return c == 0 ? 1.0 : 0.0;
    if (k == 1) return c == 1 ? 1.0 : 0.0;
    return c == 0 ? -grid.yc(j) : grid.xc(i);
  }
  int n_modes() const { return grid.dimension == 2 ? 1 : 3; }

  /// Relative tangential displacement of (p, tau): kappa B21 p + B22 tau (4.2).
  void displacement(const std::vector<double>& p, const std::vector<double>& tau, std::vector<double>& u,
                    const LinearOperator& ct, const LinearOperator* b21) const {
    ct.apply(tau, u);
    if (coupled && b21) {
      std::vector<double>& w = displacement_work;
      b21->apply(p, w);
      for (std::size_t i = 0; i < u.size(); ++i) u[i] += w[i];
    }
  }

  /// The previous relative displacement taken (shift_x, shift_y) elements downstream (the
  /// material now at (x, y) was at (x + shift_x dx, y + shift_y dy) at the start of the step,
  /// (3.8)): bilinear interpolation between the four neighbouring whole-element shifts, each exact
  /// also beyond the grid edge. shift_y = 0 is the linear interpolation along x alone (the same
  /// arithmetic, bit for bit, as before y was convected).
  void convected_displacement(double shift_x, double shift_y, std::vector<double>& u) {
    interpolate(shift_y, u, convected_row_work, [&](int ky, std::vector<double>& row) {
      interpolate(shift_x, row, convected_x_work, [&](int kx, std::vector<double>& out) {
        shifted_displacement(kx, ky, out);
      });
    });
  }

  /// u at the shift s (elements) along one axis: linear interpolation between the neighbouring
  /// whole-element shifts, at_whole(k, out) filling out at the shift k; `work` holds the second.
  template <class AtWhole>
  static void interpolate(double s, std::vector<double>& u, std::vector<double>& work, AtWhole&& at_whole) {
    const int k = static_cast<int>(std::floor(s));
    const double theta = s - k;
    at_whole(k, u);
    if (theta <= 0.0) return;
    at_whole(k + 1, work);
    for (std::size_t i = 0; i < u.size(); ++i) u[i] = (1.0 - theta) * u[i] + theta * work[i];
  }

  /// The previous relative displacement at the whole-element shift (kx, ky).
  void shifted_displacement(int kx, int ky, std::vector<double>& out) {
    if (kx == 0 && ky == 0) return displacement(p_prev, tau_prev, out, *Ct, B21.get());
    ShiftedCompliance& ops = shifted[{kx, ky}];
    if (!ops.ct) {
      ops.ct = half_space->tangential_shifted(kx, ky, kind);
      if (coupled) ops.b21 = half_space->tangential_from_normal_shifted(kx, ky, kind);
    }
    displacement(p_prev, tau_prev, out, *ops.ct, ops.b21.get());
  }

  // The last normal solution and what it was solved for: rolling and histories with kappa = 0
  // ask for the same pressure at every step.
  std::optional<NormalSolution> normal_cache;
  std::vector<double> normal_cache_heights;
  NormalSpec normal_cache_load;
  double normal_cache_tol = 0.0;  // a loose alternation's pressure is no answer for an exact one

  NormalSolution solve_normal(std::vector<double> h, const NormalSpec& load, const SolverSpec& solver) {
    if (normal_cache && normal_cache_load.control == load.control && normal_cache_load.value == load.value &&
        normal_cache_tol == solver.tol &&
        normal_cache_heights == h)
      return *normal_cache;
    normal->set_heights(h);
    normal->set_native_first(native_first || native_first_always);
    NormalSolution s = sparse ? sparse->normal(h, load, solver) : normal->solve(load, solver);
    normal_cache = s;
    normal_cache_heights = std::move(h);
    normal_cache_load = load;
    normal_cache_tol = solver.tol;
    return s;
  }

  struct InnerResult {
    std::vector<double> tau;
    std::array<double, 3> increment{};  // rigid-mode increments of the step (given or solved)
    SolverReport report;
    bool shift_undetermined = false;    // frictionless: a resultant-controlled mode has no unique value
  };

  /// The whole grid's tangential preconditioner (built on first use); none for given operators
  /// (a finite body's compliance is not translation invariant) or the sparse form.
  const TangentialPreconditioner* grid_preconditioner() {
    if (!half_space || sparse) return nullptr;
    if (!Ct_preconditioner) Ct_preconditioner = std::make_unique<TangentialPreconditioner>(*Ct, grid);
    return Ct_preconditioner.get();
  }

  /// The largest resultant of mode k that friction can carry: sum_e f_e |m_k(e)| A.
  double resultant_capacity(int k, const std::vector<double>& f) const {
    double capacity = 0.0;
    for (std::size_t e = 0; e < N; ++e) {
      double m2 = 0.0;
      for (int c = 0; c < comps; ++c) m2 += mode(k, e, c) * mode(k, e, c);
      capacity += f[e] * std::sqrt(m2) * grid.area();
    }
    return capacity;
  }

  /// Prescribed resultants must stay below what friction can carry, each alone and the force
  /// (F_x, F_y) together; reaching it is gross sliding (no quasi-static or steady solution).
  void check_resultants(const std::vector<double>& f, const std::array<ModeControl, 3>& modes) const {
    static const char* names[] = {"tangential.force[0]", "tangential.force[1]", "tangential.moment"};
    auto sliding = [](const char* key, double value, double capacity) {
      throw InputError(key, "the prescribed resultant " + format_number(value) + " reaches the friction limit " +
                                format_number(capacity) + ": gross sliding, no quasi-static or steady solution");
    };
    if (std::none_of(modes.begin(), modes.begin() + n_modes(),
                     [](const ModeControl& m) { return m.kind == ModeControl::Kind::resultant; }))
      return;
    double total = 0.0;
    for (std::size_t e = 0; e < N; ++e) total += f[e] * grid.area();
    if (!(total > 0.0)) {  // frictionless (mu = 0) or unloaded: only zero resultants have a solution
      for (int k = 0; k < n_modes(); ++k)
        if (modes[k].kind == ModeControl::Kind::resultant && modes[k].value != 0.0)
          throw InputError(names[k], "the prescribed resultant " + format_number(modes[k].value) +
                                         " cannot be carried: the friction bound f(p) is 0 over the whole contact "
                                         "(mu = 0 or no load), so any tangential load is gross sliding, no "
                                         "quasi-static or steady solution");
      return;
    }
    for (int k = 0; k < n_modes(); ++k) {
      if (modes[k].kind != ModeControl::Kind::resultant) continue;
      const double capacity = resultant_capacity(k, f);
      if (std::abs(modes[k].value) >= capacity * (1.0 - 1e-12)) sliding(names[k], modes[k].value, capacity);
    }
    if (n_modes() == 3 && modes[0].kind == ModeControl::Kind::resultant && modes[1].kind == ModeControl::Kind::resultant) {
      const double F = std::hypot(modes[0].value, modes[1].value);
      if (F >= total * (1.0 - 1e-12)) sliding("tangential.force", F, total);
    }
  }

  /// The convex program of one step: min 1/2 tau'Ct tau + W'tau over |tau| <= f, with the
  /// resultant-controlled modes as equality rows; W excludes the resultant-controlled modes.
  InnerResult solve_tangential(const std::vector<double>& W, const std::vector<double>& f,
                               const std::array<ModeControl, 3>& modes, const std::array<double, 3>& given_increment,
                               const SolverSpec& solver, const ProgressCallback& progress) {
    const double A = grid.area();
    const double ct0 = Ct->diagonal(0);
    const double f_ref = std::max(max_abs(f), 1e-300);
    const std::size_t n = comps * N;
    // The program's elements: the grid, or a window of it that holds f > 0 (the same program:
    // tau is 0 wherever f is). The sparse form: Q the half-space's share, the body's in the
    // block's rows.
    SupportWindow window;
    if (windowing && half_space && !sparse) window = support_window(grid, f);
    const bool windowed = window.nx > 0;
    if (windowed && !windows) windows.emplace(grid, materials, kind);
    const std::size_t Nw = windowed ? window.size() : N, nw = comps * Nw;
    const auto element = [&](std::size_t l) { return windowed ? window.global(grid, l) : l; };
    const WindowOperators* ops = windowed ? &windows->operators(window) : nullptr;
    ScaledOperator Q(ops ? *ops->compliance : sparse ? *sparse->halfspace : *Ct, 1.0 / ct0);
    // The FFT preconditioner of the half-space's own compliance (Q^-1 = ct0 B22^-1).
    const TangentialPreconditioner* preconditioner = ops ? ops->preconditioner.get() : grid_preconditioner();
    std::optional<ScaledOperator> Q_inverse;
    if (preconditioner) Q_inverse.emplace(*preconditioner, ct0);
    QuadraticProgram qp;
    qp.Q = &Q;
    if (Q_inverse) qp.preconditioner = &*Q_inverse;
    qp.c.resize(nw);
    qp.lower.assign(nw, -kInf);
    qp.upper.assign(nw, kInf);
    for (std::size_t l = 0; l < Nw; ++l) {
      const std::size_t e = element(l);
      for (int c = 0; c < comps; ++c) {
        double w = W[c * N + e];
        for (int k = 0; k < n_modes(); ++k)
          if (modes[k].kind == ModeControl::Kind::amplitude) w += given_increment[k] * mode(k, e, c);
        qp.c[c * Nw + l] = w / (ct0 * f_ref);
      }
      const double r = f[e] / f_ref;
      if (r <= 0.0) {
        for (int c = 0; c < comps; ++c) qp.lower[c * Nw + l] = qp.upper[c * Nw + l] = 0.0;
      } else if (comps == 1) {
        qp.lower[l] = -r;
        qp.upper[l] = r;
      } else {
        qp.disks.push_back({static_cast<int>(l), static_cast<int>(Nw + l), r});
      }
    }
    check_resultants(f, modes);
    std::vector<int> row_mode;
    std::vector<double> row_scale;
    for (int k = 0; k < n_modes(); ++k) {
      if (modes[k].kind != ModeControl::Kind::resultant) continue;
      // Row sum_e mode_k . tau A = R_k, scaled by the largest resultant friction can carry.
      const double capacity = resultant_capacity(k, f);
      LinearEquality eq;
      eq.a.assign(nw, 0.0);
      for (std::size_t l = 0; l < Nw; ++l)
        for (int c = 0; c < comps; ++c) eq.a[c * Nw + l] = mode(k, element(l), c) * A * f_ref / capacity;
      eq.b = modes[k].value / capacity;
      qp.equalities.push_back(std::move(eq));
      row_mode.push_back(k);
      row_scale.push_back(capacity);
    }
    if (tau_warm.size() == n) {
      qp.x0.resize(nw);
      for (std::size_t l = 0; l < Nw; ++l)
        for (int c = 0; c < comps; ++c) qp.x0[c * Nw + l] = tau_warm[c * N + element(l)] / f_ref;
    }
    SolveOptions options = solve_options(solver, progress);
    if (exact_hessian_limit > 0) options.exact_hessian_limit = exact_hessian_limit;
    SparseBlock body_rows;
    if (sparse) {
      const double n_active = static_cast<double>(std::count_if(f.begin(), f.end(), [](double b) { return b > 0.0; }));
      body_rows = sparse->body_rows(f_ref, A * ct0 * f_ref * f_ref, f_ref * A * std::max(1.0, 0.25 * n_active));
      qp.block = &body_rows;
      options.exact_hessian_limit = sparse->exact_hessian_limit;
    }
    if (std::all_of(f.begin(), f.end(), [](double b) { return b <= 0.0; })) return frictionless(given_increment, modes, solver);

    InnerResult first;
    first.report.requested = solver.backend;
    first.report.operator_kind = sparse ? "sparse+" + sparse->halfspace->kind() : Ct->kind();
    first.increment = given_increment;
    AttemptLedger<InnerResult> ledger(first);
    // The condensed program: the same program with the body's rows eliminated (Q the condensed
    // compliance, no block); the program itself when it has no block (no copy).
    ScaledOperator condensed_q(*Ct, 1.0 / ct0);
    QuadraticProgram sparse_condensed;
    if (sparse) {
      sparse_condensed = qp;
      sparse_condensed.Q = &condensed_q;
      sparse_condensed.block = nullptr;
      sparse_condensed.preconditioner = nullptr;
    }
    const QuadraticProgram& condensed = sparse ? sparse_condensed : qp;
    // A point of the program (x, its equality multipliers) as tractions and rigid increments,
    // certified on the condensed compliances.
    const auto certify_point = [&](const std::vector<double>& x, const std::vector<double>& multipliers,
                                   InnerResult& trial) {
      SolverReport& rep = trial.report;
      trial.increment = given_increment;
      trial.tau.assign(n, 0.0);
      for (std::size_t l = 0; l < Nw; ++l)
        for (int c = 0; c < comps; ++c) trial.tau[c * N + element(l)] = x[c * Nw + l] * f_ref;
      // Project onto the friction set (interior-point iterates may sit a hair outside).
      for (std::size_t e = 0; e < N; ++e) {
        double m2 = 0.0;
        for (int c = 0; c < comps; ++c) m2 += trial.tau[c * N + e] * trial.tau[c * N + e];
        const double mag = std::sqrt(m2);
        if (mag > f[e])
          for (int c = 0; c < comps; ++c) trial.tau[c * N + e] *= f[e] > 0.0 ? f[e] / mag : 0.0;
      }
      for (std::size_t r = 0; r < row_mode.size() && r < multipliers.size(); ++r)
        // Stationarity: (Ct tau + W)/(ct0 f_ref) + alpha m/(ct0 f_ref) = lambda a, a = m A f_ref / S
        trial.increment[row_mode[r]] = -multipliers[r] * A * f_ref * f_ref * ct0 / row_scale[r];
      // Our own certificate decides, as for the normal problem: `auto` falls back on it.
      // On a window the slip is computed there alone: tau = 0 and f = 0 outside, where the
      // certificate does not look at the slip (certify_friction).
      rep.certificate = step_certificate(
          trial.tau,
          ops ? windowed_slip_increment(W, trial.tau, window, *ops->compliance, trial.increment)
              : slip_increment(W, trial.tau, trial.increment),
          f, modes);
      const bool certified = rep.certificate.worst() <= solver.certificate_tol;
      rep.status = certified ? SolveStatus::converged : SolveStatus::not_converged;
    };
    // One backend on a program (the sparse form's or the condensed one), certified; the ledger
    // keeps the first certified result, else the best certificate.
    const auto attempt = [&](const std::string& backend, const QuadraticProgram& program, bool fallback,
                             const std::string& label) {
      const TimedOutcome run =
          run_backend(backend, program, options, [this](const QuadraticProgram& q, const SolveOptions& o) {
            return solve_tangential_native(q, o, native_work);
          });
      const SolveOutcome& out = run.outcome;
      InnerResult trial = first;
      SolverReport& rep = trial.report;
      rep.operator_kind = program.block ? "sparse+" + sparse->halfspace->kind() : Ct->kind();
      rep.backend = label;
      rep.fallback_used = fallback;
      rep.message = out.message;
      rep.iterations = out.iterations;
      rep.polished = out.polished;
      rep.time_s = run.time_s;
      rep.objective = out.objective * ct0 * f_ref * f_ref * A;
      rep.status = SolveStatus::failed;
      const bool has_point = out.x.size() == nw;
      if (has_point) {
        certify_point(out.x, out.equality_multipliers, trial);
        // Polished on the condensed program: its KKT residual is the friction law's (the same
        // compliance ct0 and level f_ref); each active set's solves cost some hundred applies,
        // each a pair of triangular solves on a finite body.
        const auto polished = finish_backend_point(backend, out, condensed, solver.certificate_tol, trial, certify_point);
        if (polished) rep.objective = condensed.objective(polished->data()) * ct0 * f_ref * f_ref * A;
      }
      ledger.record(std::move(trial), has_point, out.history);
    };
    const auto order = sparse ? sparse->backends(solver.backend, solver.fallback) : backend_order(solver.backend, native_first || native_first_always ? std::numeric_limits<std::size_t>::max() : n,
                      solver.fallback);
    for (std::size_t k = 0; k < order.size() && !ledger.converged(); ++k) attempt(order[k], qp, k > 0, order[k]);
    // The sparse form failed with `auto`: the same program with the body's rows eliminated (Q the
    // condensed compliance, no block), as for the normal problem (FiniteContact::solve_sparse).
    if (sparse && sparse->condensed_fallback && !ledger.converged() && solver.backend == "auto" && solver.fallback) {
      for (const char* backend : {"native", "nlopt"}) {
        attempt(backend, condensed, true, std::string(backend) + " (condensed program)");
        if (ledger.converged()) break;
      }
    }
    InnerResult best = std::move(ledger).finish();
    if (best.tau.empty()) best.tau.assign(n, 0.0);  // every backend failed: nothing to keep
    return best;
  }

  /// No friction anywhere (f(p) = 0: mu = 0): nothing to solve, tau = 0. Only zero resultants
  /// reach here (check_resultants); the rigid increment of a resultant-controlled mode is then
  /// undetermined (any shift leaves tau = 0) and reported as 0.
  InnerResult frictionless(const std::array<double, 3>& given_increment, const std::array<ModeControl, 3>& modes,
                           const SolverSpec& solver) const {
    InnerResult r;
    r.tau.assign(comps * N, 0.0);
    r.increment = given_increment;
    r.report.backend = "none";
    r.report.requested = solver.backend;
    r.report.operator_kind = Ct->kind();
    r.report.status = SolveStatus::converged;
    r.report.message = "no friction (f(p) = 0 over the whole contact): zero traction, nothing to solve";
    r.shift_undetermined = std::any_of(modes.begin(), modes.begin() + n_modes(), [](const ModeControl& m) {
      return m.kind == ModeControl::Kind::resultant;
    });
    if (r.shift_undetermined)
      r.report.message += "; the rigid shift is undetermined (any shift leaves the traction at 0; reported as 0)";
    return r;
  }

  /// The slip increment of a step (3.8): ds = W + rigid + Ct tau, rigid = sum_k increment_k mode_k.
  std::vector<double> slip_increment(const std::vector<double>& W, const std::vector<double>& tau,
                                     const std::array<double, 3>& increment) const {
    std::vector<double> ds;
    Ct->apply(tau, ds);
    for (std::size_t e = 0; e < N; ++e)
      for (int c = 0; c < comps; ++c) {
        double rigid = 0.0;
        for (int k = 0; k < n_modes(); ++k) rigid += increment[k] * mode(k, e, c);
        ds[c * N + e] += W[c * N + e] + rigid;
      }
    return ds;
  }

  /// The slip increment (3.8) of a traction that vanishes outside `window`, computed on the
  /// window's elements; W + rigid outside (where f = 0, so tau = 0 and the slip is not certified).
  std::vector<double> windowed_slip_increment(const std::vector<double>& W, const std::vector<double>& tau,
                                              const SupportWindow& window, const LinearOperator& ct_window,
                                              const std::array<double, 3>& increment) const {
    const std::size_t Nw = window.size();
    std::vector<double> ds(comps * N), tau_window(comps * Nw), ds_window;
    for (std::size_t l = 0; l < Nw; ++l)
      for (int c = 0; c < comps; ++c) tau_window[c * Nw + l] = tau[c * N + window.global(grid, l)];
    ct_window.apply(tau_window, ds_window);
    for (std::size_t e = 0; e < N; ++e)
      for (int c = 0; c < comps; ++c) {
        double rigid = 0.0;
        for (int k = 0; k < n_modes(); ++k) rigid += increment[k] * mode(k, e, c);
        ds[c * N + e] = W[c * N + e] + rigid;
      }
    for (std::size_t l = 0; l < Nw; ++l)
      for (int c = 0; c < comps; ++c) ds[c * N + window.global(grid, l)] += ds_window[c * Nw + l];
    return ds;
  }

  /// Resultants F_x, F_y, M_z of a traction field.
  std::array<double, 3> resultants(const std::vector<double>& tau) const {
    std::array<double, 3> r{0.0, 0.0, 0.0};
    for (std::size_t e = 0; e < N; ++e)
      for (int k = 0; k < n_modes(); ++k)
        for (int c = 0; c < comps; ++c) r[k] += mode(k, e, c) * tau[c * N + e] * grid.area();
    return r;
  }

  /// The tangential certificate of a step: friction law and gap function (certify_friction), and
  /// the prescribed resultants, relative to the resultant itself or, when that is 0, to what the
  /// traction level could carry (T sum |m_k| A).
  Certificate step_certificate(const std::vector<double>& tau, const std::vector<double>& ds,
                               const std::vector<double>& f, const std::array<ModeControl, 3>& modes) const {
    std::vector<double> tx(tau.begin(), tau.begin() + static_cast<std::ptrdiff_t>(N)), ty(N, 0.0);
    std::vector<double> sx(ds.begin(), ds.begin() + static_cast<std::ptrdiff_t>(N)), sy(N, 0.0);
    if (comps == 2) {
      ty.assign(tau.begin() + static_cast<std::ptrdiff_t>(N), tau.end());
      sy.assign(ds.begin() + static_cast<std::ptrdiff_t>(N), ds.end());
    }
    Certificate cert = TangentialProblem::certify_friction(grid, tx, ty, sx, sy, f, Ct->diagonal(0));
    const double T = TangentialProblem::traction_scale(tx, ty, f);
    const std::array<double, 3> r = resultants(tau);
    for (int k = 0; k < n_modes(); ++k) {
      if (modes[k].kind != ModeControl::Kind::resultant) continue;
      double reach = 0.0;
      for (std::size_t e = 0; e < N; ++e)
        if (f[e] > 0.0) {
          double m2 = 0.0;
          for (int c = 0; c < comps; ++c) m2 += mode(k, e, c) * mode(k, e, c);
          reach += T * std::sqrt(m2) * grid.area();
        }
      const double scale = std::max(std::abs(modes[k].value), reach);
      const double miss = std::abs(r[k] - modes[k].value);
      cert.force_residual = std::max(cert.force_residual, scale > 0.0 ? miss / scale : miss > 0.0 ? 1.0 : 0.0);
    }
    return cert;
  }

  /// Fills the fields, states, resultants and the certificate of a solution from tau, the slip
  /// ds and the bound f; the status becomes not_converged when the certificate fails.
  void finish(TangentialSolution& sol, const std::vector<double>& tau, const std::vector<double>& ds,
              const std::vector<double>& f, const std::array<ModeControl, 3>& modes, const SolverSpec& solver) const {
    sol.tx.assign(N, 0.0);
    sol.ty.assign(N, 0.0);
    sol.sx.assign(N, 0.0);
    sol.sy.assign(N, 0.0);
    sol.bound = f;
    sol.state.assign(N, 0);
    sol.n_stick = sol.n_slip = 0;
    sol.stick_area = 0.0;
    for (std::size_t e = 0; e < N; ++e) {
      sol.tx[e] = tau[e];
      sol.sx[e] = ds[e];
      if (comps == 2) {
        sol.ty[e] = tau[N + e];
        sol.sy[e] = ds[N + e];
      }
    }
    const double A = grid.area();
    // Slip against the slip of the traction level (never against the bound: full stick at huge mu).
    const double slip_scale = Ct->diagonal(0) * TangentialProblem::traction_scale(sol.tx, sol.ty, f);
    for (std::size_t e = 0; e < N; ++e) {
      if (f[e] <= 0.0) continue;
      const bool slipping = std::hypot(sol.sx[e], sol.sy[e]) > 1e-5 * slip_scale;
      sol.state[e] = slipping ? 2 : 1;
      (slipping ? sol.n_slip : sol.n_stick) += 1;
      if (!slipping) sol.stick_area += A;
    }
    sol.resultants = resultants(tau);
    const Certificate friction = step_certificate(tau, ds, f, modes);
    // The normal part of the certificate comes from the normal solve of the last iterate.
    sol.report.certificate = sol.normal.report.certificate;
    sol.report.certificate.friction_law = friction.friction_law;
    sol.report.certificate.gap_function = friction.gap_function;
    sol.report.certificate.force_residual = std::max(sol.normal.report.certificate.force_residual, friction.force_residual);
    const bool certified = sol.report.certificate.worst() <= solver.certificate_tol && sol.outer.converged &&
                           sol.normal.report.status == SolveStatus::converged;
    if (sol.report.status != SolveStatus::failed)
      sol.report.status = certified ? SolveStatus::converged : SolveStatus::not_converged;
    if (!sol.outer.converged)
      sol.report.message += " [outer loop (4.26)-(4.27)/(3.31)-(3.32) did not converge in " +
                            std::to_string(sol.outer.iterations) + " iterations: last change " +
                            format_number(sol.outer.last_change) + "; the results are its last iterate]";
  }

  /// The outer loop (4.26)-(4.27) / (3.31)-(3.32) around an inner tangential solve: the pressure
  /// with the gap shifted by kappa B32 tau of the previous iterate, the bound f(p), then
  /// `inner(p, f, tau)` updates tau (false: it gave up, the loop stops and returns false).
  /// kappa = 0: p does not depend on tau, so f(p) is final after one pass.
  /// kappa != 0: the alternation is a fixed point s = G(s) of the gap shift s = kappa B32 tau fed
  /// to (4.26), accelerated by Anderson mixing of s (N values, in the units of the stopping
  /// test; one B32 apply per pass); both problems start from the previous step's solution (warm).
  /// It stops on the certificate: the pressure was solved with kappa B32 tau_in, and the new
  /// tau moves that gap by kappa B32 (tau - tau_in); once this is below a hundredth of
  /// certificate_tol (in the certificate's units, gap / C_00 / max p), the pressure is certified
  /// again with the final tau (certify_with_final_traction), so p and tau certify together.
  /// `inexact` (the inner solve honours the pass's SolverSpec): while the coupling residual is
  /// large, both problems are solved only to a tenth of it (at most 1e-3, at least solver.tol):
  /// the next pass changes their data by about that residual anyway. The loop stops only after
  /// a pass at solver.tol, so the answer and its certificate are those of exact solves.
  template <class Inner>
  bool outer_loop(TangentialSolution& sol, const NormalSpec& normal_load, const SolverSpec& solver,
                  std::vector<double>& tau, std::vector<double>& f, bool inexact, Inner&& inner) {
    // The gap shift kappa B32 tau_in fed to (4.26) and the one of the new tau.
    std::vector<double> p_old, tau_old, shift_in, shift_out;
    f.assign(N, 0.0);
    const bool stall = injected_fault("outer") != Fault::none;  // test-only: a loop that never settles
    const int max_outer = coupled ? (stall ? 3 : 100) : 1;
    const double outer_tol = std::max(1e-9, 10.0 * solver.tol);
    const double c0 = C->diagonal(0);
    const double coupling_tol = 0.01 * solver.certificate_tol;
    AndersonMixing mixer;
    SolverSpec pass = solver;
    if (coupled && inexact) pass = loose_pass(solver, 1e-3);
    double last_gap = 0.0;
    if (coupled) B32->apply(tau, shift_in);
    for (int m = 1; m <= max_outer; ++m) {
      std::vector<double> h = heights;  // (4.26)
      if (coupled)
        for (std::size_t i = 0; i < N; ++i) h[i] += shift_in[i];
      const bool exact_pass = pass.tol == solver.tol;
      sol.normal = solve_normal(std::move(h), normal_load, pass);
      if (sol.normal.report.status == SolveStatus::failed)
        throw SolverFailure("the normal problem failed, so the tangential one cannot be set up: " +
                            sol.normal.report.message);
      const std::vector<double>& p = sol.normal.pressure;
      // (3.32): the friction bound from this pressure; noise-level pressures carry none.
      const double p_cut = 1e-9 * max_abs(p);
      for (std::size_t e = 0; e < N; ++e) f[e] = p[e] > p_cut ? friction.bound(p[e]) : 0.0;
      if (!inner(p, f, tau, pass)) return false;
      tau_warm = tau;
      const double change = std::max(relative_change(p, p_old), relative_change(tau, tau_old));
      sol.outer.iterations = m;
      sol.outer.last_change = m == 1 ? 0.0 : change;
      p_old = p;
      tau_old = tau;
      if (max_outer == 1) break;
      // The gap error the last tau leaves in the pressure's problem (certificate units).
      B32->apply(tau, shift_out);
      double gap_error = 0.0;
      for (std::size_t i = 0; i < N; ++i)
        if (std::isfinite(heights[i])) gap_error = std::max(gap_error, std::abs(shift_out[i] - shift_in[i]));
      const double p_max = max_abs(p);
      gap_error /= c0 * (p_max > 0.0 ? p_max : 1.0);
      sol.outer.coupling_residual = gap_error;
      if (m == 1) sol.outer.first_residual = gap_error;
      if (!stall && exact_pass && (gap_error <= coupling_tol || (m > 1 && change < outer_tol))) {
        certify_with_final_traction(sol, shift_out, normal_load);
        break;
      }
      if (m == max_outer) {
        sol.outer.converged = false;
        sol.outer.last_change = change;
        break;
      }
      shift_in = mixer.next(shift_in, shift_out);
      // The next pass is exact once it is expected to end the loop (the residual contracts by
      // the last pass's factor), and so is the last pass allowed: an unsettled loop reports
      // exact solves' last iterate.
      const double contraction = std::clamp(m > 1 ? gap_error / last_gap : 0.5, 0.01, 1.0);
      last_gap = gap_error;
      if (!exact_pass)
        pass = gap_error * contraction <= coupling_tol || m + 1 == max_outer ? solver
                                                                             : loose_pass(solver, 0.1 * gap_error);
    }
    return true;
  }

  /// kappa != 0: the pressure was solved with the gap shifted by kappa B32 tau_in; its
  /// certificate becomes that of the gap (4.26) with the final tau (shift_out = kappa B32 tau),
  /// so that the coupling residual is measured, not assumed (one apply of C).
  void certify_with_final_traction(TangentialSolution& sol, const std::vector<double>& shift_out,
                                   const NormalSpec& normal_load) {
    std::vector<double>& h = final_heights_work;
    h = heights;
    for (std::size_t i = 0; i < N; ++i) h[i] += shift_out[i];
    normal->set_heights(h);
    const Certificate c = normal->certify(sol.normal.pressure, sol.normal.approach, normal_load);
    Certificate& cert = sol.normal.report.certificate;
    cert.complementarity = c.complementarity;
    cert.gap_violation = c.gap_violation;
    normal->set_heights(normal_cache_heights);  // the heights of the last solve, as the cache says
  }

  /// The solver of an inexact alternation: tolerance `tol` (between solver.tol and 1e-3), and a
  /// certificate tolerance that such a solve can meet (the backends fall back on it).
  static SolverSpec loose_pass(const SolverSpec& solver, double tol) {
    SolverSpec pass = solver;
    pass.tol = std::clamp(tol, solver.tol, std::max(solver.tol, 1e-3));
    pass.certificate_tol = std::max(solver.certificate_tol, 100.0 * pass.tol);
    return pass;
  }

  /// One step with the outer loop (4.26)-(4.27) / (3.31)-(3.32); rigid slips are increments.
  /// `shift` (elements along x and y) is the travel of the step: (0, 0) quasi-static, (1, 0) a
  /// marching step. It enters through W alone (the previous displacement at the upstream point),
  /// so the slip ds = W + rigid + Ct tau and the gap function (4.24)-(4.25) of the certificate
  /// are those of the convected step.
  TangentialSolution solve_step(const NormalSpec& normal_load, const std::array<ModeControl, 3>& modes,
                                const std::array<double, 3>& given_increment, const std::array<double, 2>& shift,
                                const SolverSpec& solver, const ProgressCallback& progress) {
    const std::size_t n = comps * N;
    std::vector<double> u_prev;
    if (shift[0] == 1.0 && shift[1] == 0.0 && Ct_up)
      displacement(p_prev, tau_prev, u_prev, *Ct_up, B21_up.get());
    else
      convected_displacement(shift[0], shift[1], u_prev);

    TangentialSolution sol;
    std::vector<double> tau = tau_warm.size() == n ? tau_warm : std::vector<double>(n, 0.0);
    std::vector<double> f, W(n), w21;
    InnerResult inner;
    outer_loop(sol, normal_load, solver, tau, f, true,
               [&](const std::vector<double>& p, const std::vector<double>& bound, std::vector<double>& t,
                   const SolverSpec& pass) {
                 // (4.27): W = kappa B21 p - u_prev.
                 for (std::size_t i = 0; i < n; ++i) W[i] = -u_prev[i];
                 if (coupled) {
                   B21->apply(p, w21);
                   for (std::size_t i = 0; i < n; ++i) W[i] += w21[i];
                 }
                 inner = solve_tangential(W, bound, modes, given_increment, pass, progress);
                 t = inner.tau;
                 return true;
               });
    // Results: slip increment ds = W + rigid + Ct tau (3.8), certificate, states.
    const std::vector<double> ds = slip_increment(W, tau, inner.increment);
    sol.report = inner.report;
    sol.shift_undetermined = inner.shift_undetermined;
    finish(sol, tau, ds, f, modes, solver);
    // Remember the state for the next step.
    tau_prev = tau;
    p_prev = sol.normal.pressure;
    sol.amplitudes = inner.increment;
    return sol;
  }

  /// Steady rolling solved directly (steady_rolling_solver.hpp) inside the outer loop; the
  /// slip per step of travel dx is ds = dx v_rigid + (C - S C) tau (+ kappa (B21 - S B21) p).
  /// Empty when Newton's method gives up (the caller then marches).
  std::optional<TangentialSolution> steady_rolling_direct(const RollingLoad& load,
                                                          const std::array<double, 3>& given_increment,
                                                          const SolverSpec& solver, const ProgressCallback& progress,
                                                          std::string& why_not) {
    if (!D_conv) D_conv = half_space->tangential_convective(1, kind);
    if (coupled && !B21_up) B21_up = half_space->tangential_from_normal_shifted(1, 0, kind);
    const std::size_t n = comps * N;
    SteadyRollingProgram program;
    program.D = D_conv.get();
    program.comps = comps;
    program.area = grid.area();
    std::vector<int> unknown_modes;
    for (int k = 0; k < n_modes(); ++k) {
      if (load.modes[k].kind != ModeControl::Kind::resultant) continue;
      std::vector<double> m(n);
      for (std::size_t e = 0; e < N; ++e)
        for (int c = 0; c < comps; ++c) m[c * N + e] = mode(k, e, c);
      program.modes.push_back(std::move(m));
      program.resultants.push_back(load.modes[k].value);
      unknown_modes.push_back(k);
    }
    SolveOptions options = solve_options(solver, progress);
    options.max_iter = std::min(solver.max_iter, 200);
    TangentialSolution sol;
    std::vector<double> tau = load.warm_start.size() == n ? load.warm_start : std::vector<double>(n, 0.0);
    std::vector<double> f, w_up, w_here;
    SteadyRollingOutcome outcome;
    int newton = 0, applies = 0;
    const auto start = std::chrono::steady_clock::now();
    const bool ok = outer_loop(
        sol, load.normal, solver, tau, f, false,
        [&](const std::vector<double>& p, const std::vector<double>& bound, std::vector<double>& t, const SolverSpec&) {
          program.b.assign(n, 0.0);
          for (std::size_t e = 0; e < N; ++e)
            for (int c = 0; c < comps; ++c)
              for (int k = 0; k < n_modes(); ++k) program.b[c * N + e] += given_increment[k] * mode(k, e, c);
          if (coupled) {
            B21->apply(p, w_here);
            B21_up->apply(p, w_up);
            for (std::size_t i = 0; i < n; ++i) program.b[i] += w_here[i] - w_up[i];
          }
          check_resultants(bound, load.modes);
          if (std::all_of(bound.begin(), bound.end(), [](double b) { return b <= 0.0; })) {
            outcome.message = "no friction (f(p) = 0 over the whole contact)";
            return false;
          }
          program.bound = bound;
          program.tau0 = t;
          outcome = solve_steady_rolling(program, options);
          newton += outcome.newton_iterations;
          applies += outcome.operator_applies;
          if (!outcome.success) return false;
          t = outcome.tau;
          return true;
        });
    if (!ok) {
      why_not = outcome.message;
      return std::nullopt;
    }
    std::array<double, 3> amplitudes = given_increment;
    for (std::size_t r = 0; r < unknown_modes.size(); ++r) amplitudes[unknown_modes[r]] = outcome.amplitudes[r];
    std::vector<double> ds;
    D_conv->apply(tau, ds);
    for (std::size_t i = 0; i < n; ++i) ds[i] += program.b[i];
    for (std::size_t r = 0; r < program.modes.size(); ++r)
      for (std::size_t i = 0; i < n; ++i) ds[i] += outcome.amplitudes[r] * program.modes[r][i];
    sol.report.requested = solver.backend;
    sol.report.backend = "native";
    sol.report.operator_kind = D_conv->kind();
    sol.report.status = SolveStatus::converged;
    sol.report.iterations = applies;
    sol.newton_iterations = newton;
    sol.report.time_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    sol.report.message = "steady rolling by Newton: " + std::to_string(newton) + " iterations, " +
                         std::to_string(applies) + " operator applies";
    finish(sol, tau, ds, f, load.modes, solver);
    tau_prev = tau;
    p_prev = sol.normal.pressure;
    sol.amplitudes = amplitudes;
    return sol;
  }

  struct March {
    TangentialSolution sol;  ///< the last step; amplitudes = rigid-mode increments of that step
    int steps = 0;           ///< marching steps done
    bool steady = false;     ///< stopped because a step changed tau by less than steady_tol
    int first_unconverged = 0;  ///< the first step that was not certified (1-based), 0: none
  };

  /// Rolling in +x from the current state: up to `max_steps` marching steps of dx (dt = dx / V).
  /// Each step is one program (3.8)/(4.4)-(4.6): the convective term dt (V . grad)(u+ - u-) of
  /// (2.14) is the difference between the displacement here and the previous one taken at the
  /// upstream material point (B* of (4.6) through Ct_up, the kappa term of (4.5) through B21_up).
  /// Stops after a step that changes tau by less than `steady_tol` (0: never), or fails. The
  /// total rigid slip accumulates in amplitude_prev.
  March march(const RollingLoad& load, int max_steps, double steady_tol, const SolverSpec& solver,
              const ProgressCallback& progress) {
    if (!(load.velocity > 0.0)) throw InputError("tangential.velocity", "the rolling speed must be positive");
    // Rolling in +x: the material now at x was at x + dx one step (dt = dx / V) earlier.
    if (!Ct_up) {
      Ct_up = half_space->tangential_shifted(1, 0, kind);
      if (coupled) B21_up = half_space->tangential_from_normal_shifted(1, 0, kind);
    }
    // Per step the rigid slip is v dt = dx (creepage - phi y, eta + phi x): increments dx * mode.
    std::array<double, 3> increment{};
    for (int k = 0; k < 3; ++k)
      if (load.modes[k].kind == ModeControl::Kind::amplitude) increment[k] = grid.dx * load.modes[k].value;
    // auto: every step is one warm-started program, where the native solver is much the
    // fastest at any size (the others remain its fallbacks).
    const SolverSpec& step_solver = solver;
    native_first = true;
    struct Restore {
      bool& flag;
      ~Restore() { flag = false; }
    } restore{native_first};
    March m;
    for (m.steps = 1; m.steps <= max_steps; ++m.steps) {
      const std::vector<double> input = tau_prev;
      m.sol = solve_step(load.normal, load.modes, increment, {1.0, 0.0}, step_solver, {});
      if (m.sol.report.status != SolveStatus::converged && m.first_unconverged == 0) m.first_unconverged = m.steps;
      if (m.sol.report.status == SolveStatus::failed) break;
      for (int k = 0; k < 3; ++k) amplitude_prev[k] += m.sol.amplitudes[k];
      const double change = relative_change(tau_prev, input);
      if (progress) progress({m.steps, 0.0, change, steady_tol});
      if (steady_tol > 0.0 && m.steps > 1 && change < steady_tol) {
        m.steady = true;
        break;
      }
    }
    m.steps = std::min(m.steps, max_steps);
    return m;
  }
};

TangentialProblem::TangentialProblem(const Grid& grid, const MaterialPair& materials, std::vector<double> heights,
                                     FrictionLaw friction, OperatorKind kind)
    : impl_(std::make_shared<Impl>(grid, materials, std::move(heights), std::move(friction), kind)), grid_(grid) {}

void TangentialProblem::forget_starting_points() {
  impl_->tau_warm.clear();
  impl_->predictor.clear();
  impl_->normal->clear_warm_start();
  impl_->normal_cache.reset();
}

TangentialProblem::TangentialProblem(const Grid& grid, std::shared_ptr<const LinearOperator> normal_compliance,
                                     std::shared_ptr<const LinearOperator> tangential_compliance,
                                     std::vector<double> heights, FrictionLaw friction)
    : impl_(std::make_shared<Impl>(grid, std::move(normal_compliance), std::move(tangential_compliance),
                                   std::move(heights), std::move(friction))),
      grid_(grid) {}

void TangentialProblem::reset() { impl_->reset(); }

void TangentialProblem::set_extrapolation(bool on) { impl_->extrapolate = on; }

void TangentialProblem::set_windowing(bool on) { impl_->windowing = on; }

void TangentialProblem::set_native_first(bool on) { impl_->native_first_always = on; }

void TangentialProblem::set_exact_hessian_limit(int elements) {
  impl_->exact_hessian_limit = impl_->comps * elements;
  impl_->normal->set_exact_hessian_limit(elements);
}

void TangentialProblem::use_sparse_form(SparseTangentialForm form) {
  if (!impl_->given_operators) throw std::logic_error("tangential problem: the sparse form needs given compliances");
  impl_->sparse = std::move(form);
  impl_->normal_cache.reset();
}

TangentialSolution TangentialProblem::step(const TangentialLoad& load, const SolverSpec& solver,
                                           const ProgressCallback& progress) {
  Impl& s = *impl_;
  if (s.grid.dimension == 2)
    for (int k = 1; k < 3; ++k)
      if (load.modes[k].value != 0.0)
        throw InputError("tangential", "a 2-D problem has no y shift and no rotation about z");
  std::array<double, 3> increment{};
  for (int k = 0; k < 3; ++k)
    if (load.modes[k].kind == ModeControl::Kind::amplitude) increment[k] = load.modes[k].value - s.amplitude_prev[k];
  // kappa != 0: a history loaded in proportion starts its alternation from the extrapolated state.
  ProportionalPredictor::Load key;
  key.values.push_back(load.normal.value);
  key.kinds.push_back(static_cast<int>(load.normal.control));
  for (int k = 0; k < 3; ++k) {
    key.values.push_back(load.modes[k].value);
    key.kinds.push_back(static_cast<int>(load.modes[k].kind));
  }
  std::vector<double> tau_start, p_start;
  if (s.coupled && s.extrapolate && s.predictor.predict(key, tau_start, p_start)) {
    s.tau_warm = std::move(tau_start);
    s.normal->set_warm_start(std::move(p_start));
  }
  TangentialSolution sol = s.solve_step(load.normal, load.modes, increment, {0.0, 0.0}, solver, progress);
  for (int k = 0; k < 3; ++k) sol.amplitudes[k] += s.amplitude_prev[k];
  s.amplitude_prev = sol.amplitudes;
  if (s.coupled && sol.report.status == SolveStatus::converged)
    s.predictor.record(key, s.tau_prev, s.p_prev);
  else
    s.predictor.clear();
  return sol;
}

TangentialSolution TangentialProblem::steady_rolling(const RollingLoad& load, const SolverSpec& solver,
                                                     const ProgressCallback& progress) {
  Impl& s = *impl_;
  if (s.given_operators) throw InputError("tangential.regime", "rolling is not available for a finite body");
  s.reset();
  if (!(load.velocity > 0.0)) throw InputError("tangential.velocity", "the rolling speed must be positive");
  // auto / native: the steady state directly (Newton); the convex-program backends, or Newton
  // giving up, march in time. Per step of travel dx the rigid slip is dx (creepage - phi y,
  // eta + phi x): increments dx * mode.
  using Method = RollingLoad::Method;
  std::string direct_failure;
  const bool newton = load.method == Method::newton ||
                      (load.method == Method::automatic && (solver.backend == "auto" || solver.backend == "native"));
  if (newton) {
    std::array<double, 3> increment{};
    for (int k = 0; k < 3; ++k)
      if (load.modes[k].kind == ModeControl::Kind::amplitude) increment[k] = s.grid.dx * load.modes[k].value;
    auto direct = s.steady_rolling_direct(load, increment, solver, progress, direct_failure);
    if (direct || load.method == Method::newton) {
      if (!direct) {
        direct.emplace();
        direct->report.status = SolveStatus::failed;
        direct->report.message = "steady rolling by Newton failed: " + direct_failure;
      }
      for (int k = 0; k < 3; ++k) direct->amplitudes[k] /= s.grid.dx;
      direct->rolling = true;
      return *direct;
    }
    s.reset();
  }
  const int max_steps = load.max_steps > 0 ? load.max_steps : 10 * s.grid.nx;
  // Marching (the previous traction taken upstream) converges geometrically to the steady
  // state; stop when a step changes tau by less than the certificate tolerance, then prove the
  // steady state with the certificate of the steady slip ds = dx v + (C - S C) tau (2.19).
  const double steady_tol = std::max(0.01 * solver.certificate_tol, 10.0 * solver.tol);
  Impl::March march = s.march(load, max_steps, steady_tol, solver, progress);
  TangentialSolution& sol = march.sol;
  const int steps = march.steps;
  const bool steady = march.steady;
  if (sol.report.status != SolveStatus::failed) {
    // Steady slip with the same tau upstream and here (no lag): certificate of (2.19).
    std::vector<double> u_here, u_up;
    s.displacement(s.p_prev, s.tau_prev, u_here, *s.Ct, s.B21.get());
    s.displacement(s.p_prev, s.tau_prev, u_up, *s.Ct_up, s.B21_up.get());
    const std::size_t N = s.N;
    for (std::size_t e = 0; e < N; ++e)
      for (int c = 0; c < s.comps; ++c) {
        double rigid = 0.0;
        for (int k = 0; k < s.n_modes(); ++k) rigid += sol.amplitudes[k] * s.mode(k, e, c);
        const double ds = rigid + u_here[c * N + e] - u_up[c * N + e];
        (c == 0 ? sol.sx : sol.sy)[e] = ds;
      }
    const Certificate steady_cert =
        certify_friction(s.grid, sol.tx, sol.ty, sol.sx, sol.sy, sol.bound, s.Ct->diagonal(0));
    sol.report.certificate.friction_law = steady_cert.friction_law;
    sol.report.certificate.gap_function = steady_cert.gap_function;
    const bool certified = sol.report.certificate.worst() <= solver.certificate_tol;
    if (sol.report.status == SolveStatus::converged && !certified) {
      sol.report.status = SolveStatus::not_converged;
      sol.report.message += " [steady-state certificate " + format_number(sol.report.certificate.worst()) +
                            " exceeds the tolerance]";
    }
  }
  sol.marching_steps = std::min(steps, max_steps);
  sol.rolling = true;
  if (!direct_failure.empty()) {
    sol.report.fallback_used = true;
    sol.report.message += " [steady Newton gave up (" + direct_failure + "): marched instead]";
  }
  // Amplitudes as creepages / spin (per unit rolling distance).
  for (int k = 0; k < 3; ++k) sol.amplitudes[k] /= s.grid.dx;
  if (!steady && sol.report.status == SolveStatus::converged) {
    sol.report.status = SolveStatus::not_converged;
    sol.report.message += " [rolling did not reach a steady state in " + std::to_string(max_steps) + " steps]";
  }
  return sol;
}

TangentialSolution TangentialProblem::roll(const RollingLoad& load, double distance, const SolverSpec& solver,
                                           const ProgressCallback& progress) {
  Impl& s = *impl_;
  if (s.given_operators) throw InputError("tangential.regime", "rolling is not available for a finite body");
  if (!std::isfinite(distance) || distance < 0.0)
    throw InputError("tangential.distance", "the rolling distance must be a finite length >= 0 (m)");
  s.predictor.clear();  // rolling continues no quasi-static history
  if (distance == 0.0) {
    // No travel, no convective term: the quasi-static step (2.16) of the same controls; a
    // creepage applies no rigid slip over zero distance, a prescribed force is carried by a shift.
    if (!(load.velocity > 0.0)) throw InputError("tangential.velocity", "the rolling speed must be positive");
    TangentialSolution sol = s.solve_step(load.normal, load.modes, {0.0, 0.0, 0.0}, {0.0, 0.0}, solver, progress);
    for (int k = 0; k < 3; ++k) s.amplitude_prev[k] += sol.amplitudes[k];
    return sol;  // amplitudes: the rigid shift (m, m, rad) of this step; marching_steps = 0
  }
  // At least one marching step; otherwise the nearest whole number of elements.
  const double steps = std::max(1.0, std::round(distance / s.grid.dx));
  if (steps > 1e8) throw InputError("tangential.distance", "over 1e8 marching steps of one element each");
  const int n = static_cast<int>(steps);
  Impl::March march = s.march(load, n, 0.0, solver, progress);
  TangentialSolution& sol = march.sol;
  sol.marching_steps = march.steps;
  sol.rolling = true;
  sol.distance = march.steps * s.grid.dx;
  // The path matters in a transient: one uncertified step leaves the result uncertified.
  if (march.first_unconverged > 0 && sol.report.status == SolveStatus::converged) {
    sol.report.status = SolveStatus::not_converged;
    sol.report.message += " [marching step " + std::to_string(march.first_unconverged) + " of " +
                          std::to_string(n) + " was not converged]";
  }
  if (sol.report.status == SolveStatus::failed)
    sol.report.message += " [rolling stopped after " + std::to_string(march.steps) + " of " + std::to_string(n) +
                          " marching steps]";
  // Amplitudes as creepages / spin of the last step (per unit rolling distance).
  for (int k = 0; k < 3; ++k) sol.amplitudes[k] /= s.grid.dx;
  return sol;
}

TangentialSolution TangentialProblem::convected_step(const NormalSpec& normal, const std::array<double, 3>& increment,
                                                   const std::array<double, 2>& travel, const SolverSpec& solver) {
  Impl& s = *impl_;
  if (!std::isfinite(travel[0]) || !std::isfinite(travel[1])) throw InputError("travel", "must be finite");
  // 2-D (plane strain): there is no y direction to travel along, so a y travel is a caller's
  // error, rejected rather than ignored.
  if (s.grid.dimension == 2 && travel[1] != 0.0)
    throw InputError("travel", "a 2-D contact has no y direction: the travel along y must be 0");
  if (s.given_operators && (travel[0] != 0.0 || travel[1] != 0.0))
    throw InputError("travel", "a finite body's contact is not convected (no shifted compliances)");
  std::array<ModeControl, 3> modes{};
  for (int k = 0; k < 3; ++k) modes[k].value = increment[k];
  s.predictor.clear();  // a convected step continues no quasi-static history
  // auto: as for marching, native first at any size (the others remain its fallbacks).
  s.native_first = true;
  struct Restore {
    bool& flag;
    ~Restore() { flag = false; }
  } restore{s.native_first};
  double shift_y = s.grid.dimension == 3 ? travel[1] / s.grid.dy : 0.0;
  // A lateral travel below 1e-12 element (round-off in V_y of a body rolling along x) is not
  // convected: it would change the memory 1000 times less than the solver's tolerance, and cost
  // two more operator applies per step (and, below zero, the operators of the shift -1).
  if (std::abs(shift_y) < 1e-12) shift_y = 0.0;
  TangentialSolution sol = s.solve_step(normal, modes, increment, {travel[0] / s.grid.dx, shift_y}, solver, {});
  for (int k = 0; k < 3; ++k) s.amplitude_prev[k] += sol.amplitudes[k];
  return sol;
}

TangentialMemory TangentialProblem::memory() const {
  const Impl& s = *impl_;
  return {s.tau_prev, s.p_prev, s.tau_warm, s.amplitude_prev};
}

void TangentialProblem::restore(const TangentialMemory& m) {
  Impl& s = *impl_;
  s.tau_prev = m.tau;
  s.p_prev = m.pressure;
  s.tau_warm = m.warm_start;
  s.amplitude_prev = m.amplitudes;
  s.predictor.clear();
}

void TangentialProblem::set_heights(const std::vector<double>& heights) {
  impl_->heights.assign(heights.begin(), heights.end());  // reuses the buffer: no allocation per step
  impl_->predictor.clear();                                // another profile: no load history to continue
}

const LinearOperator& TangentialProblem::tangential_compliance() const { return *impl_->Ct; }

const LinearOperator& TangentialProblem::normal_compliance() const { return *impl_->C; }

const LinearOperator* TangentialProblem::tangential_from_normal() const {
  return impl_->coupled ? impl_->B21.get() : nullptr;
}

const LinearOperator* TangentialProblem::normal_from_tangential() const {
  return impl_->coupled ? impl_->B32.get() : nullptr;
}

const LinearOperator& TangentialProblem::convective_compliance() {
  Impl& s = *impl_;
  if (!s.half_space) throw InputError("tangential.regime", "convection is not available for a finite body");
  if (!s.D_conv) s.D_conv = s.half_space->tangential_convective(1, s.kind);
  return *s.D_conv;
}

const LinearOperator* TangentialProblem::convective_from_normal() {
  Impl& s = *impl_;
  if (!s.coupled) return nullptr;
  if (!s.half_space) throw InputError("tangential.regime", "convection is not available for a finite body");
  if (!s.D21_conv) s.D21_conv = s.half_space->tangential_from_normal_convective(1, s.kind);
  return s.D21_conv.get();
}

double TangentialProblem::traction_scale(const std::vector<double>& tx, const std::vector<double>& ty,
                                         const std::vector<double>& bound) {
  double level = 0.0;
  for (std::size_t e = 0; e < bound.size(); ++e)
    if (bound[e] > 0.0) level = std::max(level, std::hypot(tx[e], ty[e]));
  return level;
}

Certificate TangentialProblem::certify_friction(const Grid& grid, const std::vector<double>& tx,
                                                const std::vector<double>& ty, const std::vector<double>& sx,
                                                const std::vector<double>& sy, const std::vector<double>& bound,
                                                double compliance) {
  if (!all_finite(tx) || !all_finite(ty) || !all_finite(sx) || !all_finite(sy) || !all_finite(bound))
    return Certificate::not_finite();
  Certificate cert;
  const double A = grid.area();
  const double c_t = compliance;  // slip per unit traction of one element
  // Scales of the solution itself, not of the bound: the traction level T (max |tau| where
  // friction acts) and the slip level S (max |ds|, at least c_t T). max f(p) or sum f |ds| A
  // would vanish or explode in full stick, for mu -> 0 or mu -> infinity.
  double T = traction_scale(tx, ty, bound), S = 0.0, f_area = 0.0;
  for (std::size_t e = 0; e < bound.size(); ++e)
    if (bound[e] > 0.0) {
      S = std::max(S, std::hypot(sx[e], sy[e]));
      f_area += bound[e] * A;
    }
  if (!(T > 0.0)) T = S / c_t;  // no traction at all: any slip where friction acts is an error
  if (!(T > 0.0)) return cert;  // nothing loaded, nothing slipping
  S = std::max(S, c_t * T);
  double law = 0.0, gap = 0.0;
  for (std::size_t e = 0; e < bound.size(); ++e) {
    const double f = bound[e];
    // (2.4)-(2.5) as a fixed point: tau = proj_{|t| <= f}(tau - ds / c_t).
    double zx = tx[e] - sx[e] / c_t, zy = ty[e] - sy[e] / c_t;
    project_onto_disk(zx, zy, std::max(f, 0.0));
    law = std::max(law, std::hypot(tx[e] - zx, ty[e] - zy));
    law = std::max(law, std::hypot(tx[e], ty[e]) - f);
    // (4.24): g = sum [f |ds| - tau- . ds] A, with the paper's tau- = -tau+ on the substrate
    // ((3.12), (3.25)); it vanishes when tau+ = -f ds/|ds| on slip, ds = 0 on stick.
    gap += (f * std::hypot(sx[e], sy[e]) + (tx[e] * sx[e] + ty[e] * sy[e])) * A;
  }
  cert.friction_law = law / T;
  // g against the largest it could be at this slip level: sum f A times S.
  cert.gap_function = f_area > 0.0 ? std::abs(gap) / (f_area * S) : 0.0;
  return cert;
}

}  // namespace dc
