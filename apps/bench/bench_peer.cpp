// dyncontact_peer_bench: times whole cases (case files, e.g. examples/bench/*.json) as a user
// runs them: build the case, set up the operators and plans, solve (every step of a history),
// certificates included. For each case it prints the wall time (median of --repeat runs, each
// from scratch), the iterations, and the error against the closed form where one exists:
//   Hertz sphere (profile sphere, identical or any materials, normal problem): peak pressure;
//   Spence (sphere, loading history, no tangential load): stick radius ratio c/a of the last
//   step against Spence's value for |beta|/mu. Others (e.g. a table profile): "-".
//   dyncontact_peer_bench [--repeat 3] case.json...
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>

#include "blas_threads.hpp"
#include "case_model.hpp"
#include "solve_case.hpp"
#include "contact_closed_forms.hpp"
#include "hertz.hpp"
#include "normal_problem.hpp"
#include "tangential_problem.hpp"

namespace {

struct Measure {
  double time_s = 0.0;
  long long iterations = 0;   ///< normal: solver iterations; history: inner iterations of all steps
  long long alternations = 0; ///< history: outer (4.26)-(4.27) iterations of all steps
  int steps = 1;
  double error = NAN;         ///< against the closed form (relative)
  std::string error_kind = "-";
  double certificate = 0.0;   ///< worst over the steps
  bool converged = true;
  std::string backend;        ///< the backend of the answer (the last step's for a history)
  int fallbacks = 0;          ///< solves (normal or tangential, every step) whose first backend failed
  std::string fell_back;      ///< what the first failing backend said (dc::fallback_warning)
};

std::string slurp(const std::string& path) {
  std::ifstream in(path);
  if (!in) throw std::runtime_error("cannot read " + path);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

Measure run_once(const dc::Case& c) {
  using clock = std::chrono::steady_clock;
  Measure m;
  const auto t0 = clock::now();
  if (c.problem == dc::ProblemKind::normal) {
    const dc::NormalSolution s = dc::solve_normal_case(c);
    m.time_s = std::chrono::duration<double>(clock::now() - t0).count();
    m.iterations = s.report.iterations;
    m.certificate = s.report.certificate.worst();
    m.converged = s.report.status == dc::SolveStatus::converged;
    m.backend = s.report.backend;
    m.fallbacks = s.report.fallback_used ? 1 : 0;
    m.fell_back = dc::fallback_warning(s.report);
    if (c.profile.type == dc::ProfileType::sphere && c.normal.control == dc::Control::force) {
      const auto hz = dc::hertz::sphere(c.profile.radius, c.normal.value, c.materials.E_star());
      m.error = *std::max_element(s.pressure.begin(), s.pressure.end()) / hz.p0 - 1.0;
      m.error_kind = "p0";
    }
    return m;
  }
  const std::vector<dc::TangentialSolution> steps = dc::solve_tangential_case(c);
  m.time_s = std::chrono::duration<double>(clock::now() - t0).count();
  m.steps = static_cast<int>(steps.size());
  for (const auto& s : steps) {
    m.iterations += s.report.iterations + s.normal.report.iterations;
    m.alternations += s.outer.iterations;
    m.certificate = std::max(m.certificate, s.report.certificate.worst());
    m.converged = m.converged && s.report.status == dc::SolveStatus::converged;
    m.backend = s.report.backend;
    m.fallbacks += (s.report.fallback_used ? 1 : 0) + (s.normal.report.fallback_used ? 1 : 0);
    if (m.fell_back.empty()) m.fell_back = dc::fallback_warning(s.report);
    if (m.fell_back.empty()) m.fell_back = dc::fallback_warning(s.normal.report);
  }
  const auto& last = steps.back();
  const double mu = c.friction ? c.friction->mu : 0.0;
  const double beta = std::abs(dc::closed_form::dundurs_beta(c.materials));
  if (c.profile.type == dc::ProfileType::sphere && steps.size() > 1 && mu > 0.0 && beta > 0.0) {
    double loaded = 0.0;
    for (double f : last.bound) loaded += f > 0.0 ? c.grid.area() : 0.0;
    m.error = std::sqrt(last.stick_area / loaded) / dc::closed_form::spence_stick_ratio(beta / mu) - 1.0;
    m.error_kind = "c/a";
  }
  return m;
}

}  // namespace

int main(int argc, char** argv) {
  dc::use_one_blas_thread();  // as the program does: no idle BLAS threads spinning beside the solve
  std::vector<std::string> files;
  int repeat = 1;
  CLI::App app{"dyncontact_peer_bench: whole cases timed as a user runs them (median of --repeat)"};
  app.add_option("cases", files, "Case files (JSON)")->required();
  app.add_option("--repeat", repeat, "Runs per case; the time printed is the median")->check(CLI::Range(1, 100));
  CLI11_PARSE(app, argc, argv);

  std::printf("%-24s %9s %6s %9s %7s %8s %7s %9s %11s %-8s %9s  %s\n", "case", "elements", "steps", "time(s)", "runs",
              "iters", "alt", "err(%)", "certificate", "backend", "fallbacks", "status");
  int failures = 0;
  for (const std::string& file : files) {
    try {
      const std::string base = file.find('/') == std::string::npos ? "." : file.substr(0, file.rfind('/'));
      const dc::Case c = dc::build_case(dc::parse_case_text(slurp(file), file), base);
      std::vector<double> times;
      Measure m;
      for (int k = 0; k < repeat; ++k) {
        m = run_once(c);
        times.push_back(m.time_s);
      }
      std::sort(times.begin(), times.end());
      const double median = times[times.size() / 2];
      char err[32] = "-";
      if (std::isfinite(m.error)) std::snprintf(err, sizeof err, "%+.2f %s", 100.0 * m.error, m.error_kind.c_str());
      std::printf("%-24s %9zu %6d %9.3f %7d %8lld %7s %9s %11.1e %-8s %9d  %s\n", c.name.c_str(), c.grid.size(),
                  m.steps, median, repeat, m.iterations, m.steps > 1 ? std::to_string(m.alternations).c_str() : "-",
                  err, m.certificate, m.backend.c_str(), m.fallbacks,
                  !m.converged ? "NOT converged" : m.fallbacks > 0 ? "FELL BACK" : "converged");
      if (!m.fell_back.empty()) std::printf("  %s\n", m.fell_back.c_str());
      std::fflush(stdout);
      // A case that needed a fallback hides a failing fast path: the benchmark fails on it.
      if (!m.converged || m.fallbacks > 0) ++failures;
    } catch (const std::exception& e) {
      std::printf("%-24s error: %s\n", file.c_str(), e.what());
      ++failures;
    }
  }
  std::printf("\ntime: wall clock of the whole solve (operators, plans, every step, certificates), median of the runs;\n"
              "iters: normal solver iterations (history: inner iterations of every step, normal + tangential);\n"
              "alt: normal-tangential alternations (4.26)-(4.27) summed over the steps; err: peak pressure vs Hertz (p0)\n"
              "or the last step's stick ratio vs Spence (c/a); fallbacks: solves whose first backend failed (any fails\n"
              "the benchmark, as does a case that did not converge).\n");
  return failures == 0 ? 0 : 1;
}
