#include "wear_run.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>

#include "interrupt.hpp"
#include "progress.hpp"
#include "solve_case.hpp"

namespace dc::runs {
namespace {

/// One profile update: the cycles done after it, the cycles its cycle's wear was extrapolated
/// over, the deepest wear of that cycle, and the state the cycle was solved in.
struct WearUpdate {
  long long cycles_done = 0, jump = 0;
  double cycle_max_depth = 0.0, cycle_volume = 0.0, max_depth = 0.0, volume = 0.0;
  double max_pressure = 0.0, contact_area = 0.0;
  double time_s = 0.0;  ///< the cycle's solves, its wear map and the profile update after it (s)
  std::vector<double> normal_force;  ///< each step of the cycle (N)
};

double largest(const std::vector<double>& v) { return v.empty() ? 0.0 : *std::max_element(v.begin(), v.end()); }

/// The cycles one solved cycle stands for: all that remain, bounded by update.cycles and by the
/// cycles that wear update.max_depth at the deepest element (at least one); neither given: one.
long long cycles_to_jump(const WearSpec& w, long long remaining, double cycle_depth) {
  if (w.update_cycles == 0 && w.update_max_depth == 0.0) return 1;
  long long n = remaining;
  if (w.update_cycles > 0) n = std::min(n, w.update_cycles);
  if (w.update_max_depth > 0.0 && cycle_depth > 0.0) {
    const double by_depth = std::floor(w.update_max_depth / cycle_depth);
    if (by_depth < static_cast<double>(n)) n = std::max(1LL, static_cast<long long>(by_depth));
  }
  return std::max(1LL, n);
}

/// The depth element e of a quasi-static step loses (core/wear_law.hpp).
double element_depth(const WearLaw& law, const TangentialSolution& s, std::size_t e) {
  return law.depth(s.normal.pressure[e], s.tx[e], e < s.ty.size() ? s.ty[e] : 0.0, s.sx[e], e < s.sy.size() ? s.sy[e] : 0.0);
}

/// One pass of steady rolling. A steady solution's slip is per element of travel dx (the slip
/// while the material crosses one element), so a point of the track at y_j, passing under the
/// whole row j, loses d_j = sum_i depth(p_ij, tau_ij, s_ij) = int k p |s_dot| / H dx / V
/// (Archard); the body's circumference at y_j passes the contact once per revolution and loses
/// the same d_j. Both maps: d_j on every element of row j.
std::vector<double> rolling_pass_depth(const WearLaw& law, const Grid& grid, const TangentialSolution& s) {
  std::vector<double> depth(grid.size(), 0.0);
  for (int j = 0; j < grid.ny; ++j) {
    double row = 0.0;
    for (int i = 0; i < grid.nx; ++i) row += element_depth(law, s, grid.index(i, j));
    for (int i = 0; i < grid.nx; ++i) depth[grid.index(i, j)] = row;
  }
  return depth;
}

/// The worn states kept over the updates: those of every stride-th update, the stride doubling
/// (every other state dropped) whenever more than kKept would be kept, and the latest update's
/// always (replaced by the next when it is off the stride): at most kKept states.
class WornStates {
 public:
  static constexpr std::size_t kKept = 64;
  void add(long long update, long long cycles, const std::vector<double>& depth) {
    if (tentative_) {
      states_.pop_back();
      updates_.pop_back();
    }
    states_.push_back({cycles, depth});
    updates_.push_back(update);
    while (states_.size() > kKept) {  // keep every other state on the stride
      std::vector<output::WornState> states;
      std::vector<long long> updates;
      stride_ *= 2;
      for (std::size_t k = 0; k < states_.size(); ++k)
        if (updates_[k] % stride_ == 0 || k + 1 == states_.size()) {
          states.push_back(std::move(states_[k]));
          updates.push_back(updates_[k]);
        }
      states_ = std::move(states);
      updates_ = std::move(updates);
    }
    tentative_ = updates_.back() % stride_ != 0;
  }
  std::vector<output::WornState> take() { return std::move(states_); }

