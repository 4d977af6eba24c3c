// The run of a dynamic case with time.adaptive (docs/dynamics.md "Adaptive time steps"): each
// step's local error estimated against an explicit predictor (step_size_control.hpp), the step
// rejected and retried shorter when the error exceeds the tolerance, and cut at contact events
// (first touch, release; the start and end of gross sliding) so that the step ending in the new
// contact state ends just after the event; after an event bdf2 restarts with a bdf1 step of at
// most time.dt.
#include <algorithm>

#include "dynamic_simulation.hpp"
#include "errors.hpp"
#include "interrupt.hpp"
#include "number_text.hpp"
#include "simulation_run.hpp"
#include "step_size_control.hpp"

namespace dc::dynamics {
namespace {

/// An event is located when the step crossing it ends within this share of time.dt after it
/// (or within time.dt_min).
constexpr double kEventShare = 0.01;

Wrench wrench_sum(const Wrench& a, const Wrench& b) { return {a.force + b.force, a.moment + b.moment}; }

/// Gross sliding: in contact with friction and no element sticking (the friction force at its
/// bound, mu P for Coulomb); its start and end (stick -> slip -> stick) are events.
bool gross_sliding(const ContactState& cs, bool friction) { return friction && cs.in_contact && cs.n_stick == 0; }

}  // namespace

void DynamicSimulation::run_adaptive(Run& run) {
  DynamicResult& result = run.result;
  TimeStepCounts& counts = result.time_steps;
  RigidBodyState& state = run.state;
  const RigidBody& body = stepper_.body();
  StepSizeOptions o;
  o.rtol = spec_.rtol;
  o.atol = spec_.atol;
  o.dt_min = spec_.dt_min;
  o.dt_max = spec_.dt_max;
  const double t_end = spec_.t_end, t_done = t_end * (1.0 - 1e-12);
  const double event_tolerance = std::max(o.dt_min, kEventShare * spec_.dt);
  LocalErrorEstimate estimate(body.gyration_radius());

  double h = spec_.dt;
  bool in_contact = false;  // at the last accepted state
  bool sliding = false;     // gross sliding there
  const bool friction = case_.friction.has_value();
  double g_start = 0.0;     // its event function (ContactWrench::contact_function)
  bool after_rejection = false;
  bool failed = false;
  std::string why;
  RigidBodyState start = state;
  try {
    {  // y' at the start: the contact at the initial state, not committed
      const int solves = contact_.solves();
      contact_.begin_step(h);
      const Wrench ext = external(state.time);
      const StepKinematics k0{state.position, state.orientation, state.velocity, state.omega, state.time};
      const Wrench con = contact_.evaluate(k0, ext.force.z());
      in_contact = contact_.state().in_contact;
      sliding = gross_sliding(contact_.state(), friction);
      g_start = contact_.contact_function();
      contact_.reject();
      result.contact_solves += contact_.solves() - solves;
      estimate.restart(trajectory_point(body, state, wrench_sum(ext, con)));
    }
    while (state.time < t_done) {
      throw_if_interrupted();
      const double rest = t_end - state.time;
      h = std::min(h, rest);
      if (rest - h < 0.01 * h) h = rest;  // no sliver of a last step
      DynamicSample sample;
      start = state;
      const ContactCounts before = contact_counts();
      Scheme scheme = Scheme::bdf1;
      bool solved = solve_step(state, h, sample, why, scheme);
      bool converged = solved;
      double err = 0.0, theta = 1.0;
      bool crossed = false;
      if (solved) {
        const Wrench ext = external(state.time);
        contact_.evaluate_at({state.position, state.orientation, state.velocity, state.omega, state.time},
                             ext.force.z());
        const ContactState& cs = contact_.state();
        converged = cs.converged;
        if (!converged) why = "the contact solve did not converge (" + cs.message + ")";
        err = estimate.error(state, scheme, o);
        // Touch or release: the secant on the event function; the start or end of gross
        // sliding: bisection.
        crossed = cs.in_contact != in_contact || gross_sliding(cs, friction) != sliding;
        if (cs.in_contact != in_contact) theta = event_share(g_start, contact_.contact_function());
        else if (crossed) theta = 0.5;
      }
      const bool at_dt_min = h <= o.dt_min * (1.0 + 1e-9);
      const bool locate = converged && crossed && (1.0 - theta) * h > event_tolerance && !at_dt_min;
      if (!converged || err > 1.0 || locate) {
        if (solved) {  // solved but not taken: back to the step's start
          contact_.reject();
          stepper_.retract();
        }
        state = start;
        ++result.rejected_steps;
        add_counts(result, sample);
        if (at_dt_min) {
          if (converged)
            why = "the local error (" + six_digits(err) + " times the tolerance of time.rtol and time.atol) "
                  "cannot be met at time.dt_min (" + six_digits(o.dt_min) + " s)";
          else
            why += " at time.dt_min (" + six_digits(o.dt_min) + " s)";
          failed = true;
          break;
        }
        if (!converged) {
          h = std::max(o.dt_min, 0.25 * h);
        } else if (locate) {
          ++counts.event_rejections;
          // End the retried step just after the event, its estimate from the event function (secant).
          h = std::max(o.dt_min, std::min(theta * h + 0.5 * event_tolerance, 0.5 * (1.0 + theta) * h));
        } else {
          ++counts.error_rejections;
          h = propose_step(h, err, LocalErrorEstimate::order(scheme), true, o);
        }
        after_rejection = true;
        continue;
      }
      StepSums sums;
      sums.contact_before = run.contact_at_step_start;
      if (!commit_step(start, state, h, before, sample, sums, why)) {  // not expected: evaluated above
        add_counts(result, sample);
        failed = true;
        break;
      }
      add_counts(result, sample);
      counts.add(h);
      record_step(run, state, sums, sample);
      const TrajectoryPoint p =
          trajectory_point(body, state, wrench_sum(external(state.time), contact_.state().wrench));
      double next = propose_step(h, err, LocalErrorEstimate::order(scheme), after_rejection, o);
      if (crossed) {  // an event: bdf2 restarts (a bdf1 step of at most time.dt)
        ++counts.events;
        in_contact = contact_.state().in_contact;
        sliding = gross_sliding(contact_.state(), friction);
        stepper_.reset();
        estimate.restart(p);
        next = std::min(next, spec_.dt);
      } else {
        estimate.accept(p);
      }
      g_start = contact_.contact_function();
      after_rejection = false;
      h = next;
    }
  } catch (const Interrupted&) {  // the steps so far stand
    result.interrupted = true;
    why = "interrupted";
    failed = true;
  } catch (const InputError& e) {  // nothing a smaller step could mend
    result.input_error = e.what();
    why = e.what();
    failed = true;
  }
  if (failed) {
    contact_.reject();
    state = start;
    stepper_.reset();
    result.status = "stopped at t = " + std::to_string(state.time) + " s: " + why;
  }
  result.completed = !failed && state.time >= t_done;
}

}  // namespace dc::dynamics
