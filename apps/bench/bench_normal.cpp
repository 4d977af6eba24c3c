// dyncontact_bench: wall-clock timing of the normal-contact backends.
//
// The case: a Hertz sphere pressed on a half-space, steel on steel (E = 210 GPa, nu = 0.3),
// R = 0.01 m, P = 100 N, square grid n x n covering +-1.3 Hertz radii. For each size and
// backend the problem is set up (profile, compliance operator, plans) and solved through
// dc::NormalProblem; the table reports set-up and solve time separately (best of --repeat,
// a fresh NormalProblem each repeat so that no warm start helps), iterations, the worst
// certificate residual, the error of the peak pressure against Hertz and the peak resident
// memory. Each (backend, size) runs in a child process (unless --in-process), so the peak
// RSS is that case's own and a crash or abort in one backend does not end the benchmark.
//
//   dyncontact_bench --backends native,ipopt,nlopt --sizes 32,64,128,256,512 [--repeat 1]
//
// ipopt is skipped above 128^2 and nlopt above 64^2 (they take minutes to hours there)
// unless --force.
#include <sys/resource.h>
#include <sys/types.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <exception>
#include <fstream>
#include <limits>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>
#include <nlohmann/json.hpp>

#include "bench_sphere.hpp"
#include "blas_threads.hpp"
#include "case_model.hpp"
#include "grid.hpp"
#include "hertz.hpp"
#include "linear_operator.hpp"
#include "material.hpp"
#include "normal_problem.hpp"
#include "profile.hpp"
#include "solver_report.hpp"
#include "tangential_problem.hpp"