 private:
  std::vector<output::WornState> states_;
  std::vector<long long> updates_;
  long long stride_ = 1;
  bool tentative_ = false;
};

}  // namespace

StaticRun run_wear(const Case& c, bool progress) {
  const WearSpec& w = *c.wear;
  const TangentialSpec& t = *c.tangential;
  const std::size_t n = c.grid.size();
  const bool rolling = t.regime == TangentialRegime::rolling;  // steady rolling (read_wear)
  const int n_steps = static_cast<int>(t.history.size());
  const int first = w.cycle_from_step;
  // One body's worn depth (each listed body loses the law's depth); the gap opens by their sum.
  std::vector<double> worn(n, 0.0), gap_worn(n, 0.0), cycle_depth(n, 0.0);
  const double bodies = static_cast<double>(w.base) + static_cast<double>(w.body);
  auto update_gap = [&](TangentialProblem& problem) {
    for (std::size_t e = 0; e < n; ++e) gap_worn[e] = bodies * worn[e];
    problem.set_heights(contact_heights(c, gap_worn));
  };

  Progress reporter("solving " + c.name + " with wear (" + to_string(c.solver.backend) + ")", progress);
  ProgressCallback callback = reporter.callback();
  TangentialProblem problem = make_tangential_problem(c);
  // Steps [from, to) of the history, each timed whole, their wear summed into cycle_depth.
  auto solve_steps = [&](int from, int to, std::vector<TangentialSolution>& out) {
    for (int k = from; k < to; ++k) {
      ProgressCallback step_progress;
      if (callback)
        step_progress = [&, k](ProgressInfo info) {
          info.step = k;
          info.steps = n_steps;
          callback(info);
        };
      const auto start = std::chrono::steady_clock::now();
      out.push_back(problem.step(t.history[k], c.solver, step_progress));
      TangentialSolution& s = out.back();
      s.report.time_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
      for (std::size_t e = 0; e < n; ++e) cycle_depth[e] += element_depth(w.law, s, e);
    }
  };
  // Steady rolling: one pass, one steady solve, its row depths (rolling_pass_depth) the cycle's.
  auto solve_pass = [&](std::vector<TangentialSolution>& out) {
    const auto start = std::chrono::steady_clock::now();
    out.push_back(problem.steady_rolling(t.rolling, c.solver, callback));
    TangentialSolution& s = out.back();
    s.report.time_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    cycle_depth = rolling_pass_depth(w.law, c.grid, s);
  };
  auto solve_cycle = [&](std::vector<TangentialSolution>& out) {
    if (rolling) solve_pass(out);
    else solve_steps(first, n_steps, out);
  };
  // A history's volume is its map's on the grid; a rolling pass's rows are uniform along x, their
  // volume per length of travel (sum over x / the grid's length) times the travel 2 pi R per cycle.
  const double volume_factor =
      c.grid.area() * (rolling ? 2.0 * M_PI * w.rolling_radius / (c.grid.nx * c.grid.dx) : 1.0);
  auto volume_of = [&](const std::vector<double>& depth) {
    double v = 0.0;
    for (double d : depth) v += d;
    return v * volume_factor;
  };

  std::vector<TangentialSolution> cycle, solved;
  std::vector<WearUpdate> updates;
  WornStates states;
  long long done = 0;
  bool interrupted = false;
  try {
    if (first > 0 && !rolling) {  // the first loading, once
      solve_steps(0, first, solved);
      for (std::size_t e = 0; e < n; ++e) worn[e] += cycle_depth[e];
      update_gap(problem);
    }
    while (done < w.cycles) {
      const auto cycle_start = std::chrono::steady_clock::now();
      cycle.clear();
      cycle_depth.assign(n, 0.0);
      solve_cycle(cycle);
      const bool converged = std::all_of(cycle.begin(), cycle.end(), [](const TangentialSolution& s) {
        return s.report.status == SolveStatus::converged;
      });
      solved = std::move(cycle);
      WearUpdate u;
      u.cycle_max_depth = largest(cycle_depth);
      u.cycle_volume = volume_of(cycle_depth);
      u.jump = cycles_to_jump(w, w.cycles - done, u.cycle_max_depth);
      for (std::size_t e = 0; e < n; ++e) worn[e] += static_cast<double>(u.jump) * cycle_depth[e];
      done += u.jump;
      u.cycles_done = done;
      u.max_depth = largest(worn);
      u.volume = volume_of(worn);
      for (const TangentialSolution& s : solved) {
        u.normal_force.push_back(s.normal.force);
        u.max_pressure = std::max(u.max_pressure, largest(s.normal.pressure));
      }
      const std::vector<double>& p = solved.back().normal.pressure;
      const double peak = largest(p);
      u.contact_area = static_cast<double>(std::count_if(p.begin(), p.end(), [&](double v) {
                         return v > std::max(c.solver.certificate_tol, 1e-12) * peak;
                       })) * c.grid.area();
      updates.push_back(std::move(u));
      states.add(static_cast<long long>(updates.size()) - 1, done, worn);
      if (converged && done < w.cycles) update_gap(problem);
      updates.back().time_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - cycle_start).count();
      if (!converged) break;  // a cycle the solver failed on wears nothing more: reported as is
    }
  } catch (const Interrupted&) {
    if (updates.empty()) throw;  // else: the cycles finished (interrupt_requested() says why no more)
    interrupted = true;
  }
  reporter.finish();

