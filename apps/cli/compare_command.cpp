// dyncontact compare CASE.json --backends ipopt,nlopt,native [--out DIR]
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <exception>
#include <filesystem>
#include <iostream>
#include <memory>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>

#include "cli_common.hpp"
#include "result_limits.hpp"
#include "commands.hpp"
#include "errors.hpp"
#include "output_files.hpp"
#include "solver_report.hpp"
#include "summary_entries.hpp"
#include "summary_writer.hpp"
#include "tangential_run.hpp"
#include "interrupt.hpp"

namespace dc::cli {
namespace {

/// The "backend" of a finite case that solves the sparse saddle form (a) with Ipopt.
bool sparse_form(const std::string& backend) { return backend == "ipopt-sparse"; }

struct CompareArgs {
  std::string case_path, out;
  std::vector<std::string> backends{"ipopt", "nlopt", "native"};
  std::vector<std::string> sets;
  bool quiet = false;
};

struct Entry {
  std::string backend;
  bool ok = false;  ///< produced a result (whatever its status)
  runs::StaticRun run;
  std::string error;  ///< what the backend threw, if it did
};

double relative(double value, double reference) {
  const double scale = std::abs(reference);
  return scale > 0.0 ? std::abs(value - reference) / scale : std::abs(value);
}

/// Largest difference of a field (one or two components) relative to the reference's peak.
double field_difference(const std::vector<double>& p, const std::vector<double>& ref,
                        const std::vector<double>& q = {}, const std::vector<double>& q_ref = {}) {
  double scale = 0.0, diff = 0.0;
  for (const auto* r : {&ref, &q_ref})
    for (double v : *r) scale = std::max(scale, std::abs(v));
  for (std::size_t i = 0; i < std::min(p.size(), ref.size()); ++i) diff = std::max(diff, std::abs(p[i] - ref[i]));
  for (std::size_t i = 0; i < std::min(q.size(), q_ref.size()); ++i) diff = std::max(diff, std::abs(q[i] - q_ref[i]));
  return scale > 0.0 ? diff / scale : diff;
}

/// summary[key] (or its component), 0 when absent or not a number.
double number(const nlohmann::json& summary, const char* key, int component = -1) {
  if (!summary.is_object() || !summary.contains(key)) return 0.0;
  const nlohmann::json& v = summary.at(key);
  if (component < 0) return v.is_number() ? v.get<double>() : 0.0;
  const auto k = static_cast<std::size_t>(component);
  return v.is_array() && k < v.size() && v[k].is_number() ? v[k].get<double>() : 0.0;
}

/// |F - F_ref| / |F_ref| of the tangential force vectors.
double force_difference(const nlohmann::json& s, const nlohmann::json& ref) {
  const double dx = number(s, "tangential_force", 0) - number(ref, "tangential_force", 0);
  const double dy = number(s, "tangential_force", 1) - number(ref, "tangential_force", 1);
  const double scale = std::hypot(number(ref, "tangential_force", 0), number(ref, "tangential_force", 1));
  return scale > 0.0 ? std::hypot(dx, dy) / scale : std::hypot(dx, dy);
}

int run_compare(const CompareArgs& args) {
  if (args.backends.empty()) throw InputError("--backends", "give at least one backend");
  const Case base = load_case(args.case_path, args.sets);
  const bool finite = base.problem == ProblemKind::finite;
  for (const auto& b : args.backends)
    if (!backend_from_string(b) && !(finite && sparse_form(b)))
      throw InputError("--backends", "unknown backend '" + b + "' (expected auto, ipopt, nlopt or native" +
                                         (finite ? ", or ipopt-sparse for the sparse form)" : ")"));
  if (base.problem == ProblemKind::paper_cylinder)
    throw InputError("problem",
                     "a paper_cylinder case has no contact backend to compare: its traction is the Carter-Poritsky "
                     "closed form (traction_model carter_poritsky) or a creep law tabulated once by the native "
                     "steady-rolling solver (numerical); run it with `dyncontact solve`");
  if (base.problem != ProblemKind::normal && base.problem != ProblemKind::tangential && !finite)
    not_implemented(base.problem);
  const bool tangential = base.problem == ProblemKind::tangential || (finite && base.tangential);
  const std::string dir = prepare_output_dir(base, args.out);

  std::vector<Entry> entries;
  for (const auto& b : args.backends) {
    Case c = base;
    c.solver.backend = sparse_form(b) ? Backend::ipopt : *backend_from_string(b);
    if (finite) {  // a finite body: the condensed program, or the sparse saddle form by Ipopt
      c.fe_body->program = sparse_form(b) ? "sparse" : "condensed";
      c.source["fe_body"]["program"] = c.fe_body->program;
    }
    c.solver.fallback = false;  // compare the backend itself, not its fallbacks
    c.source["solver"]["backend"] = to_string(c.solver.backend);
    c.source["solver"]["fallback"] = false;
    Entry e;
    e.backend = b;
    try {
      e.run = runs::run_static(c, !args.quiet);
      throw_if_interrupted();  // a part of a history is no comparison: main() says "interrupted"
      e.ok = true;
    } catch (const InputError&) {
      throw;
    } catch (const std::exception& ex) {
      e.error = ex.what();
    }
    entries.push_back(std::move(e));
  }

  const Entry* first = entries.front().ok ? &entries.front() : nullptr;
  nlohmann::json list = nlohmann::json::array();
  bool all_converged = true;
  std::printf("%-12s %-14s %6s %9s %14s %11s %11s %11s %11s", "backend", "status", "iter", "time_s", "objective",
              "certificate", "d_pressure", "d_approach", "d_force");
  if (tangential) std::printf(" %11s %11s", "d_traction", "d_t_force");
  std::printf("\n");
  // The limits of the result (grid edge, a/R) are the case's, whichever backend: judged on the first.
  std::vector<ResultLimit> limits;
  if (first) limits = result_limits(base, runs::measured_contact_size(base, first->run.summary));
  for (auto& e : entries) {
    nlohmann::json item;
    item["backend"] = e.backend;
    if (!e.ok) {
      all_converged = false;
      item["status"] = "failed";
      item["message"] = e.error;
      item["time_s"] = nullptr;
      item["iterations"] = nullptr;
      item["objective"] = nullptr;
      item["certificate"] = nullptr;
      item["summary"] = nullptr;
      list.push_back(item);
      std::printf("%-12s %-14s %s\n", e.backend.c_str(), "failed", e.error.c_str());
      continue;
    }
    const SolverReport& r = e.run.report;
    all_converged = all_converged && e.run.converged;
    item["status"] = to_string(r.status);
    item["time_s"] = r.time_s;
    item["iterations"] = r.iterations;
    item["objective"] = r.objective;
    item["certificate"] = output::to_json(r.certificate);
    e.run.summary["limits"] = output::limits_json(limits);
    item["summary"] = e.run.summary;
    double dp = 0.0, da = 0.0, df = 0.0, dt = 0.0, dft = 0.0;
    if (first) {
      const output::StaticFields& f = e.run.fields.back();
      const output::StaticFields& f0 = first->run.fields.back();
      const nlohmann::json& s0 = first->run.summary;
      dp = field_difference(f.p, f0.p);
      da = relative(number(e.run.summary, "approach"), number(s0, "approach"));
      df = relative(number(e.run.summary, "normal_force"), number(s0, "normal_force"));
      item["difference_from_first"] = {{"backend", first->backend}, {"pressure", dp}, {"approach", da}, {"normal_force", df}};
      if (tangential) {
        dt = field_difference(f.tx, f0.tx, f.ty, f0.ty);
        dft = force_difference(e.run.summary, s0);
        item["difference_from_first"]["traction"] = dt;
        item["difference_from_first"]["tangential_force"] = dft;
      }
    }
    list.push_back(item);
    auto cell = [&](double v) {
      char b[32];
      if (!first || &e == first) std::snprintf(b, sizeof b, "%11s", "-");
      else std::snprintf(b, sizeof b, "%11.2e", v);
      return std::string(b);
    };
    std::printf("%-12s %-14s %6d %9.3f %14.6e %11.2e %s %s %s", e.backend.c_str(), to_string(r.status), r.iterations,
                r.time_s, r.objective, r.certificate.worst(), cell(dp).c_str(), cell(da).c_str(), cell(df).c_str());
    if (tangential) std::printf(" %s %s", cell(dt).c_str(), cell(dft).c_str());
    std::printf("\n");
  }
  if (first) std::printf("(d_*: largest relative difference from %s)\n", first->backend.c_str());
  const std::string path = (std::filesystem::path(dir) / "compare.json").string();
  output::write_file_whole(path, list.dump(2) + "\n");
  std::printf("wrote %s\n", path.c_str());
  std::fflush(stdout);
  if (runs::report_limits(limits, dir)) return runs::kExitBadInput;
  if (!all_converged) {
    std::cerr << "error: solver: not every backend converged (see " << path << ")\n";
    return runs::kExitUnconverged;
  }
  return runs::kExitOk;
}

}  // namespace

void add_compare_command(CLI::App& app, int& exit_code) {
  auto args = std::make_shared<CompareArgs>();
  CLI::App* sub = app.add_subcommand("compare", "Solve one case with several backends and compare the results");
  sub->footer(
      "Solves the same case once per backend (fallback off, so each result is that backend's own), writes "
      "compare.json into the output folder (a list of {backend, status, time_s, iterations, objective, "
      "certificate, summary}) and prints a table: status, iterations, time, objective, the largest certificate "
      "residual, and the largest relative difference of the pressure field, the approach and the force from the "
      "first backend (tangential cases add the traction field and the tangential force: d_traction, d_t_force). "
      "Use it to check that the backends agree on a new kind of case or to pick the fastest. A finite case "
      "(problem finite) solves the condensed program with each backend; 'ipopt-sparse' adds Ipopt on the sparse "
      "saddle form (docs/finite.md), certified on the condensed program (normal and tangential cases). "
      "Exit code 0 when every backend converged, 3 otherwise, 2 for bad input, 5 when compare.json cannot be written.");
  sub->add_option("case", args->case_path, "case file (JSON)")->required();
  sub->add_option("--backends", args->backends, "comma-separated backends (default ipopt,nlopt,native)")
      ->delimiter(',');
  sub->add_option("-o,--out", args->out, "output folder (default: output.dir of the case, else out/<name>)")
      ->check(non_empty_folder());
  sub->add_option("-s,--set", args->sets, "override a case key: path=value (repeatable)")->allow_extra_args(false);
  sub->add_flag("-q,--quiet", args->quiet, "no progress line");
  sub->callback([args, &exit_code] { exit_code = run_compare(*args); });
}

}  // namespace dc::cli
