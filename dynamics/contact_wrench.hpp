#pragma once
// The contact resultant of one step of the moving body (issue: the paper's (3.8)-(3.10)): from
// trial end-of-step kinematics (R, q, V, Omega), the approach and the undeformed gap (2.6) on a
// grid that follows the body (its origin under the centre of mass), the rigid slip V + Omega x r
// of each element over the step, the normal pressure (4.7), the tangential traction (4.8) with
// the memory of the previous step carried over the step's travel (V_x dt, V_y dt), and the resultant force
// and moment about the centre of mass. The memory is committed only when the step is accepted.
// Operators and plans are set up once (constructor); solves are warm-started from the last.
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "body_gap.hpp"
#include "contact_energy.hpp"
#include "dynamic_spec.hpp"
#include "contact_sensitivity.hpp"
#include "finite_body.hpp"
#include "friction_law.hpp"
#include "normal_problem.hpp"
#include "tangential_problem.hpp"
#include "wrench.hpp"

namespace dc::dynamics {

/// What the last evaluation found (the contact at the trial kinematics).
struct ContactState {
  Wrench wrench;                 ///< the contact's force and moment about the centre of mass
  bool in_contact = false;
  double approach = 0.0;         ///< m (quasi-static / 2-D: from the force-controlled solve)
  double contact_area = 0.0;     ///< m^2 (2-D: contact length, m)
  double stick_fraction = 0.0;   ///< stick area / contact area (0 without contact)
  int n_contact = 0, n_stick = 0, n_slip = 0;
  double creepage = 0.0;         ///< longitudinal creepage: the rigid slip velocity at the contact centre along the
                                 ///< horizontal travel, over the travel speed (0 at rest); a pure x roll: slip_x / V_x
  double certificate = 0.0;      ///< worst residual of the contact solve (0 without contact)
  bool converged = true;
  std::string message;           ///< why not converged
  std::string backend;           ///< the backend whose solution was kept ("" without contact)
  bool fallback_used = false;    ///< the requested backend (or auto's first) failed and another took over
  const TangentialSolution* fields = nullptr;  ///< the last solution (null without friction or contact)
  const std::vector<double>* pressure = nullptr;  ///< the last pressure field (null without contact)
  /// Of an accepted step (ContactWrench::accept; 0 before): the frictional work dissipated over
  /// the step, -sum tau . ds A with ds the step's slip (2.4)-(2.5) (J; 2-D J/m), and the elastic
  /// energy stored at its end (contact_energy.hpp).
  double frictional_work = 0.0;
  double elastic_energy = 0.0;
};

class ContactWrench {
 public:
  /// The case's grid, materials, profile, friction (optional: frictionless), body and models;
  /// with an fe_body, `finite` its body (finite_body.hpp; InputError("fe_body") when null).
  explicit ContactWrench(const DynamicContactSpec& c, std::unique_ptr<FiniteBody> finite = nullptr);
  ~ContactWrench();

  /// The worn depth (m, both bodies summed) on the grid at trial kinematics k, written into
  /// `depth` (one per element): it is added to the body's undeformed gap (2.6) at every
  /// evaluation (a rigid profile's; wear over a dynamic run, apps/runs/dynamic_wear.hpp).
  using WornGap = std::function<void(const StepKinematics& k, std::vector<double>& depth)>;
  void set_worn_gap(WornGap worn) { worn_gap_ = std::move(worn); }

  /// Starts a step of length dt at time t (the memory of the accepted state is kept).
  void begin_step(double dt);
  /// The contact wrench at trial end-of-step kinematics; `vertical_load` is the applied vertical
  /// force at t_{K+1} (the quasi-static normal model balances it).
  Wrench evaluate(const StepKinematics& k, double vertical_load);
  /// The sensitivity of the last evaluation (stick/slip set fixed), for Newton's Jacobian.
  /// `fresh` false: the transient model's tangential sensitivity (the costly part: one GMRES
  /// solve per rigid mode) may be the one kept from an earlier evaluation (WrenchJacobian::kept).
  WrenchJacobian jacobian(bool fresh = true);
  /// The step is accepted at `k`: the memory becomes the state at its end (re-solved if the
  /// last evaluation was elsewhere).
  void accept(const StepKinematics& k, double vertical_load);
  /// The step was rejected: back to the memory of the last accepted state.
  void reject();
  /// The contact at `k` without committing it (the last evaluation's when it was at `k`): what
  /// accept(k, ...) would take, for deciding on the step first (adaptive steps).
  void evaluate_at(const StepKinematics& k, double vertical_load);
  /// The contact of the initial state `k` for the energy audit (dynamic normal model): a body that
  /// starts pressed into the half-space (contact_function() > 0) stores elastic energy at t = 0
  /// and presses on it with a wrench there. Solved at rest (no slip, no traction memory; with
  /// kappa != 0 the traction the indentation itself makes), its wrench and elastic_energy returned
  /// and nothing committed (the first step starts from the unloaded memory, as before). Touching,
  /// above, or the quasi-static normal model: none (a default ContactState).
  ContactState initial_contact(const StepKinematics& k);
  /// The event function of contact at the last evaluation (dynamic normal model): the approach
  /// centre_height - z less the smallest undeformed gap of the grid's elements, positive when
  /// an element is in contact (m); NaN for the quasi-static normal model.
  double contact_function() const;