namespace {

using dc::bench::kE;
using dc::bench::kExtent;
using dc::bench::kForce;
using dc::bench::kNu;
using dc::bench::kRadius;

struct Options {
  std::vector<std::string> backends{"native", "ipopt", "nlopt"};
  std::vector<int> sizes{32, 64, 128, 256, 512};
  int repeat = 1;
  bool force = false;
  bool in_process = false;
  double tol = 1e-9;
  int max_iter = 1000;
  std::string operator_kind = "auto";
  std::string csv;
  std::string problem = "normal";  ///< normal | shift (Cattaneo, Q = mu P / 2) | rolling (F = mu P / 2)
};

struct Row {
  std::string backend;
  int n = 0;
  std::string status;    ///< converged | not_converged | failed | skipped | error | crashed
  std::string message;   ///< reason for skip / error, backend message otherwise
  std::string used;      ///< backend that actually produced the result
  std::string op;        ///< operator kind (dense | fft)
  double setup_s = std::numeric_limits<double>::quiet_NaN();
  double solve_s = std::numeric_limits<double>::quiet_NaN();
  int iterations = 0;
  int outer = 0;         ///< tangential: outer iterations (shift), Newton iterations or marching steps (rolling)
  double certificate = std::numeric_limits<double>::quiet_NaN();
  double p0_error = std::numeric_limits<double>::quiet_NaN();  ///< (max p - p0) / p0
  double rss_mib = std::numeric_limits<double>::quiet_NaN();
};

nlohmann::json to_json(const Row& r) {
  auto num = [](double v) { return std::isfinite(v) ? nlohmann::json(v) : nlohmann::json(); };
  return {{"backend", r.backend}, {"n", r.n},         {"status", r.status},
          {"message", r.message}, {"used", r.used},   {"operator", r.op},
          {"setup_s", num(r.setup_s)}, {"solve_s", num(r.solve_s)},
          {"iterations", r.iterations}, {"outer", r.outer}, {"certificate", num(r.certificate)},
          {"p0_error", num(r.p0_error)}, {"rss_mib", num(r.rss_mib)}};
}

Row from_json(const nlohmann::json& j) {
  auto num = [&](const char* key) {
    return j.at(key).is_null() ? std::numeric_limits<double>::quiet_NaN() : j.at(key).get<double>();
  };
  Row r;
  r.backend = j.at("backend");
  r.n = j.at("n");
  r.status = j.at("status");
  r.message = j.at("message");
  r.used = j.at("used");
  r.op = j.at("operator");
  r.setup_s = num("setup_s");
  r.solve_s = num("solve_s");
  r.iterations = j.at("iterations");
  r.outer = j.at("outer");
  r.certificate = num("certificate");
  r.p0_error = num("p0_error");
  r.rss_mib = num("rss_mib");
  return r;
}

double peak_rss_mib() {
  rusage usage{};
  if (getrusage(RUSAGE_SELF, &usage) != 0) return std::numeric_limits<double>::quiet_NaN();
  return static_cast<double>(usage.ru_maxrss) / 1024.0;  // Linux: KiB
}

/// Tangential cases on the same sphere, Coulomb mu = 0.3: shift by Q = mu P / 2 (error: rigid
/// shift vs Mindlin) or steady rolling by F = mu P / 2. Iterations: the last inner solve's.
void run_tangential(const std::string& problem, int n, const dc::SolverOptions& solver, Row& row, double& setup_s,
                    double& solve_s) {
  using clock = std::chrono::steady_clock;
  constexpr double kMu = 0.3;
  const dc::bench::BenchSphere sphere;
  const dc::MaterialPair& materials = sphere.materials;
  const dc::hertz::SphereSolution& hertz = sphere.hertz;
  const dc::ProfileSpec& profile = sphere.profile;
  const auto t0 = clock::now();
  const dc::Grid grid = sphere.grid(n, 1.2);
  dc::TangentialProblem tp(grid, materials, dc::profile_heights(profile, grid), dc::FrictionLaw::coulomb(kMu));
  const auto t1 = clock::now();
  const dc::NormalSpec normal{dc::Control::force, kForce};
  const dc::ModeControl force{dc::ModeControl::Kind::resultant, -0.5 * kMu * kForce};
  dc::TangentialSolution sol;
  if (problem == "shift") {
    dc::TangentialLoad load;
    load.normal = normal;
    load.modes[0] = force;
    sol = tp.step(load, solver);
    row.outer = sol.outer.iterations;
    const double shift = 3 * kMu * kForce / (16 * hertz.a) * materials.mindlin_compliance() *
                         (1 - std::pow(0.5, 2.0 / 3.0));
    row.p0_error = sol.amplitudes[0] / shift - 1.0;
  } else {
    dc::RollingLoad load;
    load.normal = normal;
    load.modes[0] = force;
    sol = tp.steady_rolling(load, solver);
    row.outer = sol.marching_steps > 0 ? sol.marching_steps : sol.newton_iterations;
  }
  const auto t2 = clock::now();
  setup_s = std::chrono::duration<double>(t1 - t0).count();
  solve_s = std::chrono::duration<double>(t2 - t1).count();
  row.status = dc::to_string(sol.report.status);
  row.message = sol.report.message;
  row.used = sol.report.backend;
  row.op = sol.report.operator_kind;
  row.iterations = sol.report.iterations;
  row.certificate = sol.report.certificate.worst();
}

/// One (backend, size): set up and solve `repeat` times, keep the best times.
Row run_case(const std::string& backend, int n, const Options& options) {
  using clock = std::chrono::steady_clock;
  auto seconds = [](clock::time_point a, clock::time_point b) {
    return std::chrono::duration<double>(b - a).count();
  };

  Row row;
  row.backend = backend;
  row.n = n;
  try {
    const dc::bench::BenchSphere sphere;
    const dc::MaterialPair& materials = sphere.materials;
    const dc::hertz::SphereSolution& hertz = sphere.hertz;
    const dc::ProfileSpec& profile = sphere.profile;
    const dc::NormalSpec& control = sphere.normal;
    dc::SolverOptions solver;
    solver.backend = *dc::backend_from_string(backend);  // one of --backends' names
    solver.fallback = false;  // time the backend asked for, not a fallback
    solver.tol = options.tol;
    solver.max_iter = options.max_iter;
    solver.operator_kind = *dc::operator_kind_from_string(options.operator_kind);

    double best_setup = std::numeric_limits<double>::infinity();
    double best_solve = std::numeric_limits<double>::infinity();
    double worst_certificate = 0.0;
    if (options.problem != "normal") {
      for (int k = 0; k < options.repeat; ++k) {
        double setup_s = 0.0, solve_s = 0.0;
        run_tangential(options.problem, n, solver, row, setup_s, solve_s);
        best_setup = std::min(best_setup, setup_s);
        best_solve = std::min(best_solve, solve_s);
        worst_certificate = std::max(worst_certificate, row.certificate);
      }
    }
    for (int k = 0; k < options.repeat && options.problem == "normal"; ++k) {
      const auto t0 = clock::now();
      const dc::Grid grid = sphere.grid(n);
      dc::NormalProblem problem(grid, materials, dc::profile_heights(profile, grid), solver.operator_kind);
      const auto t1 = clock::now();
      const dc::NormalSolution solution = problem.solve(control, solver);
      const auto t2 = clock::now();

      best_setup = std::min(best_setup, seconds(t0, t1));
      best_solve = std::min(best_solve, seconds(t1, t2));
      const dc::SolverReport& report = solution.report;
      const double certificate = report.certificate.worst();
      worst_certificate = std::isfinite(certificate) ? std::max(worst_certificate, certificate)
                                                     : std::numeric_limits<double>::infinity();
      row.status = dc::to_string(report.status);
      row.message = report.message;
      row.used = report.backend;
      row.op = report.operator_kind.empty() ? problem.compliance().kind() : report.operator_kind;
      row.iterations = report.iterations;
      if (!solution.pressure.empty()) {
        const double p_max = *std::max_element(solution.pressure.begin(), solution.pressure.end());
        row.p0_error = p_max / hertz.p0 - 1.0;
      }
    }
    row.setup_s = best_setup;
    row.solve_s = best_solve;
    row.certificate = worst_certificate;
  } catch (const std::exception& e) {
    row.status = "error";
    row.message = e.what();
  }
  row.rss_mib = peak_rss_mib();
  return row;
}

/// Runs the case in a child process and reads its row back through a pipe.
Row run_case_isolated(const std::string& backend, int n, const Options& options) {
  Row failed;
  failed.backend = backend;
  failed.n = n;
  int fds[2];
  if (pipe(fds) != 0) {
    failed.status = "error";
    failed.message = std::string("pipe: ") + std::strerror(errno);
    return failed;
  }
  std::fflush(nullptr);
  const pid_t pid = fork();
  if (pid < 0) {
    close(fds[0]);
    close(fds[1]);
    failed.status = "error";
    failed.message = std::string("fork: ") + std::strerror(errno);
    return failed;
  }
  if (pid == 0) {  // child
    close(fds[0]);
    const std::string text = to_json(run_case(backend, n, options)).dump();
    std::size_t written = 0;
    while (written < text.size()) {
      const ssize_t w = write(fds[1], text.data() + written, text.size() - written);
      if (w <= 0) break;
      written += static_cast<std::size_t>(w);
    }
    close(fds[1]);
    std::fflush(nullptr);
    _exit(0);
  }
  close(fds[1]);
  std::string text;
  char buffer[4096];
  for (;;) {
    const ssize_t r = read(fds[0], buffer, sizeof buffer);
    if (r < 0 && errno == EINTR) continue;
    if (r <= 0) break;
    text.append(buffer, static_cast<std::size_t>(r));
  }
  close(fds[0]);
  int wstatus = 0;
  while (waitpid(pid, &wstatus, 0) < 0 && errno == EINTR) {
  }
  if (WIFSIGNALED(wstatus)) {
    failed.status = "crashed";
    failed.message = std::string("signal ") + std::to_string(WTERMSIG(wstatus)) + " (" +
                     strsignal(WTERMSIG(wstatus)) + ")";
    return failed;
  }
  try {
    return from_json(nlohmann::json::parse(text));
  } catch (const std::exception& e) {
    failed.status = "error";
    failed.message = std::string("no result from the child process: ") + e.what();
    return failed;
  }
}

std::string skip_reason(const std::string& backend, int n, const Options& options) {
  if (options.force) return {};
  if (backend == "ipopt" && n > 128) return "skipped above 128^2 (--force runs it)";
  if (backend == "nlopt" && n > 64) return "skipped above 64^2 (--force runs it)";
  return {};
}

std::string format_number(const char* format, double value) {
  if (!std::isfinite(value)) return "-";
  char buffer[64];
  std::snprintf(buffer, sizeof buffer, format, value);
  return buffer;
}

void print_header() {
  std::printf("%-8s %9s %8s %9s %10s %7s %6s %11s %10s %9s  %s\n", "backend", "grid", "N",
              "setup(s)", "solve(s)", "iters", "outer", "certificate", "err ref(%)", "RSS(MiB)", "status");
  std::printf("%s\n", std::string(111, '-').c_str());
}

void print_row(const Row& r) {
  const std::string grid = std::to_string(r.n) + "x" + std::to_string(r.n);
  const bool ran = r.status != "skipped";
  std::string status = r.status;
  if (ran && !r.used.empty() && r.used != r.backend) status += " [by " + r.used + "]";
  if (!r.op.empty()) status += " (" + r.op + ")";
  if ((r.status != "converged") && !r.message.empty()) status += ": " + r.message;
  const bool finished = ran && r.status != "error" && r.status != "crashed";
  std::printf("%-8s %9s %8lld %9s %10s %7s %6s %11s %10s %9s  %s\n", r.backend.c_str(), grid.c_str(),
              static_cast<long long>(r.n) * r.n, format_number("%.3f", r.setup_s).c_str(),
              format_number("%.3f", r.solve_s).c_str(), finished ? std::to_string(r.iterations).c_str() : "-",
              finished && r.outer > 0 ? std::to_string(r.outer).c_str() : "-",
              format_number("%.1e", r.certificate).c_str(),
              format_number("%+.2f", 100.0 * r.p0_error).c_str(),
              ran ? format_number("%.0f", r.rss_mib).c_str() : "-", status.c_str());
  std::fflush(stdout);
}

void write_csv(const std::string& path, const std::vector<Row>& rows) {
  std::ofstream out(path);
  if (!out) throw std::runtime_error("cannot write " + path);
  out << "backend,n,N,setup_s,solve_s,iterations,certificate,p0_error,rss_mib,status,used,operator,message\n";
  auto num = [](double v) { return std::isfinite(v) ? format_number("%.9g", v) : std::string(); };
  for (const Row& r : rows) {
    std::string message = r.message;
    std::replace(message.begin(), message.end(), '"', '\'');
    out << r.backend << ',' << r.n << ',' << static_cast<long long>(r.n) * r.n << ',' << num(r.setup_s)
        << ',' << num(r.solve_s) << ',' << r.iterations << ',' << num(r.certificate) << ','
        << num(r.p0_error) << ',' << num(r.rss_mib) << ',' << r.status << ',' << r.used << ','
        << r.op << ",\"" << message << "\"\n";
  }
}

}  // namespace

