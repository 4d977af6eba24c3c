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

/// One accepted step.
struct DynamicSample {
  RigidBodyState state;       ///< at the end of the step
  Wrench contact;             ///< the contact's force and moment about the centre of mass
  Wrench external;            ///< the applied loads at the end of the step
  ContactState contact_state; ///< approach, area, stick/slip, creepage, certificate (fields: the last solution)
  double kinetic_energy = 0.0;
  double external_work = 0.0;  ///< of the applied loads since t = 0 (J)
  double contact_work = 0.0;   ///< of the contact wrench since t = 0 (J)
  int newton_iterations = 0;   ///< of this step
  int chord_steps = 0;         ///< of this step: Newton updates with the last sensitivity kept
  int contact_solves = 0;      ///< of this step (retries included)
  int alternations = 0;        ///< their (p, tau) alternations (4.26)-(4.27)
  int sensitivities = 0;       ///< tangential sensitivities computed for Newton's Jacobian (kept ones not counted)
  int step = 0;                ///< 1-based
  const FiniteBody* finite_body = nullptr;  ///< an fe_body (its displacement() at this step); null without
};

struct DynamicResult {
  bool completed = false;        ///< reached t_end with every step converged
  std::string status = "converged";  ///< or why and when it stopped
  bool interrupted = false;      ///< stopped by an interrupt (core/interrupt.hpp) before a step
  std::string input_error;       ///< "key: reason" when a step met input it cannot take (e.g. an
                                 ///< upright-only profile tilting): the run stopped there
  int steps = 0, rejected_steps = 0;  ///< accepted steps; step halvings after a failed step
  int newton_iterations = 0, contact_solves = 0;
  int alternations = 0;          ///< (p, tau) alternations of the contact solves (one per solve at kappa = 0)
  int sensitivities = 0;         ///< tangential sensitivities computed (chord steps reuse the last)
  int chord_steps = 0;           ///< Newton updates with a kept sensitivity
  std::string contact_model;     ///< transient | steady (auto resolved)
  std::map<std::string, int> backends;  ///< accepted steps in contact per backend that solved them
  int fallback_steps = 0;        ///< accepted steps whose contact solve fell back to another backend
  double worst_certificate = 0.0, last_certificate = 0.0;
  double momentum_imbalance = 0.0;  ///< |m dV - sum dt F| / max(sum dt |F|, m |V|) over the run (bdf1: round-off)
  double energy_imbalance = 0.0;    ///< |KE_end - KE_0 - W_external - W_contact| / max(KE, |W|)
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

  const RigidBody& body() const { return stepper_.body(); }
  /// The applied force and moment at time t (loads: value + rate t).
  Wrench external(double t) const;
  /// The finite-element body (null without an fe_body).
  const FiniteBody* finite_body() const { return contact_.finite_body(); }

 private:
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
