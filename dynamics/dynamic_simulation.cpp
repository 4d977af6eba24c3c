#include "dynamic_simulation.hpp"

#include <algorithm>
#include <cmath>

#include "dynamic_limits.hpp"
#include "simulation_run.hpp"
#include "errors.hpp"
#include "interrupt.hpp"

namespace dc::dynamics {
namespace {

StepperOptions stepper_options(const DynamicContactSpec& c) {
  StepperOptions o;
  o.scheme = c.dynamic->bdf2 ? Scheme::bdf2 : Scheme::bdf1;
  // The contact resultant is accurate to about the contact solver's tolerance: ask the step's
  // residual for a little less than that, relative to the body's speeds.
  o.newton.rel_tol = std::max(1e-10, 10.0 * c.solver.tol);
  o.newton.max_iterations = 40;
  // Chord steps with the last tangential sensitivity while they contract the residual tenfold
  // (the sensitivity, a GMRES solve per rigid mode, costs about a contact solve), accepted like
  // an extrapolated start at a tenth of the tolerance.
  o.newton.chord_contraction = 0.1;
  o.newton.inexact_share = 0.1;
  return o;
}

RigidBody make_body(const DynamicSpec& s, const FiniteBody* finite) {
  if (finite) return finite->rigid_body();  // the mesh's full inertia tensor
  return RigidBody::principal(s.mass, s.inertia[0], s.inertia[1], s.inertia[2], "body");
}

void check_agrees(const std::string& key, double given, double mesh) {
  if (std::abs(given - mesh) > 0.01 * std::abs(mesh))
    throw InputError(key, "is " + std::to_string(given) + " but the fe_body's mesh and density give " +
                              std::to_string(mesh) + " (leave it out to take the mesh's)");
}

Eigen::Vector3d vec(const std::array<double, 3>& a) { return {a[0], a[1], a[2]}; }

}  // namespace

RigidBodyState initial_state(const DynamicSpec& s) {
  RigidBodyState st;
  st.position = vec(s.position);
  st.velocity = vec(s.velocity);
  st.omega = vec(s.omega);
  return st;
}

DynamicSpec resolve_finite_body(const DynamicSpec& spec, const FiniteBody* finite) {
  DynamicSpec s = spec;
  if (!finite) return s;
  const RigidBody body = finite->rigid_body();
  const Eigen::Matrix3d& I = body.inertia_body();
  if (s.has_mass) check_agrees("body.mass", s.mass, body.mass());
  if (s.has_inertia)
    for (int k = 0; k < 3; ++k) check_agrees("body.inertia[" + std::to_string(k) + "]", s.inertia[k], I(k, k));
  if (s.has_radius) check_agrees("body.radius", s.radius, finite->centre_height());
  s.mass = body.mass();
  s.inertia = {I(0, 0), I(1, 1), I(2, 2)};
  s.radius = finite->centre_height();
  if (!s.has_position) s.position = {0.0, 0.0, s.radius};  // touching
  return s;
}

DynamicSimulation::DynamicSimulation(const DynamicContactSpec& c, std::unique_ptr<FiniteBody> finite)
    : before_limits_(dynamic_limits_before(c)),
      case_(c),
      spec_(resolve_finite_body(*c.dynamic, finite.get())),
      stepper_(make_body(spec_, finite.get()), stepper_options(c)),
      contact_(c, std::move(finite)) {}

Wrench DynamicSimulation::external(double t) const {
  Wrench w;
  for (int k = 0; k < 3; ++k) {
    w.force[k] = spec_.force[k].value + spec_.force[k].rate * t;
    w.moment[k] = spec_.moment[k].value + spec_.moment[k].rate * t;
  }
  return w;
}

void TimeStepCounts::add(double dt) {
  dt_min = dt_max == 0.0 ? dt : std::min(dt_min, dt);
  dt_max = std::max(dt_max, dt);
}

DynamicSimulation::ContactCounts DynamicSimulation::contact_counts() const {
  return {contact_.solves(), contact_.alternations(), contact_.sensitivities()};
}

bool DynamicSimulation::solve_step(RigidBodyState& state, double h, DynamicSample& sample, std::string& why,
                                   Scheme& scheme) {
  contact_.begin_step(h);
  auto wrench = [&](const StepKinematics& k) {
    const Wrench ext = external(k.time);
    const Wrench con = contact_.evaluate(k, ext.force.z());
    return Wrench{ext.force + con.force, ext.moment + con.moment};
  };
  auto jacobian = [&](const StepKinematics&, bool fresh) { return contact_.jacobian(fresh); };
  const StepReport report = stepper_.step(state, h, wrench, jacobian);
  sample.newton_iterations += report.iterations;
  sample.chord_steps += report.chord_steps;
  scheme = report.scheme_used;
  if (report.converged()) return true;
  contact_.reject();
  why = std::string("the step's Newton iteration did not converge (") + to_string(report.status) + ", residual " +
        std::to_string(report.residual) + " m/s)";
  return false;
}

bool DynamicSimulation::commit_step(const RigidBodyState& before, const RigidBodyState& state, double h,
                                    const ContactCounts& counts, DynamicSample& sample, StepSums& sums,
                                    std::string& why) {
  const StepKinematics end{state.position, state.orientation, state.velocity, state.omega, state.time};
  const Wrench ext = external(state.time);
  contact_.accept(end, ext.force.z());
  sample.contact_solves += contact_.solves() - counts.solves;
  sample.alternations += contact_.alternations() - counts.alternations;
  sample.sensitivities += contact_.sensitivities() - counts.sensitivities;
  const ContactState& cs = contact_.state();
  if (!cs.converged) {
    why = "the contact solve did not converge (" + cs.message + ")";
    return false;
  }
  const Wrench& con = cs.wrench;
  const Eigen::Vector3d F = ext.force + con.force;
  const Wrench ext_before = external(before.time);
  const Wrench& con_before = sums.contact_before;
  // The impulse: bdf1's own sum, dt F_{K+1} (m dV equals it step by step, (3.9)); for bdf2 the
  // trapezoidal rule, second order as the scheme is (dt F_{K+1} misses dt/2 of the force at the
  // run's start and end: 1 % of a pressed-in ball's release in 72 steps).
  const Eigen::Vector3d dI = spec_.bdf2 ? Eigen::Vector3d(0.5 * h * (ext_before.force + con_before.force + F))
                                        : Eigen::Vector3d(h * F);
  sums.impulse += dI;
  sums.impulse_size += dI.norm();
  // Work over the step's displacement and rotation by the trapezoidal rule (exact for a
  // wrench linear in the motion over the step): the end-of-step wrench alone misses a
  // share of every step's force change, which over an elastic impact's loading and
  // unloading adds up to ~10 % of the kinetic energy where the rebound loses 0.1 %.
  const Eigen::Vector3d dR = state.position - before.position;
  const Eigen::Vector3d dTheta = h * state.omega;
  sums.external_work +=
      0.5 * ((ext_before.force + ext.force).dot(dR) + (ext_before.moment + ext.moment).dot(dTheta));
  sums.contact_work +=
      0.5 * ((con_before.force + con.force).dot(dR) + (con_before.moment + con.moment).dot(dTheta));
  sums.contact_before = con;
  sums.dissipated += cs.frictional_work;
  sums.duration += h;
  return true;
}

void DynamicSimulation::record_step(Run& run, const RigidBodyState& state, const StepSums& sums,
                                    DynamicSample& sample) {
  DynamicResult& result = run.result;
  run.impulse += sums.impulse;
  run.impulse_size += sums.impulse_size;
  run.contact_at_step_start = sums.contact_before;
  run.external_work += sums.external_work;
  run.contact_work += sums.contact_work;
  const ContactState& cs = contact_.state();
  ++result.steps;
  result.worst_certificate = std::max(result.worst_certificate, cs.certificate);
  result.last_certificate = cs.certificate;
  if (cs.in_contact) ++result.backends[cs.backend];
  if (cs.in_contact && cs.fallback_used) ++result.fallback_steps;
  sample.state = state;
  sample.contact = cs.wrench;
  sample.external = external(state.time);
  sample.contact_state = cs;
  sample.kinetic_energy = kinetic_energy(stepper_.body(), state);
  sample.external_work = run.external_work;
  sample.contact_work = run.contact_work;
  run.dissipated += sums.dissipated;
  run.largest_elastic = std::max(run.largest_elastic, cs.elastic_energy);
  EnergyAudit& e = sample.energy;
  e.work_of_loads = run.external_work;
  e.kinetic_change = sample.kinetic_energy - run.initial_kinetic;
  e.elastic = cs.elastic_energy;
  e.elastic_initial = run.initial_elastic;
  e.dissipated = run.dissipated;
  e.numerical_damping = e.work_of_loads - e.kinetic_change - (e.elastic - e.elastic_initial) - e.dissipated;
  sample.frictional_power = sums.duration > 0.0 ? sums.dissipated / sums.duration : 0.0;
  if (sample.frictional_power > result.peak_frictional_power) {
    result.peak_frictional_power = sample.frictional_power;
    result.peak_power_time = state.time;
  }
  result.last_frictional_power = sample.frictional_power;
  result.energy = e;
  sample.step = result.steps;
  sample.finite_body = contact_.finite_body();
  run.limits.add(sample);
  if (run.on_step) run.on_step(sample);
}

void DynamicSimulation::add_counts(DynamicResult& result, const DynamicSample& sample) {
  result.newton_iterations += sample.newton_iterations;
  result.contact_solves += sample.contact_solves;
  result.alternations += sample.alternations;
  result.sensitivities += sample.sensitivities;
  result.chord_steps += sample.chord_steps;
}

DynamicResult DynamicSimulation::run(const std::function<void(const DynamicSample&)>& on_step) {
  Run run(case_, on_step);
  DynamicResult& result = run.result;
  run.state = initial_state(spec_);
  result.initial = run.state;
  result.adaptive = spec_.adaptive;
  const RigidBody& body = stepper_.body();
  const double ke0 = kinetic_energy(body, run.state);
  run.initial_kinetic = ke0;
  bool start_known = true;
  {
    // A body started pressed in: the energy it stores and the wrench the first step's work starts from.
    const RigidBodyState& s0 = run.state;
    const ContactState initial =
        contact_.initial_contact({s0.position, s0.orientation, s0.velocity, s0.omega, s0.time});
    run.initial_elastic = initial.elastic_energy;
    run.largest_elastic = initial.elastic_energy;
    run.contact_at_step_start = initial.wrench;
    result.energy.elastic = result.energy.elastic_initial = initial.elastic_energy;
    result.worst_certificate = initial.certificate;
    start_known = initial.converged;
    if (!start_known)
      result.status = "stopped at t = 0 s: the contact solve of the body started pressed into the half-space did not "
                      "converge (" + initial.message + "); its stored energy and force are not known";
  }
  if (start_known) {
    if (spec_.adaptive) run_adaptive(run);
    else run_fixed(run);
  }
  const RigidBodyState& state = run.state;
  result.time_steps.accepted = result.steps;
  result.time_steps.rejected = result.rejected_steps;
  result.contact_model = contact_.model_used();
  result.final = state;
  const Eigen::Vector3d dp = body.mass() * (state.velocity - result.initial.velocity);
  result.momentum_imbalance =
      (dp - run.impulse).norm() / std::max({run.impulse_size, body.mass() * state.velocity.norm(), 1e-300});
  const double ke = kinetic_energy(body, state);
  result.energy_imbalance =
      std::abs(ke - ke0 - run.external_work - run.contact_work) /
      std::max({ke0, ke, std::abs(run.external_work), std::abs(run.contact_work), 1e-300});
  result.energy_relative_residual =
      result.energy.numerical_damping / std::max({ke0, ke, std::abs(result.energy.work_of_loads), run.largest_elastic,
                                                  result.energy.dissipated, 1e-300});
  result.limits = before_limits_;
  for (ResultLimit& l : run.limits.limits(result)) result.limits.push_back(std::move(l));
  return std::move(run.result);
}

void DynamicSimulation::run_fixed(Run& run) {
  DynamicResult& result = run.result;
  RigidBodyState& state = run.state;
  const int n_steps = std::max(1, static_cast<int>(std::ceil(spec_.t_end / spec_.dt - 1e-9)));
  constexpr int kMaxHalvings = 6;

  for (int step = 1; step <= n_steps; ++step) {
    const double t_target = std::min(spec_.t_end, step * spec_.dt);
    DynamicSample sample;
    // One step of the nominal dt, or 2^m sub-steps of it after failures (halving, then back).
    bool ok = false;
    std::string why;
    const RigidBodyState step_start = state;
    StepSums sums;
    try {
      throw_if_interrupted();
      for (int halvings = 0; halvings <= kMaxHalvings && !ok; ++halvings) {
        if (halvings > 0) ++result.rejected_steps;
        const int parts = 1 << halvings;
        const RigidBodyState start = state;
        const double h = (t_target - state.time) / parts;
        ok = true;
        sums = StepSums{};
        sums.contact_before = run.contact_at_step_start;
        for (int part = 0; part < parts && ok; ++part) {
          const ContactCounts counts = contact_counts();
          const RigidBodyState before = state;
          Scheme scheme = Scheme::bdf1;
          ok = solve_step(state, h, sample, why, scheme) && commit_step(before, state, h, counts, sample, sums, why);
        }
        if (!ok) {
          state = start;
          stepper_.reset();
          continue;
        }
        result.time_steps.add(h);
      }
    } catch (const Interrupted&) {  // the steps so far stand
      result.interrupted = true;
      why = "interrupted";
      ok = false;
    } catch (const InputError& e) {  // nothing a smaller step could mend
      result.input_error = e.what();
      why = e.what();
      ok = false;
    }
    if (!ok) {
      contact_.reject();
      state = step_start;
      stepper_.reset();
    }
    add_counts(result, sample);
    if (!ok) {
      result.status = "stopped at t = " + std::to_string(state.time) + " s: " + why;
      break;
    }
    record_step(run, state, sums, sample);
  }
  result.completed = result.steps == n_steps;
}

}  // namespace dc::dynamics
