#pragma once
// The run of a "dynamic" case: the rigid body (2.20)-(2.21) stepped by (3.9)-(3.10) with the
// contact wrench (contact_wrench.hpp) solved at the end-of-step kinematics inside every Newton
// iteration, the external loads value + rate t, step halving on a failed step, and the
// bookkeeping of the run (momentum and energy balances, worst certificate).
#include <functional>
#include <map>
#include <memory>
#include <string>

#include "dynamic_spec.hpp"
#include "contact_limits.hpp"
#include "contact_wrench.hpp"
#include "rigid_body.hpp"
#include "time_stepper.hpp"

namespace dc::dynamics {

/// The energy audit of a run from t = 0 (docs/wear_energy.md "Dynamic runs"): the work of the
/// applied loads goes into the kinetic energy (translational and rotational), the contact's
/// stored elastic energy, the frictional work dissipated in the contact, and the scheme's own
/// numerical damping, the residual (bdf1 damps at O(dt), bdf2 at O(dt^2)). A body that starts
/// pressed into the half-space stores elastic energy at t = 0 (ContactWrench::initial_contact).
struct EnergyAudit {
  double work_of_loads = 0.0;      ///< of the applied force and moment (trapezoidal over each step; J, 2-D J/m)
  double kinetic_change = 0.0;     ///< KE - KE(0)
  double elastic = 0.0;            ///< the contact's stored elastic energy now
  double elastic_initial = 0.0;    ///< stored at t = 0 (0 unless the body starts pressed in)
  double dissipated = 0.0;         ///< sum of the steps' frictional work -sum tau . ds A
  /// work_of_loads - kinetic_change - (elastic - elastic_initial) - dissipated: what the scheme
  /// took (> 0) or gave.
  double numerical_damping = 0.0;
};

/// One accepted step.
struct DynamicSample {
  RigidBodyState state;       ///< at the end of the step
  Wrench contact;             ///< the contact's force and moment about the centre of mass
  Wrench external;            ///< the applied loads at the end of the step
  ContactState contact_state; ///< approach, area, stick/slip, creepage, certificate (fields: the last solution)
  double kinetic_energy = 0.0;
  double external_work = 0.0;  ///< of the applied loads since t = 0 (J)
  double contact_work = 0.0;   ///< of the contact wrench since t = 0 (J)
  EnergyAudit energy;          ///< since t = 0, at the end of this step
  double frictional_power = 0.0;  ///< this step's frictional work over its length (W; 2-D W/m)
  int newton_iterations = 0;   ///< of this step
  int chord_steps = 0;         ///< of this step: Newton updates with the last sensitivity kept
  int contact_solves = 0;      ///< of this step (retries included)
  int alternations = 0;        ///< their (p, tau) alternations (4.26)-(4.27)
  int sensitivities = 0;       ///< tangential sensitivities computed for Newton's Jacobian (kept ones not counted)
  int step = 0;                ///< 1-based
  const FiniteBody* finite_body = nullptr;  ///< an fe_body (its displacement() at this step); null without
};

/// The steps of a run (summary.json "time_steps"): accepted and rejected ones, and the shortest and
/// longest accepted step (s). Fixed steps: a nominal step halved after a failure counts once as
/// accepted, its halvings as rejected, its sub-steps in dt_min.
struct TimeStepCounts {
  int accepted = 0, rejected = 0;
  int error_rejections = 0;  ///< adaptive: rejected for the local error (the rest: events, failed solves)
  int event_rejections = 0;  ///< adaptive: rejected to land on a contact event
  int events = 0;            ///< adaptive: contact events located (first touch, release)
  double dt_min = 0.0, dt_max = 0.0;
  void add(double dt);       ///< an accepted step of dt
};

struct DynamicResult {
  bool completed = false;        ///< reached t_end with every step converged
  std::string status = "converged";  ///< or why and when it stopped
  bool interrupted = false;      ///< stopped by an interrupt (core/interrupt.hpp) before a step
  std::string input_error;       ///< "key: reason" when a step met input it cannot take (e.g. an
                                 ///< upright-only profile tilting): the run stopped there
  int steps = 0, rejected_steps = 0;  ///< accepted steps; step halvings after a failed step (adaptive: rejected steps)
  bool adaptive = false;         ///< time.adaptive
  TimeStepCounts time_steps;
  int newton_iterations = 0, contact_solves = 0;
  int alternations = 0;          ///< (p, tau) alternations of the contact solves (one per solve at kappa = 0)
  int sensitivities = 0;         ///< tangential sensitivities computed (chord steps reuse the last)
  int chord_steps = 0;           ///< Newton updates with a kept sensitivity
  std::string contact_model;     ///< transient | steady (auto resolved)
  std::map<std::string, int> backends;  ///< accepted steps in contact per backend that solved them
  int fallback_steps = 0;        ///< accepted steps whose contact solve fell back to another backend
  double worst_certificate = 0.0, last_certificate = 0.0;
  /// |m dV - impulse| / max(|impulse| summed per step, m |V|) over the run: bdf1 sums dt F_{K+1}
  /// (round-off); bdf2 the trapezoidal impulse (O(dt^2)).
  double momentum_imbalance = 0.0;
  double energy_imbalance = 0.0;    ///< |KE_end - KE_0 - W_external - W_contact| / max(KE, |W|)
  EnergyAudit energy;               ///< at the end of the run
  /// numerical_damping / max(KE_0, KE_end, |work_of_loads|, the largest elastic energy, dissipated)
  double energy_relative_residual = 0.0;
  double peak_frictional_power = 0.0, peak_power_time = 0.0;  ///< the largest step's power (W) and its end time (s)
  double last_frictional_power = 0.0;                         ///< the last step's (W)
  RigidBodyState initial, final;
  /// What is known wrong or outside the model (dynamic_limits.hpp): the warnings found before the
  /// run (its errors are InputErrors of the constructor), then the limits of the steps run.
  std::vector<ResultLimit> limits;
};

class DynamicSimulation {
 public:
  /// `finite`: the body of a case with an fe_body (finite/finite_body_contact.hpp's
  /// make_finite_body); its mass, inertia and centre height are the mesh's. Throws InputError for
  /// what is known wrong before the run (dynamic_limits_before).
  explicit DynamicSimulation(const DynamicContactSpec& c, std::unique_ptr<FiniteBody> finite = nullptr);
  /// Runs to t_end; `on_step` after every accepted step (output, progress). Never throws for
  /// non-convergence, an interrupt or input a step cannot take: the result says where and why
  /// it stopped, with the steps before it, and its result limits (DynamicResult::limits).
  DynamicResult run(const std::function<void(const DynamicSample&)>& on_step);
  /// The worn depth added to the body's gap at every evaluation (ContactWrench::set_worn_gap).
  void set_worn_gap(ContactWrench::WornGap worn) { contact_.set_worn_gap(std::move(worn)); }

