#include "finite_contact.hpp"

#include <chrono>
#include <cmath>

#include "backend_choice.hpp"
#include "body_compliance.hpp"
#include "certified_solve.hpp"
#include "errors.hpp"
#include "saddle_form.hpp"
#include "gmsh_mesher.hpp"
#include "interrupt.hpp"

namespace dc {

FiniteContact::FiniteContact(const FeBodySpec& spec, const Grid& grid, const Elastic& halfspace, OperatorKind kind)
    : grid_(grid), program_(spec.program), load_line_(spec.load_line), tilt_(spec.tilt) {
  // Meshing, assembly, factorisation and the condensed compliance: nothing is finished before
  // the body is ready, so an interrupt may end the process anywhere in here (core/interrupt.hpp).
  const NonPollingSection preparing("preparing the finite-element body");
  const auto start = std::chrono::steady_clock::now();
  FeBodySpec meshed = spec;  // the face refined over the grid unless the case says otherwise
  if (!meshed.refine_radius) meshed.refine_radius = grid_refine_radius(grid);
  if (meshed.contact_size == 0.0)
    meshed.default_contact_size_bound = default_contact_size_bound(spec, halfspace, grid);
  fe::BodyMesh mesh = fe::mesh_body(meshed);
  mesh_seconds_ = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  std::vector<fe::BodyMaterial> materials{spec.material};
  for (const auto& r : spec.regions) materials.push_back(r.material);
  face_ = std::make_unique<fe::ContactFace>(mesh, grid_);
  body_ = std::make_unique<fe::ElasticBody>(std::move(mesh), std::move(materials));
  // The half-space alone: the body's compliance is the mesh's.
  const MaterialPair pair{Elastic::make_rigid(), halfspace};
  const HalfSpace half_space(grid_, pair);
  std::shared_ptr<const LinearOperator> hs(half_space.normal(kind));
  halfspace_normal_ = hs;
  halfspace_tangential_ = std::shared_ptr<const LinearOperator>(half_space.tangential(kind));
  body_normal_ = std::make_shared<BodyCompliance>(*body_, *face_, grid_, std::vector<int>{2});
  normal_compliance_ = std::make_shared<SumOperator>(hs, body_normal_);
  normal_ = std::make_unique<NormalProblem>(normal_compliance_, grid_, profile_heights());
  normal_->set_exact_hessian_limit(static_cast<int>(kSaddleExactLimit));  // as the tangential program's below
}

FiniteNormalSolution FiniteContact::solve_normal(const NormalSpec& control, const SolverOptions& solver,
                                                 const ProgressCallback& progress) {
  FiniteNormalSolution out;
  if (program_ == "sparse") {
    out.contact = solve_sparse(control, solver, progress, out.body_displacement);
  } else if (load_line_) {
    out.contact = solve_tilted(control, solver, progress);
    body_normal_->displacement(out.contact.pressure.data(), out.body_displacement);
  } else {
    out.contact = normal_->solve(control, solver, progress);
    body_normal_->displacement(out.contact.pressure.data(), out.body_displacement);
  }
  out.max_body_displacement = 0.0;
  for (Eigen::Index k = 0; k + 2 < out.body_displacement.size(); k += 3)
    out.max_body_displacement = std::max(out.max_body_displacement, out.body_displacement.segment<3>(k).norm());
  return out;
}

NormalSolution FiniteContact::solve_sparse(const NormalSpec& control, const SolverOptions& solver,
                                           const ProgressCallback& progress, Eigen::VectorXd& body_displacement) {
  return solve_sparse(profile_heights(), control, solver, progress, body_displacement);
}

NormalSolution FiniteContact::solve_sparse(const std::vector<double>& h, const NormalSpec& control,
                                           const SolverOptions& solver, const ProgressCallback& progress,
                                           Eigen::VectorXd& body_displacement) {
  // The backends of saddle_backend_order in turn: the first result the condensed program's
  // certificate accepts, else the best (one rule: certified_solve.hpp).
  NormalSolution first;
  first.report.requested = to_string(solver.backend);
  AttemptLedger<NormalSolution> ledger(first);
  Eigen::VectorXd kept_displacement;
  const std::vector<std::string> order = saddle_backend_order(solver.backend);
  for (std::size_t k = 0; k < order.size() && !ledger.converged(); ++k) {
    Eigen::VectorXd u;
    NormalSolution sol = solve_sparse_by(order[k], h, control, solver, progress, u);
    sol.report.fallback_used = k > 0;
    const bool has_point = !sol.pressure.empty();
    if (ledger.record(std::move(sol), has_point)) kept_displacement = std::move(u);
  }
  // Ipopt failed on the sparse form: NLopt on the condensed program, the same minimax with the
  // body's rows eliminated by the kept factor (NLopt cannot take the rows themselves: with them
  // held densely it did not converge). Small bodies only: each NLopt evaluation costs a pair of
  // triangular solves, and NLopt takes hundreds.
  if (!ledger.converged() && solver.backend == Backend::automatic && solver.fallback &&
      body_->dofs() <= kSaddleFallbackDofs) {
    normal_->set_heights(h);
    SolverOptions nlopt = solver;
    nlopt.backend = Backend::nlopt;
    nlopt.fallback = false;
    NormalSolution sol = normal_->solve(control, nlopt, progress);
    sol.report.fallback_used = true;
    sol.report.backend = "nlopt (condensed program)";
    const bool has_point = sol.report.status != SolveStatus::failed;
    Eigen::VectorXd u;
    if (has_point) body_normal_->displacement(sol.pressure.data(), u);
    if (ledger.record(std::move(sol), has_point)) kept_displacement = std::move(u);
  }
  body_displacement = std::move(kept_displacement);
  return std::move(ledger).finish();
}

NormalSolution FiniteContact::solve_sparse_by(const std::string& backend, const std::vector<double>& h,
                                              const NormalSpec& control, const SolverOptions& solver,
                                              const ProgressCallback& progress, Eigen::VectorXd& body_displacement) {
  const auto start = std::chrono::steady_clock::now();
  const SaddleNormalOutcome o = solve_saddle_normal(*body_, stress_rows(), *face_, *halfspace_normal_, grid_, h, control,
                                                    solve_options(solver, progress), backend);
  NormalSolution sol;
  sol.report.requested = to_string(solver.backend);
  sol.report.backend = backend;
  sol.report.operator_kind = "sparse+" + halfspace_normal_->kind();
  sol.report.message = o.message;
  sol.report.iterations = o.iterations;
  sol.report.time_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  if (o.pressure.empty()) {
    sol.report.status = SolveStatus::failed;
    return sol;
  }
  sol.pressure = o.pressure;
  body_displacement = o.body_displacement;
  const double A = grid_.area();
  // The approach: given, or where the saddle point's own displacement closes the gap (the
  // pressure-weighted mean of w + h over the contact, as for the condensed program).
  if (control.control == Control::approach) {
    sol.approach = control.value;
  } else {
    double num = 0.0, den = 0.0;
    for (std::size_t i = 0; i < h.size(); ++i)
      if (sol.pressure[i] > 0.0) {
        num += sol.pressure[i] * (o.displacement[i] + h[i]);
        den += sol.pressure[i];
      }
    sol.approach = den > 0.0 ? num / den : 0.0;
  }
  sol.gap.resize(h.size());
  double energy = 0.0;
  const double delta = control.control == Control::approach ? control.value : 0.0;
  for (std::size_t i = 0; i < h.size(); ++i) {
    sol.gap[i] = std::isfinite(h[i]) ? o.displacement[i] + h[i] - sol.approach : kInf;
    sol.force += sol.pressure[i] * A;
    if (std::isfinite(h[i])) energy += A * sol.pressure[i] * (0.5 * o.displacement[i] + h[i] - delta);
  }
  sol.report.objective = energy;
  // Certified on the condensed program (its operator applies the kept factor): the same
  // residuals as for the condensed solvers, so (a) and (b) are judged alike.
  normal_->set_heights(h);
  sol.report.certificate = normal_->certify(sol.pressure, sol.approach, control);
  // An interior point leaves the contact's edge elements off their bound by about mu / (their
  // multiplier): a point Ipopt accepted that misses the certificate is finished by the
  // active-set polish on the condensed program, kept when its certificate is the better one.
  if (sol.report.certificate.worst() > solver.certificate_tol && o.success) {
    NormalSolution polished = normal_->polish(sol.pressure, control, solver);
    if (polished.report.polished && polished.report.certificate.worst() < sol.report.certificate.worst()) {
      sol.pressure = std::move(polished.pressure);
      sol.gap = std::move(polished.gap);
      sol.approach = polished.approach;
      sol.force = polished.force;
      sol.report.objective = polished.report.objective;
      sol.report.certificate = polished.report.certificate;
      sol.report.polished = true;
      sol.report.message += "; " + polished.report.message;
      body_normal_->displacement(sol.pressure.data(), body_displacement);
    }
    sol.report.time_s += polished.report.time_s;
  }
  const bool certified = sol.report.certificate.worst() <= solver.certificate_tol;
  sol.report.status = certified ? SolveStatus::converged : SolveStatus::not_converged;
  if (!certified && o.success)
    sol.report.message += " (backend reported success but the certificate " +
                          format_number(sol.report.certificate.worst()) + " exceeds the tolerance)";
  return sol;
}

const fe::StressEquilibrium& FiniteContact::stress_rows() {
  if (!stresses_) stresses_ = std::make_unique<fe::StressEquilibrium>(fe::stress_equilibrium(*body_));
  return *stresses_;
}

std::vector<double> FiniteContact::profile_heights() const {
  return tilted_heights(face_->heights(), grid_, tilt_[0], tilt_[1]);
}

TangentialProblem& FiniteContact::tangential_problem(const FrictionLaw& friction) {
  if (!tangential_) {
    auto body_t = std::make_shared<BodyCompliance>(*body_, *face_, grid_, std::vector<int>{0, 1});
    auto Ct = std::make_shared<SumOperator>(halfspace_tangential_, body_t);
    tangential_ = std::make_unique<TangentialProblem>(grid_, normal_compliance_, Ct, profile_heights(), friction);
    // Ipopt on the condensed program: the exact Hessian while the dense compliance is as large
    // as the sparse form's dense block (its cost: one multi-column solve of the kept factor, and
    // a dense factorisation per iteration); limited memory beyond, whose every iteration costs
    // an apply (a pair of triangular solves) and which takes them by the thousand.
    tangential_->set_exact_hessian_limit(static_cast<int>(kSaddleExactLimit));
    if (program_ == "sparse") use_sparse_tangential();
  }
  return *tangential_;
}

void FiniteContact::use_sparse_tangential() {
  SparseTangentialForm form;
  form.halfspace = halfspace_tangential_;
  form.body_rows = [this](double traction_unit, double energy_unit, double force_scale) {
    return saddle_body_block(*body_, stress_rows(), *face_, grid_, {0, 1}, traction_unit, energy_unit, force_scale).block;
  };
  form.normal = [this](const std::vector<double>& h, const NormalSpec& load, const SolverOptions& solver) {
    Eigen::VectorXd u;
    return solve_sparse(h, load, solver, {}, u);
  };
  form.backends = [](Backend requested, bool) { return saddle_backend_order(requested); };
  form.exact_hessian_limit = static_cast<int>(2 * kSaddleExactLimit);  // (tau_x, tau_y): two per element
  form.condensed_fallback = body_->dofs() <= kSaddleFallbackDofs;
  tangential_->use_sparse_form(std::move(form));
}

Eigen::VectorXd FiniteContact::body_displacement(const std::vector<double>& tx, const std::vector<double>& ty,
                                                 const std::vector<double>& p) const {
  const std::size_t N = grid_.size();
  std::vector<double> t(3 * N, 0.0);
  std::copy(tx.begin(), tx.end(), t.begin());
  std::copy(ty.begin(), ty.end(), t.begin() + static_cast<std::ptrdiff_t>(N));
  std::copy(p.begin(), p.end(), t.begin() + static_cast<std::ptrdiff_t>(2 * N));
  const BodyCompliance all(*body_, *face_, grid_, {0, 1, 2});
  Eigen::VectorXd u;
  all.displacement(t.data(), u);
  return u;
}

}  // namespace dc