int main(int argc, char** argv) {
  dc::use_one_blas_thread();  // as the program does: no idle BLAS threads spinning beside the solve
  Options options;
  CLI::App app{"dyncontact_bench: normal-contact backends on a Hertz sphere (steel on steel, "
               "R = 0.01 m, P = 100 N, grid +-1.3 a)"};
  app.add_option("--backends", options.backends, "Comma-separated: native, ipopt, nlopt, auto")
      ->delimiter(',')
      ->check(CLI::IsMember({"native", "ipopt", "nlopt", "auto"}))
      ->capture_default_str();
  app.add_option("--sizes", options.sizes, "Comma-separated grid sizes n (n x n elements)")
      ->delimiter(',')
      ->check(CLI::Range(2, 1 << 14))
      ->capture_default_str();
  app.add_option("--repeat", options.repeat, "Repeats per case; times are the best")
      ->check(CLI::Range(1, 1000))
      ->capture_default_str();
  app.add_flag("--force", options.force, "Run ipopt above 128^2 and nlopt above 64^2 as well");
  app.add_option("--tol", options.tol, "Backend tolerance")->capture_default_str();
  app.add_option("--max-iter", options.max_iter, "Backend iteration limit")->capture_default_str();
  app.add_option("--operator", options.operator_kind, "Compliance operator")
      ->check(CLI::IsMember({"auto", "dense", "fft"}))
      ->capture_default_str();
  app.add_option("--problem", options.problem,
                 "normal (Hertz), shift (Cattaneo, Q = mu P/2: err ref = rigid shift vs Mindlin) or "
                 "rolling (steady, F = mu P/2; outer = Newton iterations, or marching steps when it marched)")
      ->check(CLI::IsMember({"normal", "shift", "rolling"}))
      ->capture_default_str();
  app.add_option("--csv", options.csv, "Also write the table as CSV to this file");
  app.add_flag("--in-process", options.in_process,
               "Run every case in this process (RSS is then the running peak)");
  CLI11_PARSE(app, argc, argv);

  const dc::MaterialPair materials = dc::bench::steel_on_steel();
  const dc::hertz::SphereSolution hertz = dc::hertz::sphere(kRadius, kForce, materials.E_star());
  std::printf("Hertz sphere: E = %.3g Pa, nu = %.2f (both bodies), R = %g m, P = %g N\n", kE, kNu,
              kRadius, kForce);
  std::printf("  a = %.4e m, p0 = %.4e Pa, approach = %.4e m; grid +-%.1f a; tol %.1e, "
              "best of %d, %s\n\n",
              hertz.a, hertz.p0, hertz.approach, kExtent, options.tol, options.repeat,
              options.in_process ? "in process" : "one process per case");
  print_header();

  std::vector<Row> rows;
  bool any_failed = false;
  for (const int n : options.sizes) {
    for (const std::string& backend : options.backends) {
      Row row;
      const std::string reason = skip_reason(backend, n, options);
      if (!reason.empty()) {
        row.backend = backend;
        row.n = n;
        row.status = "skipped";
        row.message = reason;
      } else {
        row = options.in_process ? run_case(backend, n, options)
                                 : run_case_isolated(backend, n, options);
        if (row.status == "error" || row.status == "crashed") any_failed = true;
      }
      print_row(row);
      rows.push_back(row);
    }
  }
  std::printf("\nsetup: grid, profile, operator (and FFT plans); solve: NormalProblem::solve, "
              "certificate included.\ncertificate: worst residual measured after the solve; "
              "err ref: peak pressure vs Hertz (normal) or rigid shift vs Mindlin (shift); RSS: peak resident memory of the case.\n");
  if (!options.csv.empty()) {
    write_csv(options.csv, rows);
    std::printf("CSV written to %s\n", options.csv.c_str());
  }
  return any_failed ? 1 : 0;
}