  const RigidBody& body() const { return stepper_.body(); }
  /// The applied force and moment at time t (loads: value + rate t).
  Wrench external(double t) const;
  /// The finite-element body (null without an fe_body).
  const FiniteBody* finite_body() const { return contact_.finite_body(); }

 private:
  /// What a run carries from step to step: its result, limits, balances' sums and output.
  struct Run;
  /// Counts of the contact's solves before a step (the step's share is the difference).
  struct ContactCounts {
    int solves = 0, alternations = 0, sensitivities = 0;
  };
  /// The sums of one step (its sub-steps), added to the run's when the step is accepted.
  struct StepSums {
    Eigen::Vector3d impulse = Eigen::Vector3d::Zero();
    double impulse_size = 0.0, external_work = 0.0, contact_work = 0.0;
    double dissipated = 0.0, duration = 0.0;  ///< frictional work and length of the step's sub-steps
    Wrench contact_before;  ///< the contact wrench at the step's start, then at its end
  };

  /// Newton for one step of h from `state` (the contact's step begun, solved at the end-of-step
  /// kinematics, not committed): false with `why` (the contact rejected, `state` as it was) when
  /// it did not converge. `scheme` the scheme it took.
  bool solve_step(RigidBodyState& state, double h, DynamicSample& sample, std::string& why, Scheme& scheme);
  /// Commits a solved step from `before` to `state` (the contact's memory) and adds its
  /// impulse and work to `sums`: false with `why` when the contact solve at its end did not converge.
  bool commit_step(const RigidBodyState& before, const RigidBodyState& state, double h, const ContactCounts& counts,
                   DynamicSample& sample, StepSums& sums, std::string& why);
  /// An accepted step: its sums into the run's, the result's counts, the sample to the limits
  /// and to the output.
  void record_step(Run& run, const RigidBodyState& state, const StepSums& sums, DynamicSample& sample);
  ContactCounts contact_counts() const;
  /// A step's Newton iterations and solves (taken or not) into the run's.
  static void add_counts(DynamicResult& result, const DynamicSample& sample);
  void run_fixed(Run& run);
  /// time.adaptive (adaptive_steps.cpp).
  void run_adaptive(Run& run);

  std::vector<ResultLimit> before_limits_;  ///< the warnings of dynamic_limits_before
  const DynamicContactSpec& case_;
  DynamicSpec spec_;  ///< the case's, with an fe_body's mass, inertia and radius from its mesh
  RigidBodyStepper stepper_;
  ContactWrench contact_;
};

/// The case's dynamic blocks with an fe_body's mass, inertia and radius (height of the centre of
/// mass over the lowest point) from its mesh; given ones must agree within 1 % (InputError
/// naming body.mass, body.inertia or body.radius).
DynamicSpec resolve_finite_body(const DynamicSpec& spec, const FiniteBody* finite);

/// The body's initial state from the case (position, velocity, omega; orientation identity).
RigidBodyState initial_state(const DynamicSpec& spec);

}  // namespace dc::dynamics