  const ContactState& state() const { return state_; }
  /// The tangential model actually used ("transient" or "steady"; auto resolved on the first
  /// step), and the accepted steps the steady model left to the transient one because their
  /// travel was not along +x: "steady (transient in 3 of 120 steps: travel not along +x)".
  std::string model_used() const;
  /// The steady model rolls along +x: it takes a step only when V_x > 0 and |V_y| <= 0.1 V_x
  /// (the travel within 5.7 degrees of x); other steps are transient.
  static bool travel_along_x(const Eigen::Vector3d& velocity);
  int solves() const { return solves_; }
  /// The (p, tau) alternations (4.26)-(4.27) of these solves (one per solve when kappa = 0 or
  /// without friction).
  int alternations() const { return alternations_; }
  /// Tangential sensitivities computed (the kept ones not counted).
  int sensitivities() const { return sensitivities_; }
  /// The finite-element body (null without an fe_body).
  const FiniteBody* finite_body() const { return finite_.get(); }

 private:
  NormalSpec normal_load(const StepKinematics& k, double vertical_load) const;
  /// The accepted step's frictional work and stored elastic energy into state_.
  void audit_energy();
  void no_contact();
  /// The undeformed gap at the body's orientation (the problems' heights when it changes).
  void orient(const StepKinematics& k);
  /// Height of the centre of mass over the body's lowest point (the approach's reference).
  double centre_height() const;
  /// The gap the problems hold: the body's (or fe_body's), plus the worn depth when set.
  const std::vector<double>& heights() const;

  const DynamicContactSpec& case_;
  const DynamicSpec& spec_;
  SolverOptions solver_;
  std::optional<BodyGap> gap_;                     // the profile's gap (rigid-body profile)
  WornGap worn_gap_;                               // the worn depth added to it (none: unworn)
  std::vector<double> worn_depth_, worn_heights_;  // its last value, and gap_ + it
  std::unique_ptr<FiniteBody> finite_;             // or the fe_body's (finite contact in each step)
  std::unique_ptr<NormalProblem> own_normal_;
  std::unique_ptr<TangentialProblem> own_tangential_;
  NormalProblem* normal_ = nullptr;                // frictionless
  TangentialProblem* tangential_ = nullptr;        // with friction
  std::optional<FrictionLaw> law_;                 // with friction
  TangentialMemory committed_;
  TangentialSensitivity sensitivity_;
  TangentialSolution solution_;
  RollingLoad rolling_;  // the steady model's load of the last solve
  NormalSolution normal_solution_;
  ContactState state_;
  StepKinematics last_{};
  double dt_ = 0.0;
  double lever_ = 0.0;  // height of the centre of mass over the contact plane at the last evaluation
  bool steady_ = false;            // the steady model chosen (or auto resolved to it)
  bool off_axis_ = false;          // the last evaluation's travel was not along +x
  bool steady_step_ = false;       // the last evaluation was solved by the steady model
  EnergyScratch energy_scratch_;   // audit_energy's vectors
  bool model_resolved_ = false;
  int steps_in_contact_ = 0;       // accepted steps in contact
  bool accepted_in_contact_ = false;  // the last accepted step was in contact (its answer starts the next)
  int transient_steps_ = 0;        // of these, solved by the transient model although steady_
  int solves_ = 0;
  int alternations_ = 0;
  int trials_in_step_ = 0;         // evaluations since begin_step (the later ones start near)
  int sensitivities_ = 0;
  // The last tangential sensitivity computed, d(F_x, F_y, M_z)/d(rigid modes) (transient model).
  Eigen::Matrix3d kept_sensitivity_ = Eigen::Matrix3d::Zero();
  bool has_kept_sensitivity_ = false;
};

}  // namespace dc::dynamics