  std::vector<NormalSpec> normals;  // of the cycle's steps (a rolling pass: its one solve)
  if (rolling) normals = t.step_normals();
  for (int k = first; k < n_steps && !rolling; ++k) normals.push_back(t.history[k].normal);
  TangentialRun run = tangential_run_of(c, std::move(solved), std::move(normals));
  StaticRun out;
  out.summary = std::move(run.summary);
  // The steps reported are the cycle's: each names its step of tangential.history.
  if (out.summary.contains("steps"))
    for (std::size_t k = 0; k < out.summary["steps"].size(); ++k) out.summary["steps"][k]["history_step"] = first + k;
  out.fields = std::move(run.fields);
  out.normal = run.normal.back();
  out.report = run.report();
  out.report.time_s = run.total_time_s();
  out.converged = run.converged() && done == w.cycles;
  out.history = !rolling;
  out.interrupted = interrupted || run.interrupted;
  out.grid = c.grid;
  if (w.base) out.worn_base = worn;
  if (w.body) out.worn_body = worn;
  out.wear_series = states.take();

  nlohmann::json j = {{"law", to_string(w.law.kind)}, {"cycles", done}, {"updates", updates.size()},
                      {"cycle_from_step", first}};
  const nlohmann::json body = {{"max_depth", largest(worn)}, {"volume", volume_of(worn)}};
  if (w.base) j["base"] = body;
  if (w.body) j["body"] = body;
  if (rolling) {  // a cycle is one revolution of the body and one pass over the track
    j.erase("cycle_from_step");
    j["rolling_radius"] = w.rolling_radius;
    j["travel"] = 2.0 * M_PI * w.rolling_radius * static_cast<double>(done);
  }
  nlohmann::json history = nlohmann::json::array();
  for (const WearUpdate& u : updates)
    history.push_back({{"cycles", u.cycles_done}, {"jump", u.jump}, {"cycle_max_depth", u.cycle_max_depth},
                       {"cycle_volume", u.cycle_volume},
                       {"max_depth", u.max_depth}, {"volume", u.volume}, {"max_pressure", u.max_pressure},
                       {"contact_area", u.contact_area}, {"normal_force", u.normal_force},
                       {"time_s", u.time_s}});
  j["history"] = history;
  if (done < w.cycles) j["cycles_requested"] = w.cycles;
  out.summary["wear"] = j;
  return out;
}

}  // namespace dc::runs
