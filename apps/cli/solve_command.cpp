// dyncontact solve CASE.json [--out DIR] [--backend B] [--set path=value ...]
#include <cstdio>
#include <filesystem>
#include <iostream>
#include <memory>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>

#include "cli_common.hpp"
#include "finite_run.hpp"
#include "paper_cylinder_run.hpp"
#include "commands.hpp"
#include "dynamic_limits.hpp"
#include "dynamic_run.hpp"
#include "static_field_files.hpp"
#include "interrupt.hpp"
#include "interrupt_handler.hpp"
#include "plot_writer.hpp"
#include "accuracy_run.hpp"
#include "result_limits.hpp"
#include "subsurface_plots.hpp"
#include "subsurface_writer.hpp"
#include "summary_writer.hpp"
#include "wear_writer.hpp"
#include "table_ranks.hpp"
#include "tangential_run.hpp"

namespace dc::cli {
namespace {

struct SolveArgs {
  std::string case_path, out, backend;
  std::vector<std::string> sets;
  bool quiet = false;
};

void print_line(const char* label, double value, const char* unit, const nlohmann::json& ref, const char* ref_key) {
  std::printf("  %-16s %-12.5g %-5s", label, value, unit);
  if (ref.is_object() && ref.contains(ref_key) && ref[ref_key].is_number())
    std::printf("  (closed form %.5g)", ref[ref_key].get<double>());
  std::printf("\n");
}

/// The tangential lines of the report (from the summary, like the normal ones).
void print_tangential(const Case& c, const nlohmann::json& s) {
  const bool two_d = c.dimension == 2;
  const auto& F = s["tangential_force"];
  if (two_d)
    std::printf("  %-16s %-12.5g %-5s\n", "tangential force", F[0].get<double>(), "N/m");
  else
    std::printf("  %-16s [%.5g, %.5g] N\n  %-16s %-12.5g %-5s\n", "tangential force", F[0].get<double>(),
                F[1].get<double>(), "twisting moment", s["twisting_moment"].get<double>(), "N m");
  if (s["creepage"].is_array()) {
    std::printf("  %-16s [%.5g, %.5g]", "creepage", s["creepage"][0].get<double>(), s["creepage"][1].get<double>());
    if (!two_d) std::printf(", spin %.5g 1/m", s["spin"].get<double>());
    if (s["marching_steps"].get<int>() > 0)
      std::printf(" (%d marching steps)\n", s["marching_steps"].get<int>());
    else
      std::printf(" (steady state by Newton, %d iterations)\n", s["newton_iterations"].get<int>());
  } else {
    std::printf("  %-16s [%.5g, %.5g] m", "rigid shift", s["rigid_shift"][0].get<double>(),
                s["rigid_shift"][1].get<double>());
    if (!two_d) std::printf(", rotation %.5g rad", s["rotation"].get<double>());
    std::printf("\n");
  }
  std::printf("  %-16s %d stick, %d slip; stick %s %.5g %s\n", "contact", s["n_stick"].get<int>(),
              s["n_slip"].get<int>(), two_d ? "length" : "area", s["stick_area"].get<double>(), two_d ? "m" : "m^2");
  if (!s.contains("steps")) return;
  std::printf("  history (%zu steps):\n", s["steps"].size());
  for (const auto& st : s["steps"]) {
    std::printf("    step %d: normal force %.5g, tangential force [%.5g, %.5g], %d stick, %d slip",
                st["step"].get<int>(), st["normal_force"].get<double>(), st["tangential_force"][0].get<double>(),
                st["tangential_force"][1].get<double>(), st["n_stick"].get<int>(), st["n_slip"].get<int>());
    if (st.contains("distance")) {  // a rolling history
      std::printf(", rolled %.4g m", st["distance"].get<double>());
      if (st["creepage"].is_array()) std::printf(", creepage %.5g", st["creepage"][0].get<double>());
    }
    std::printf(", %s\n", st["solver"]["status"].get<std::string>().c_str());
  }
}

/// The summary of a run stopped before anything was finished.
nlohmann::json interrupted_summary(const Case& c) {
  nlohmann::json header = output::summary_header(c);
  header["status"] = "interrupted";
  header["files"] = {{"summary", "summary.json"}};
  return header;
}

/// While a run is under way, the summary the watchdog leaves in `dir` when an interrupt stops a
/// non-polling section (meshing, a factorisation: nothing finished yet); cleared afterwards.
class InterruptedSummaryOnWatchdog {
 public:
  InterruptedSummaryOnWatchdog(const Case& c, const std::string& dir) {
    runs::set_interrupt_last_file((std::filesystem::path(dir) / "summary.json").string(),
                            interrupted_summary(c).dump(2) + "\n");
  }
  ~InterruptedSummaryOnWatchdog() { runs::set_interrupt_last_file("", ""); }
  InterruptedSummaryOnWatchdog(const InterruptedSummaryOnWatchdog&) = delete;
  InterruptedSummaryOnWatchdog& operator=(const InterruptedSummaryOnWatchdog&) = delete;
};

int run_solve(const SolveArgs& args) {
  const Case c = load_case(args.case_path, args.sets, args.backend);
  // Under mpirun a sweep's runs are spread over the ranks (rank 0 writes); any other case is
  // solved by rank 0 alone.
  const bool root = table::launch_rank().root();
  // What a dynamic run is known to get wrong before it starts (InputError: exit 2, nothing written).
  if (c.problem == ProblemKind::dynamic && !c.sweep) dynamics::dynamic_limits_before(c);
  if (c.problem == ProblemKind::paper_cylinder)
    return runs::run_paper_cylinder(c, root ? prepare_output_dir(c, args.out) : std::string(), args.quiet);
  if (c.problem == ProblemKind::dynamic && c.sweep)
    return runs::run_dynamic_sweep(c, root ? prepare_output_dir(c, args.out) : std::string(), args.quiet);
  if (!root) return runs::kExitOk;
  if (c.problem != ProblemKind::normal && c.problem != ProblemKind::tangential && c.problem != ProblemKind::dynamic &&
      c.problem != ProblemKind::finite)
    not_implemented(c.problem);
  const std::string dir = prepare_output_dir(c, args.out);
  const InterruptedSummaryOnWatchdog last_words(c, dir);
  if (c.problem == ProblemKind::dynamic || c.problem == ProblemKind::finite) {
    try {
      return c.problem == ProblemKind::dynamic ? runs::run_dynamic(c, dir, args.quiet)
                                               : runs::run_finite(c, dir, args.quiet);
    } catch (const Interrupted&) {  // before anything was finished (e.g. while meshing the body)
      const std::string path = output::write_summary(dir, interrupted_summary(c));
      std::cerr << "interrupted before a result was finished; wrote " << path << '\n';
      return runs::interrupted_exit_code();
    }
  }

  runs::StaticRun run;
  output::SubsurfaceSnapshots subsurface_series(dir);  // a history's states (subsurface_series.hpp)
  try {
    run = runs::run_static(c, !args.quiet, c.subsurface.enabled ? runs::subsurface_file_sink(subsurface_series) : nullptr);
  } catch (const Interrupted&) {  // nothing finished: a summary that says so
    const std::string path = output::write_summary(dir, interrupted_summary(c));
    std::cerr << "interrupted before a result was finished; wrote " << path << '\n';
    return runs::interrupted_exit_code();
  }
  // The grid solved: the case's, or the one an accuracy target chose.
  Case solved = c;
  solved.grid = run.grid;
  nlohmann::json& s = run.summary;
  if (run.interrupted) s["status"] = "interrupted";
  nlohmann::json files = {{"summary", "summary.json"}};
  output::StaticFieldFiles surface{&run.fields, c.output.fields, run.history, c.output.power, &run.worn_base,
                                   &run.worn_body, &run.wear_series};
  output::write_static_field_files(dir, solved.grid, surface, files, s);
  std::vector<output::SubsurfaceBody> bodies;  // the subsurface block's field of the final state
  if (run.subsurface && c.subsurface.enabled) {  // subsurface.vti (evenly spaced depths) and the planes through the worst points
    if (subsurface_series.count() > 0) files["subsurface_series"] = subsurface_series.collection();
    bodies = runs::write_subsurface_files(dir, c, *run.subsurface, files);
  }
  if (c.output.plots && !run.interrupted) {  // an interrupted run writes its data, not figures
    Case plotted = solved;
    plotted.normal = run.normal;  // the closed-form curve of the last step's load
    nlohmann::json plots = nlohmann::json::array();
    std::vector<output::GnuplotFigure> planes;  // the subsurface planes, the worn depth
    if (!bodies.empty() && c.subsurface.planes && run.subsurface->depths.size() > 1)
      planes = output::subsurface_plane_figures(dir, c.name, bodies);
    if (!run.worn_base.empty() || !run.worn_body.empty())
      planes.push_back(output::wear_figure(dir, c.name, solved.grid, run.worn_base, run.worn_body));
    if (!run.wear_series.empty()) planes.push_back(output::wear_evolution_figure(dir, c.name, solved.grid, run.wear_series));
    for (const auto& p : output::write_static_plots(dir, plotted, run.fields.back(), planes))
      plots.push_back(std::filesystem::path(p).filename().string());
    files["plots"] = plots;
  }
  s["files"] = files;
  const std::vector<ResultLimit> limits = runs::attach_result_limits(solved, s);
  const std::string summary_path = output::write_summary(dir, s);

  const SolverReport& r = run.report;
  if (!args.quiet) {
    std::printf("%s: %s (%s, %d iterations, %.3g s; certificate %.2e)\n", c.name.c_str(), to_string(r.status),
                r.backend.c_str(), r.iterations, r.time_s, r.certificate.worst());
    const nlohmann::json ref = s.contains("hertz") ? s["hertz"] : nlohmann::json();
    const bool two_d = c.dimension == 2;
    print_line("normal force", s["normal_force"].get<double>(), two_d ? "N/m" : "N", ref, "normal_force");
    print_line("approach", s["approach"].get<double>(), "m", ref, "approach");
    print_line(two_d ? "contact width" : "contact area", s["contact_area"].get<double>(), two_d ? "m" : "m^2", ref,
               "contact_area");
    print_line("max pressure", s["max_pressure"].get<double>(), "Pa", ref, "max_pressure");
    std::printf("  %-16s %d of %zu elements\n", "in contact", s["n_contact"].get<int>(), solved.grid.size());
    if (c.problem == ProblemKind::tangential) print_tangential(c, s);
    if (s.contains("accuracy")) runs::print_accuracy(s["accuracy"]);
    if (run.subsurface_series)
      runs::print_subsurface_series(*run.subsurface_series, false);
    else if (run.subsurface)
      runs::print_subsurface(*run.subsurface);
    auto number = [](const nlohmann::json& v) {
      char b[32];
      if (!v.is_number()) return std::string("none");
      std::snprintf(b, sizeof b, "%.4g", v.get<double>());
      return std::string(b);
    };
    if (s.contains("yield"))
      for (const auto& [body, y] : s["yield"].items())
        std::printf("  yield %-5s      utilisation %s (%s); %s%s\n", body.c_str(), number(y["utilisation"]).c_str(),
                    y["criterion"].get<std::string>().c_str(),
                    y["first_yield_load_factor"].is_number()
                        ? ("first yield at " + number(y["first_yield_load_factor"]) + " x the load").c_str()
                        : "no first-yield load factor",
                    y.contains("note") ? (" (" + y["note"].get<std::string>() + ")").c_str() : "");
    if (s.contains("shakedown")) {
      const nlohmann::json& sd = s["shakedown"];
      std::printf("  shakedown        %s: limit %s x the load (p0/k %s), elastic limit %s x; p0/k %s, traction %s\n",
                  sd["verdict"].get<std::string>().c_str(), number(sd["load_factor"]).c_str(),
                  number(sd["shakedown_p0_over_k"]).c_str(), number(sd["elastic_limit_load_factor"]).c_str(),
                  number(sd["p0_over_k"]).c_str(), number(sd["traction_coefficient"]).c_str());
    }
    if (s.contains("wear")) {  // the worn profile (wear_run.hpp): cycles, updates, each body's scar
      const nlohmann::json& w = s["wear"];
      std::printf("  wear (%s)    %s cycles, %s profile updates", w["law"].get<std::string>().c_str(),
                  number(w["cycles"]).c_str(), number(w["updates"]).c_str());
      for (const char* body : {"base", "body"})
        if (w.contains(body))
          std::printf("; %s max depth %s m, volume %s m^3", body, number(w[body]["max_depth"]).c_str(),
                      number(w[body]["volume"]).c_str());
      std::printf("\n");
    }
    if (s.contains("temperature") && s["temperature"]["max_rise"].is_number()) {
      const nlohmann::json& t = s["temperature"];
      std::printf("  flash temperature rise %s K (base %s, body %s); %s of the heat %s W into the base (%s)\n",
                  number(t["max_rise"]).c_str(), number(t["base"]["max_rise"]).c_str(),
                  number(t["body"]["max_rise"]).c_str(), number(t["fraction_into_base"]).c_str(),
                  number(t["heat"]).c_str(), t["partition"].get<std::string>().c_str());
    }
    if (r.backend == "none") std::printf("note: %s\n", r.message.c_str());
    std::printf("wrote %s\n", summary_path.c_str());
    std::fflush(stdout);
  }
  if (const std::string fell_back = fallback_warning(r); !fell_back.empty())
    std::cerr << "warning: solver: " << fell_back << '\n';
  if (run.interrupted) {
    std::cerr << "interrupted after " << run.fields.size() << " finished step(s); results written to " << dir
              << '\n';
    return runs::interrupted_exit_code();
  }
  if (runs::report_limits(limits, dir)) return runs::kExitBadInput;
  if (s.contains("shakedown") && s["shakedown"].value("status", std::string()) != "optimal") {
    std::cerr << "error: shakedown: the program did not converge (" << s["shakedown"].value("status", std::string())
              << ": " << s["shakedown"].value("message", std::string()) << "); results written to " << dir << "\n";
    return runs::kExitUnconverged;
  }
  if (runs::accuracy_target_missed(s)) {
    const nlohmann::json& a = s["accuracy"];
    std::cerr << "error: accuracy: " << runs::missed_target_message(a) << "; results written to " << dir << "\n";
    return runs::kExitUnconverged;
  }
  if (!run.converged) {
    const std::string what = std::string(to_string(r.status)) + (r.message.empty() ? "" : ": " + r.message);
    if (c.solver.accept_unconverged) {
      std::cerr << "warning: solver: " << what << " (accepted: solver.accept_unconverged)\n";
      return runs::kExitOk;
    }
    std::cerr << "error: solver: did not converge (" << what << "); results written to " << dir
              << " (set solver.accept_unconverged to accept them)\n";
    return runs::kExitUnconverged;
  }
  return runs::kExitOk;
}

}  // namespace

void add_solve_command(CLI::App& app, int& exit_code) {
  auto args = std::make_shared<SolveArgs>();
  CLI::App* sub = app.add_subcommand("solve", "Solve a case file; write summary.json, fields.csv and plots");
  sub->footer(
      "Reads a case file (JSON, the contract in CASES.md; get a start with `dyncontact example hertz-sphere`), "
      "checks every key, solves it and writes into the output folder: summary.json (force, approach, contact "
      "area, peak pressure, solver status and certificate, and the Hertz/Boussinesq values when a closed form "
      "exists), fields.csv (x,y,p,tx,ty,sx,sy,state per element; state 0 free, 1 stick, 2 slip - a normal "
      "problem marks every element in contact with 1) and plots (SVG and PNG via gnuplot). A tangential case "
      "(problem \"tangential\": shift, torsion, steady or transient rolling) adds tangential_force, twisting_moment, "
      "rigid_shift/rotation or creepage/spin, n_stick, n_slip and stick_area to summary.json, and plots of the "
      "tractions between -f(p) and f(p); with a loading history (tangential.history; rolling: steps that roll a "
      "distance from the state the last one left) summary.json lists the steps and fields_<k>.csv holds each step (fields.csv the last). Any key can be "
      "changed without editing the file: --set grid.nx=128 --set normal.force=200. Exit code 0 converged, "
      "2 bad input (also: the output folder is in use by another run), 3 not converged (results are still written), "
      "4 internal error, 5 an output file could not be written (the message names it).");
  sub->add_option("case", args->case_path, "case file (JSON)")->required();
  sub->add_option("-o,--out", args->out, "output folder (default: output.dir of the case, else out/<name>)")
      ->check(non_empty_folder());
  sub->add_option("-b,--backend", args->backend, "solver backend: auto, ipopt, nlopt or native (sets solver.backend)");
  sub->add_option("-s,--set", args->sets, "override a case key: path=value, e.g. materials.body.E=2e11 (repeatable)")
      ->allow_extra_args(false);
  sub->add_flag("-q,--quiet", args->quiet, "print nothing but warnings and errors");
  sub->callback([args, &exit_code] { exit_code = report_input_errors_on_root([&] { return run_solve(*args); }); });
}

}  // namespace dc::cli
