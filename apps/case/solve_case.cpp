// A case's problems built from its specs and solved: the normal problem, and the tangential
// block (tangential_spec.hpp) as one step, steady rolling, or a loading history with memory.
#include "solve_case.hpp"

#include <chrono>
#include <stdexcept>

#include "errors.hpp"
#include "interrupt.hpp"
#include "profile.hpp"

namespace dc {

std::vector<double> contact_heights(const ContactSpec& c, const std::vector<double>& worn_depth) {
  std::vector<double> h = profile_heights(c.profile, c.grid);
  if (!worn_depth.empty()) {
    if (worn_depth.size() != h.size()) throw std::invalid_argument("contact_heights: one worn depth per element");
    for (std::size_t e = 0; e < h.size(); ++e) h[e] += worn_depth[e];  // worn material opens the gap (2.6)
  }
  return h;
}

NormalSolution solve_normal_case(const ContactSpec& c, const ProgressCallback& progress,
                                 const std::vector<double>* warm_pressure) {
  NormalProblem problem(c.grid, c.materials, contact_heights(c), c.solver.operator_kind);
  if (warm_pressure && warm_pressure->size() == c.grid.size()) problem.set_warm_start(*warm_pressure);
  return problem.solve(c.normal, c.solver, progress);
}

TangentialProblem make_tangential_problem(const ContactSpec& c, const std::vector<double>& worn_depth) {
  if (!c.friction) throw InputError("friction", "required for a tangential problem");
  return TangentialProblem(c.grid, c.materials, contact_heights(c, worn_depth), FrictionLaw::from_spec(*c.friction),
                           c.solver.operator_kind);
}

std::vector<TangentialSolution> solve_tangential_case(const Case& c, const ProgressCallback& progress) {
  if (!c.tangential) throw InputError("tangential", "required for a tangential problem (an object)");
  if (!c.friction) throw InputError("friction", "required for a tangential problem");
  const TangentialSpec& t = *c.tangential;
  TangentialProblem problem = make_tangential_problem(c);
  std::vector<TangentialSolution> out;
  // Each step's report times the whole step (every marching step, Newton and outer-loop
  // iteration, fallback), not only its last inner solve.
  auto timed = [&out](const auto& solve) {
    const auto start = std::chrono::steady_clock::now();
    out.push_back(solve());
    out.back().report.time_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  };
  // A history's progress says which step of how many is being solved.
  const int n_steps = static_cast<int>(t.regime == TangentialRegime::rolling ? t.rolling_history.size()
                                                                             : t.history.size());
  ProgressCallback step_progress;
  if (progress)
    step_progress = [&](ProgressInfo info) {
      info.step = static_cast<int>(out.size());
      info.steps = n_steps;
      progress(info);
    };
  if (t.regime == TangentialRegime::rolling) {
    if (!t.has_history) {
      timed([&] { return problem.steady_rolling(t.rolling, c.solver, progress); });
      return out;
    }
    try {
      for (const RollingStep& step : t.rolling_history)
        timed([&] { return problem.roll(step.load, step.distance, c.solver, step_progress); });
    } catch (const Interrupted&) {
      if (out.empty()) throw;  // else: the finished steps (interrupt_requested() says why no more)
    }
    return out;
  }
  if (!t.has_history) {
    timed([&] { return problem.step(t.load, c.solver, progress); });
    return out;
  }
  try {
    for (const TangentialLoad& step : t.history) timed([&] { return problem.step(step, c.solver, step_progress); });
  } catch (const Interrupted&) {
    if (out.empty()) throw;  // else: the finished steps (interrupt_requested() says why no more)
  }
  return out;
}

}  // namespace dc
