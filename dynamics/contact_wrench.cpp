#include "contact_wrench.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>

#include "errors.hpp"
#include "friction_law.hpp"

namespace dc::dynamics {

ContactWrench::ContactWrench(const DynamicContactSpec& c, std::unique_ptr<FiniteBody> finite)
    : case_(c), spec_(*c.dynamic), solver_(c.solver), finite_(std::move(finite)) {
  if (c.friction) law_ = FrictionLaw::from_spec(*c.friction);
  if (c.fe_body && !finite_)
    throw InputError("fe_body", "needs finite-element support: this build has none (install libgmsh-dev and "
                                "libsuitesparse-dev, then reconfigure with -DDYNCONTACT_WITH_FE=ON)");
  if (finite_) {
    // The finite program in every step: the factor kept, the problems warm-started.
    if (law_) tangential_ = &finite_->tangential_problem(*law_);
    else normal_ = &finite_->normal_problem();
  } else {
    gap_.emplace(c.profile, c.grid, c.dynamic->radius);
    // auto: FFT at every size. A run applies the operators thousands of times, and the padded FFT
    // product is the faster one from 12^2 elements (3-D) and 200 strips (2-D) up (scripts/bench.sh
    // dynamic with solver.operator dense / fft).
    const OperatorKind kind = c.solver.operator_kind == OperatorKind::dense ? OperatorKind::dense : OperatorKind::fft;
    if (law_) {
      own_tangential_ = std::make_unique<TangentialProblem>(c.grid, c.materials, gap_->heights(), *law_, kind);
      tangential_ = own_tangential_.get();
    } else {
      own_normal_ = std::make_unique<NormalProblem>(c.grid, c.materials, gap_->heights(), kind);
      normal_ = own_normal_.get();
    }
  }
  // Every step is one warm-started program: `auto` tries the native solvers first at any size,
  // the others are their fallbacks.
  if (normal_) normal_->set_native_first(true);
  if (tangential_) tangential_->set_native_first(true);
  if (tangential_) committed_ = tangential_->memory();
  steady_ = spec_.contact_model == ContactModel::steady;
  model_resolved_ = spec_.contact_model != ContactModel::automatic;
}

ContactWrench::~ContactWrench() = default;

double ContactWrench::centre_height() const {
  if (finite_) return finite_->centre_height();
  return gap_->centre_height();
}

std::string ContactWrench::model_used() const {
  if (finite_) return "shift_torsion";
  if (!steady_) return "transient";
  if (transient_steps_ == 0) return "steady";
  return "steady (transient in " + std::to_string(transient_steps_) + " of " + std::to_string(steps_in_contact_) +
         " steps: travel not along +x)";
}

bool ContactWrench::travel_along_x(const Eigen::Vector3d& V) {
  // The steady model convects along x at V_x with creepages per V_x dt; rolling at an angle
  // theta off x that errs by ~theta |C11 - C22| / C11 + theta^2 / 2 of the creep force (Kalker's
  // coefficients), about 1.5 % at tan theta = 0.1, the level of the grid's own creep-law error.
  return V.x() > 0.0 && std::abs(V.y()) <= 0.1 * V.x();
}

void ContactWrench::begin_step(double dt) {
  dt_ = dt;
  trials_in_step_ = 0;
}

NormalSpec ContactWrench::normal_load(const StepKinematics& k, double vertical_load) const {
  if (spec_.normal_model == NormalModel::quasi_static) return {Control::force, std::max(0.0, -vertical_load)};
  // (2.6): the lowest point of the body at its orientation is centre_height() below the centre
  // of mass (body.radius upright); the base is z = 0.
  return {Control::approach, centre_height() - k.position.z()};
}

void ContactWrench::no_contact() {
  state_ = ContactState{};
  has_kept_sensitivity_ = false;
  if (tangential_) tangential_->reset();
}

void ContactWrench::orient(const StepKinematics& k) {
  // (2.6): the gap of the body at its current orientation (body_gap.hpp; an fe_body's at its
  // tilt and spin, finite_body_contact.hpp).
  const std::vector<double>* heights = nullptr;
  if (finite_) {
    if (!finite_->update(k)) return;
    heights = &finite_->heights();
  }
  if (gap_) {
    const bool turned = gap_->update(k.orientation, k.time);
    heights = &gap_->heights();
    if (worn_gap_) {  // the worn depth under the contact at k (it moves with the body: every trial)
      worn_gap_(k, worn_depth_);
      worn_heights_.resize(heights->size());
      for (std::size_t e = 0; e < heights->size(); ++e)
        worn_heights_[e] = (*heights)[e] + (e < worn_depth_.size() ? worn_depth_[e] : 0.0);
      heights = &worn_heights_;
    } else if (!turned) {
      return;
    }
  }
  if (tangential_) tangential_->set_heights(*heights);
  if (normal_) normal_->set_heights(*heights);
}

const std::vector<double>& ContactWrench::heights() const {
  if (finite_) return finite_->heights();
  return worn_gap_ && !worn_heights_.empty() ? worn_heights_ : gap_->heights();
}

Wrench ContactWrench::evaluate(const StepKinematics& k, double vertical_load) {
  // The step's history as accepted; the solve starts from the last trial's traction (Newton's
  // trials of one step lie within its correction of each other), or from the last accepted
  // step's when that one was in contact (its data differ by one step's motion).
  if (tangential_) {
    tangential_->restore_history(committed_);
    tangential_->set_near_start(trials_in_step_ > 0 || accepted_in_contact_);
  }
  ++trials_in_step_;
  orient(k);
  last_ = k;
  const NormalSpec load = normal_load(k, vertical_load);
  // The height of the centre of mass over the base: quasi-static, over the lowest point.
  lever_ = spec_.normal_model == NormalModel::quasi_static ? centre_height() : k.position.z();
  if (!(load.value > 0.0)) {
    no_contact();
    return state_.wrench;
  }
  ++solves_;
  const Grid& g = case_.grid;
  const std::size_t N = g.size();
  const double A = g.area();
  const double h = lever_;
  // Rigid slip of the body over the step at the grid point (x, y, -h) from the centre of mass:
  // (V + Omega x r) dt = (a_x - a_z y, a_y + a_z x), the tangential problem's rigid modes.
  const Eigen::Vector3d& V = k.velocity;
  const Eigen::Vector3d& W = k.omega;
  const std::array<double, 3> increment = {(V.x() - h * W.y()) * dt_, (V.y() + h * W.x()) * dt_, W.z() * dt_};
  const std::vector<double>* pressure = nullptr;
  state_ = ContactState{};
  off_axis_ = !travel_along_x(V);
  const bool steady_step = steady_ && !off_axis_;
  steady_step_ = steady_step;
  if (tangential_) {
    auto solve = [&](const SolverOptions& solver) {
      if (steady_step) {
        RollingLoad& rolling = rolling_;  // its warm start's storage kept from step to step
        rolling.normal = load;
        rolling.velocity = V.x();
        // Newton on the steady equations starts from the last solve's traction (the last trial
        // of this step, or the last accepted step's): nearby data, as a table's neighbour.
        if (solution_.tx.size() == g.size()) rolling_warm_start(solution_, g.dimension, rolling.warm_start);
        else rolling.warm_start.clear();
        for (int m = 0; m < 3; ++m) rolling.modes[m].value = increment[m] / (V.x() * dt_);
        tangential_->steady_rolling(rolling, solver, solution_);
      } else {
        // An fe_body's memory is not convected (shift and torsion, (2.16)): its surface moves
        // with the grid, and the half-space's travel under it is small against the contact.
        const std::array<double, 2> travel =
            finite_ ? std::array<double, 2>{0.0, 0.0} : std::array<double, 2>{V.x() * dt_, V.y() * dt_};
        tangential_->convected_step(load, increment, travel, solver, solution_);
      }
      alternations_ += std::max(1, solution_.outer.iterations);
    };
    solve(solver_);
    if (solution_.report.status == SolveStatus::not_converged && solver_.tol > 1e-14) {
      // Converged but not certified (a nearly stuck contact: the certificate divides by a
      // tiny slip): once more from the same memory with a 1000 times tighter tolerance.
      tangential_->restore(committed_);
      SolverOptions tight = solver_;
      tight.tol = std::max(1e-15, 1e-3 * solver_.tol);
      solve(tight);
    }
    pressure = &solution_.normal.pressure;
    state_.fields = &solution_;
    state_.certificate = solution_.report.certificate.worst();
    state_.converged = solution_.report.status == SolveStatus::converged;
    if (!state_.converged) {
      char cert[160];
      std::snprintf(cert, sizeof cert, "certificate %.3g (tolerance %.3g), normal solve %s", state_.certificate,
                    solver_.certificate_tol, to_string(solution_.normal.report.status));
      state_.message = solution_.report.message + "; " + cert;
    }
    state_.approach = solution_.normal.approach;
    state_.backend = solution_.report.backend;
    state_.fallback_used = solution_.report.fallback_used || solution_.normal.report.fallback_used;
    state_.n_stick = solution_.n_stick;
    state_.n_slip = solution_.n_slip;
  } else {
    ++alternations_;
    normal_->solve(load, solver_, normal_solution_);
    pressure = &normal_solution_.pressure;
    state_.certificate = normal_solution_.report.certificate.worst();
    state_.converged = normal_solution_.report.status == SolveStatus::converged;
    if (!state_.converged) state_.message = normal_solution_.report.message;
    state_.approach = normal_solution_.approach;
    state_.backend = normal_solution_.report.backend;
    state_.fallback_used = normal_solution_.report.fallback_used;
  }
  // Resultants about the centre of mass: r = (x, y, -h), f = (tau_x, tau_y, p) A (an fe_body's
  // centre of mass need not lie over the grid origin).
  Eigen::Vector2d centre = Eigen::Vector2d::Zero();
  if (finite_) centre = finite_->centre_xy();
  Eigen::Vector3d F = Eigen::Vector3d::Zero(), M = Eigen::Vector3d::Zero();
  for (std::size_t e = 0; e < N; ++e) {
    const double p = (*pressure)[e];
    const double tx = tangential_ ? solution_.tx[e] : 0.0, ty = tangential_ ? solution_.ty[e] : 0.0;
    if (p <= 0.0 && tx == 0.0 && ty == 0.0) continue;
    if (p > 0.0) ++state_.n_contact;
    const int i = static_cast<int>(e % g.nx), j = static_cast<int>(e / g.nx);
    const Eigen::Vector3d r(g.xc(i) - centre.x(), g.yc(j) - centre.y(), -h), f(tx * A, ty * A, p * A);
    F += f;
    M += r.cross(f);
  }
  state_.in_contact = state_.n_contact > 0;
  state_.pressure = pressure;
  state_.contact_area = state_.n_contact * A;
  state_.stick_fraction = state_.n_contact > 0 ? static_cast<double>(state_.n_stick) / state_.n_contact : 0.0;
  // Kalker's longitudinal creepage: the slip along the direction of travel over the speed.
  const double speed2 = V.x() * V.x() + V.y() * V.y();
  state_.creepage = speed2 > 0.0 ? (increment[0] * V.x() + increment[1] * V.y()) / (speed2 * dt_) : 0.0;
  state_.wrench = {F, M};
  if (!model_resolved_ && state_.in_contact) {
    // auto: transient while the step's travel |V| dt resolves the contact (a quarter of its
    // half-length); steady takes only the steps whose travel is along +x (travel_along_x).
    const double half_length = g.dimension == 2 ? 0.5 * state_.contact_area : std::sqrt(state_.contact_area / M_PI);
    steady_ = std::hypot(V.x(), V.y()) * dt_ > 0.25 * half_length;
    model_resolved_ = true;
  }
  return state_.wrench;
}

WrenchJacobian ContactWrench::jacobian(bool fresh) {
  WrenchJacobian J;
  if (!state_.in_contact) return J;
  const double h = lever_;
  const Eigen::Vector3d& F = state_.wrench.force;
  // Normal stiffness dP/d(delta) with the contact set fixed: a flat punch of the contact's
  // footprint, 2 E* sqrt(A/pi) (exact for a circle); R_z up is delta down.
  double kn = 0.0;
  double E_star = case_.materials.E_star();
  if (finite_) E_star = 1.0 / (1.0 / E_star + 1.0 / finite_->plane_modulus());  // the pair's
  if (spec_.normal_model == NormalModel::dynamic) kn = 2.0 * E_star * std::sqrt(state_.contact_area / M_PI);
  if (kn > 0.0 && F.z() > 0.0) {
    // The pressure's centroid, and the slipping traction (proportional to p) follow the load.
    // M = sum r x f, r = (x, y, -h): M_x = ybar F_z + h F_y, M_y = -xbar F_z - h F_x.
    const double mx = -state_.wrench.moment.y() - h * F.x(), my = state_.wrench.moment.x() - h * F.y();
    const double xbar = mx / F.z(), ybar = my / F.z();
    Eigen::Vector3d dF(0.0, 0.0, -kn);
    if (tangential_) {
      double sx = 0.0, sy = 0.0;
      for (std::size_t e = 0; e < solution_.state.size(); ++e)
        if (solution_.state[e] == 2) {
          sx += solution_.tx[e];
          sy += solution_.ty[e];
        }
      dF.x() = -kn * sx * case_.grid.area() / F.z();
      dF.y() = -kn * sy * case_.grid.area() / F.z();
    }
    J.position.col(2).head<3>() = dF;
    J.position.col(2).tail<3>() = Eigen::Vector3d(h * dF.y() + ybar * dF.z(), -h * dF.x() - xbar * dF.z(), 0.0);
  }
  if (F.z() > 0.0 && gap_) {  // (an fe_body's first-order tilt: left out)
    // The body turning moves its lowest point (2.6): the contact moves with it, carrying the
    // moment of the normal force, and the approach centre_height - z changes as a lift of the
    // centre (the position column's response to -dz).
    const GapSensitivity d = gap_->sensitivity(last_.orientation);
    for (int l = 0; l < 3; ++l) {
      J.orientation.col(l) = -d.centre_height(l) * J.position.col(2);
      J.orientation(3, l) += F.z() * d.lowest(1, l);
      J.orientation(4, l) -= F.z() * d.lowest(0, l);
    }
  }
  if (!tangential_) return J;
  // The model of the last evaluation (auto resolves after its first evaluation: that one's
  // Jacobian is already the resolved model's).
  const bool steady = steady_ && !off_axis_;
  // G = d(F_x, F_y, M_z)/d(q_x, q_y, q_z): transient q = a = dt (V_x - h W_y, V_y + h W_x, W_z),
  // steady q = a / (V_x dt) (creepages and spin).
  // The full linearisation, kappa != 0 included (the pressure follows the traction,
  // (4.2)-(4.3)): transient d(ds) = dm + B22 dtau + kappa B21 dp; steady, per element of
  // travel, d(ds) = dx dxi m + (B22 - S B22) dtau + kappa (B21 - S B21) dp. Without kappa the
  // steady creep law's own linearisation (compute_steady) is the same and cheaper.
  TangentialSensitivity::Coupling coupling;
  if (const LinearOperator* B21 = tangential_->tangential_from_normal()) {
    coupling.C = &tangential_->normal_compliance();
    coupling.B21 = steady ? tangential_->convective_from_normal() : B21;
    coupling.B32 = tangential_->normal_from_tangential();
    coupling.force_control = spec_.normal_model == NormalModel::quasi_static;
  }
  Eigen::Matrix3d G;
  // A kept sensitivity for the transient model only: the steady model's (one CG solve per mode
  // on the stick set) costs less than the chord iterations a gross-sliding creep law needs.
  const bool reuse = !fresh && !steady && has_kept_sensitivity_;
  if (reuse) {
    G = kept_sensitivity_;
    J.kept = true;
  } else if (!steady)
    G = sensitivity_.compute_full(tangential_->tangential_compliance(), coupling, *law_, case_.grid, solution_);
  else if (coupling.B21)
    G = case_.grid.dx *
        sensitivity_.compute_full(tangential_->convective_compliance(), coupling, *law_, case_.grid, solution_);
  else
    G = sensitivity_.compute_steady(tangential_->convective_compliance(), tangential_->tangential_compliance(),
                                    case_.grid, solution_);
  if (!reuse) {
    ++sensitivities_;
    kept_sensitivity_ = G;
    has_kept_sensitivity_ = !steady;
  }
  Eigen::Matrix<double, 6, 3> dq;  // the wrench rows per unit q_l
  for (int l = 0; l < 3; ++l) {
    dq(0, l) = G(0, l);
    dq(1, l) = G(1, l);
    dq(2, l) = 0.0;
    dq(3, l) = h * G(1, l);   // M_x = y p + h tau_y
    dq(4, l) = -h * G(0, l);  // M_y = -h tau_x - x p
    dq(5, l) = G(2, l);
  }
  // dq/d(V, W): a = dt (...) for transient; for steady also through the 1/V_x.
  const double s = steady ? 1.0 / last_.velocity.x() : dt_;
  J.velocity.col(0) = s * dq.col(0);
  J.velocity.col(1) = s * dq.col(1);
  J.omega.col(0) = s * h * dq.col(1);
  J.omega.col(1) = -s * h * dq.col(0);
  J.omega.col(2) = s * dq.col(2);
  if (steady) {
    const Eigen::Vector3d& V = last_.velocity;
    const Eigen::Vector3d& W = last_.omega;
    const Eigen::Vector3d q((V.x() - h * W.y()) / V.x(), (V.y() + h * W.x()) / V.x(), W.z() / V.x());
    J.velocity.col(0) -= (dq * q) / V.x();  // d q / d V_x = (e_x - q) / V_x
  }
  return J;
}

void ContactWrench::evaluate_at(const StepKinematics& k, double vertical_load) {
  const bool same = k.time == last_.time && k.position == last_.position && k.velocity == last_.velocity &&
                    k.omega == last_.omega;
  if (!same) evaluate(k, vertical_load);
}

ContactState ContactWrench::initial_contact(const StepKinematics& k) {
  if (spec_.normal_model != NormalModel::dynamic) return {};
  orient(k);
  last_ = k;
  if (!(contact_function() > 0.0)) return {};
  // At rest: the solve's rigid slip and travel vanish (dt only scales them); the model choice
  // (auto) waits for the first step's travel, and the memory stays the unloaded one.
  const bool resolved = model_resolved_, steady = steady_;
  StepKinematics at_rest = k;
  at_rest.velocity.setZero();
  at_rest.omega.setZero();
  begin_step(1.0);
  evaluate(at_rest, 0.0);
  audit_energy();
  ContactState initial = state_;
  initial.frictional_work = 0.0;
  initial.fields = nullptr;
  initial.pressure = nullptr;
  model_resolved_ = resolved;
  steady_ = steady;
  if (tangential_) tangential_->restore(committed_);
  state_ = ContactState{};
  has_kept_sensitivity_ = false;
  return initial;
}

double ContactWrench::contact_function() const {
  if (spec_.normal_model == NormalModel::quasi_static) return std::numeric_limits<double>::quiet_NaN();
  const std::vector<double>& heights = this->heights();
  const double lowest = heights.empty() ? 0.0 : *std::min_element(heights.begin(), heights.end());
  return centre_height() - last_.position.z() - lowest;
}

void ContactWrench::audit_energy() {
  state_.frictional_work = state_.elastic_energy = 0.0;
  if (!state_.in_contact) return;
  const double A = case_.grid.area();
  // The step's slip (3.8); the steady model's is per dx of travel, and the step travels V_x dt.
  if (tangential_)
    state_.frictional_work =
        frictional_work(solution_, A) * (steady_step_ ? last_.velocity.x() * dt_ / case_.grid.dx : 1.0);
  // The quasi-static normal model holds the body's height: its normal force does no work on the
  // body, and the normal part of the stored energy (with the kappa coupling's share) is left out
  // of the audit with it.
  const bool with_normal = spec_.normal_model == NormalModel::dynamic;
  const std::vector<double>& heights = this->heights();
  static const std::vector<double> none;
  state_.elastic_energy = elastic_energy(
      state_.pressure, heights, state_.approach, with_normal, tangential_ ? solution_.tx : none,
      tangential_ ? solution_.ty : none, tangential_ ? &tangential_->tangential_compliance() : nullptr,
      tangential_ && with_normal ? tangential_->tangential_from_normal() : nullptr, A, energy_scratch_);
}

void ContactWrench::accept(const StepKinematics& k, double vertical_load) {
  evaluate_at(k, vertical_load);
  audit_energy();
  if (tangential_) tangential_->save_memory(committed_);
  if (finite_) {  // the body's deformation at the accepted step (output, max displacement)
    static const std::vector<double> none;
    const bool touching = state_.in_contact;
    finite_->accept(touching && tangential_ ? solution_.tx : none, touching && tangential_ ? solution_.ty : none,
                    touching ? *state_.pressure : none);
  }
  accepted_in_contact_ = state_.in_contact;
  if (state_.in_contact) {
    ++steps_in_contact_;
    if (steady_ && off_axis_) ++transient_steps_;
  }
}

void ContactWrench::reject() {
  has_kept_sensitivity_ = false;
  if (tangential_) tangential_->restore(committed_);
}

}  // namespace dc::dynamics
