#include "dynamic_run.hpp"

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <iostream>
#include <sstream>
#include <vector>

#include "accuracy_run.hpp"
#include "dynamic_accuracy.hpp"
#include "dynamic_peaks.hpp"
#include "dynamic_series.hpp"
#include "dynamic_subsurface.hpp"
#include "dynamic_temperature.hpp"
#include "dynamic_wear.hpp"
#include "dynamic_sweep.hpp"
#include "energy_series.hpp"
#include "exit_codes.hpp"
#include "fe_body_estimate.hpp"
#include "fields_vti.hpp"
#include "fields_writer.hpp"
#include "gnuplot_figures.hpp"
#include "interrupt_handler.hpp"
#include "output_files.hpp"
#include "profile.hpp"
#include "progress.hpp"
#include "result_limits.hpp"
#include "summary_entries.hpp"
#include "subsurface_series.hpp"
#include "summary_writer.hpp"
#include "wear_writer.hpp"
#ifdef DYNCONTACT_WITH_FE
#include "body_snapshots.hpp"
#include "elastic_body.hpp"
#include "finite_body_contact.hpp"
#endif

namespace dc::runs {
namespace {

using nlohmann::json;
namespace fs = std::filesystem;

json vec(const Eigen::Vector3d& v) { return {v.x(), v.y(), v.z()}; }

/// summary.json "energy" (docs/wear_energy.md "Dynamic runs"): the dissipated frictional work,
/// the peak step's frictional power and the audit of the run.
json energy_json(const dynamics::DynamicResult& r) {
  const dynamics::EnergyAudit& e = r.energy;
  return {{"dissipated", e.dissipated},
          {"frictional_power", r.peak_frictional_power},
          {"frictional_power_time", r.peak_power_time},
          {"frictional_power_last", r.last_frictional_power},
          {"audit",
           {{"work_of_loads", e.work_of_loads},
            {"kinetic_change", e.kinetic_change},
            {"elastic_change", e.elastic - e.elastic_initial},
            {"dissipated", e.dissipated},
            {"numerical_damping", e.numerical_damping},
            {"relative_residual", r.energy_relative_residual}}}};
}

}  // namespace

DynamicOutcome simulate_dynamic(const Case& c, bool progress,
                                const std::function<void(const dynamics::DynamicSample&)>& on_step,
                                const dynamics::ContactWrench::WornGap& worn_gap) {
  DynamicOutcome out;
  check_fe_body_fits(c);
#ifdef DYNCONTACT_WITH_FE
  dynamics::DynamicSimulation sim(c, dynamics::make_finite_body(c));
#else
  dynamics::DynamicSimulation sim(c);  // an fe_body: an input error saying how to build with it
#endif
  if (worn_gap) sim.set_worn_gap(worn_gap);
  std::ostringstream series, energy;
  series << output::kTimeseriesColumns;
  const auto start = std::chrono::steady_clock::now();
  Progress line("dynamic", progress);
  const double t_end = c.dynamic->t_end;
  // The height of the centre over the lowest point (an fe_body's from its mesh).
  ContactPeaks peaks(sim.finite_body() ? sim.finite_body()->centre_height() : c.dynamic->radius);
  out.result = sim.run([&](const dynamics::DynamicSample& s) {
    output::append_timeseries_row(series, s);
    output::append_energy_row(energy, s);
    peaks.add(s);
    if (on_step) on_step(s);
    if (progress) line.time(s.state.time, t_end);
  });
  line.finish();
  out.elapsed = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  out.timeseries = series.str();
  {
    std::ostringstream text;
    text << output::kEnergyColumns;
    output::append_energy_start(text, out.result.initial.time, dynamics::kinetic_energy(sim.body(), out.result.initial),
                                out.result.energy.elastic_initial);
    text << energy.str();
    out.energy = text.str();
  }

  const dynamics::DynamicResult& r = out.result;
  const auto& sp = *c.dynamic;
  json summary = output::summary_header(c);
  summary["status"] = r.completed ? "completed" : r.interrupted ? "interrupted" : "stopped";
  summary["message"] = r.status;
  summary["steps"] = r.steps;
  summary["rejected_steps"] = r.rejected_steps;
  const dynamics::TimeStepCounts& ts = r.time_steps;
  summary["time_steps"] = {{"accepted", ts.accepted}, {"rejected", ts.rejected}, {"dt_min", ts.dt_min},
                           {"dt_max", ts.dt_max}, {"adaptive", r.adaptive}};
  if (r.adaptive) {
    summary["time_steps"]["error_rejections"] = ts.error_rejections;
    summary["time_steps"]["event_rejections"] = ts.event_rejections;
    summary["time_steps"]["events"] = ts.events;
  }
  summary["final"] = {{"time", r.final.time}, {"position", vec(r.final.position)},
                      {"velocity", vec(r.final.velocity)}, {"omega", vec(r.final.omega)}};
  summary["timeseries"] = "timeseries.csv";
  summary["peaks"] = peaks.to_json();
  out.peaks = peaks.quantities();
  summary["models"] = {{"normal_model", to_string(sp.normal_model)},
                       {"contact_model", to_string(sp.contact_model)},
                       {"contact_model_used", r.contact_model},
                       {"scheme", sp.bdf2 ? "bdf2" : "bdf1"},
                       {"friction", c.friction ? to_string(c.friction->law) : "none (frictionless)"}};
  summary["solver"] = {{"backend", to_string(c.solver.backend)},
                       {"backends_used", r.backends},
                       {"fallback_steps", r.fallback_steps},
                       {"status", r.completed ? "converged" : "stopped"},
                       {"newton_iterations", r.newton_iterations},
                       {"chord_steps", r.chord_steps},
                       {"contact_solves", r.contact_solves},
                       {"outer_iterations", r.alternations},
                       {"sensitivities", r.sensitivities},
                       {"time_s", out.elapsed},
                       {"certificate", {{"worst", r.worst_certificate}, {"last", r.last_certificate}}}};
  summary["balances"] = {{"momentum", r.momentum_imbalance}, {"energy", r.energy_imbalance}};
  summary["energy"] = energy_json(r);
  out.limits = r.limits;
  summary["limits"] = output::limits_json(out.limits);
#ifdef DYNCONTACT_WITH_FE
  if (const dynamics::FiniteBody* body = sim.finite_body()) {  // as for problem "finite"
    summary["body_dofs"] = body->elastic_body().dofs();
    summary["body_elements"] = body->elastic_body().mesh().elements.size();
    summary["max_body_displacement"] = body->max_displacement();
    summary["mesh_time_s"] = body->mesh_seconds();
    summary["factorisation_time_s"] = body->elastic_body().factorisation_seconds();
    summary["body"] = {{"mass", sim.body().mass()},
                       {"inertia", {sim.body().inertia_body()(0, 0), sim.body().inertia_body()(1, 1),
                                    sim.body().inertia_body()(2, 2)}},
                       {"radius", body->centre_height()}};
  }
#endif
  out.summary = std::move(summary);
  return out;
}

int run_dynamic(const Case& c, const std::string& dir, bool quiet) {
  json snapshots = json::array();
  const int every = c.output.snapshot_every;
#ifdef DYNCONTACT_WITH_FE
  output::BodySnapshots body_series(dir);  // an fe_body: body_NNNN.vtu per snapshot and body.pvd
#endif
  Grid grid = c.grid;  // of the run the snapshots are taken from (an accuracy target chooses it)
  output::FieldsSnapshots surface_series(dir);  // fields_NNNN.vti per snapshot and fields.pvd
  DynamicSubsurface field(c);  // the snapshots' and the peak load's tractions, their field after the run
  DynamicTemperature temperature(c);  // the flash temperature at the snapshots
  DynamicWear wear(c);                // every step's wear, in each body's frame
  const bool subsurface = field.wanted();
  const auto write_snapshot = [&](const dynamics::DynamicSample& s) {
    wear.observe(grid, s);
    const output::StaticFields* kept = nullptr;
    output::StaticFields fields;
    const bool at_snapshot = every > 0 && s.step % every == 0;
    if (at_snapshot || temperature.every_step()) {
      fields = dynamic_step_fields(grid, s.contact_state);
      temperature.observe(grid, s, fields, at_snapshot);
    }
    if (at_snapshot) {
      const std::string name = "fields_" + std::to_string(s.step) + ".csv";
      output::write_fields(dir, grid, fields, name);
      json snapshot = {{"step", s.step}, {"time", s.state.time}, {"file", name},
                       {"image", surface_series.write(grid, fields, s.step, s.state.time)}};
#ifdef DYNCONTACT_WITH_FE
      if (s.finite_body) snapshot["body"] = body_series.write(*s.finite_body, s.state);
#endif
      snapshots.push_back(snapshot);
      kept = &fields;
    }
    field.observe(grid, s, kept);
  };
  // A worn gap (wear.gap_feedback; build_case refuses it with an accuracy estimate): one run.
  const DynamicOutcome out =
      wear.feeds_back()
          ? simulate_dynamic(c, !quiet, write_snapshot,
                             [&wear](const dynamics::StepKinematics& k, std::vector<double>& depth) { wear.worn_depth(k, depth); })
          : simulate_dynamic_with_accuracy(
                c, !quiet, every > 0 || subsurface || wear.wanted() ? std::function(write_snapshot) : nullptr, &grid);
  const dynamics::DynamicResult& r = out.result;
  const double elapsed = out.elapsed;
  output::write_file_whole((fs::path(dir) / "timeseries.csv").string(), out.timeseries);
  output::write_file_whole((fs::path(dir) / "energy.csv").string(), out.energy);
  json summary = out.summary;
  json files = {{"summary", "summary.json"}, {"timeseries", "timeseries.csv"}, {"energy", "energy.csv"}};
  if (!snapshots.empty()) files["snapshots"] = snapshots;
  if (surface_series.count() > 0) files["fields_series"] = surface_series.collection();
  temperature.add_entries(summary);
  wear.add_entries(summary);
  // The worn depths (dynamic_wear.hpp): the track's along world x in wear.csv, the body's along
  // its circumference in wear_body.csv.
  const WornStrip worn_base = wear.base(), worn_body = wear.body();
  if (!worn_base.depth.empty()) {
    output::write_wear(dir, worn_base.grid, worn_base.depth, {});
    files["wear"] = "wear.csv";
  }
  if (!worn_body.depth.empty()) {
    output::write_wear(dir, worn_body.grid, {}, worn_body.depth, "wear_body.csv", "s");
    files["wear_body"] = "wear_body.csv";
  }
  std::optional<SubsurfaceSeries> series;  // the field of the snapshots and the peak load, the worst of them
  if (subsurface && !r.interrupted) {
    output::SubsurfaceSnapshots images(dir);
    series = field.add_entries(grid, c.subsurface.enabled ? subsurface_file_sink(images) : SubsurfaceSink(), summary);
    if (images.count() > 0) files["subsurface_series"] = images.collection();
  }
#ifdef DYNCONTACT_WITH_FE
  if (body_series.count() > 0) files["body_series"] = body_series.collection();
#endif
  if (c.output.plots && !r.interrupted) {  // an interrupted run writes its data, not figures
    json plots = json::array();
    std::vector<output::GnuplotFigure> figures = output::timeseries_figures(c, {{"timeseries.csv", ""}});
    if (!worn_base.depth.empty())
      figures.push_back(output::wear_figure(dir, c.name, worn_base.grid, worn_base.depth, {}, "wear_x", "track x"));
    if (!worn_body.depth.empty())
      figures.push_back(output::wear_figure(dir, c.name, worn_body.grid, {}, worn_body.depth, "wear_s", "circumference s"));
    for (const auto& img : output::render_gnuplot(dir, c.name, figures)) plots.push_back(fs::path(img).filename().string());
    files["plots"] = plots;
  }
  summary["files"] = files;
  const std::string path = output::write_summary(dir, summary);
  if (!quiet) {
    std::printf("%s: %s, %d steps (%d rejected), contact model %s, %.3g s; worst certificate %.2e\n", c.name.c_str(),
                r.completed ? "completed" : r.interrupted ? "interrupted" : "stopped", r.steps, r.rejected_steps, r.contact_model.c_str(), elapsed,
                r.worst_certificate);
    if (r.adaptive)
      std::printf("  adaptive time steps: %d accepted, %d rejected (%d for the error, %d at %d contact events), dt "
                  "from %.3g to %.3g s\n",
                  r.time_steps.accepted, r.time_steps.rejected, r.time_steps.error_rejections,
                  r.time_steps.event_rejections, r.time_steps.events, r.time_steps.dt_min, r.time_steps.dt_max);
    if (r.fallback_steps > 0)
      std::printf("  %d steps fell back from the first backend (backends used: %s)\n", r.fallback_steps,
                  json(r.backends).dump().c_str());
    std::printf("  final t %.6g s: position [%.6g, %.6g, %.6g] m, velocity [%.6g, %.6g, %.6g] m/s, omega [%.6g, %.6g, "
                "%.6g] rad/s\n",
                r.final.time, r.final.position.x(), r.final.position.y(), r.final.position.z(), r.final.velocity.x(),
                r.final.velocity.y(), r.final.velocity.z(), r.final.omega.x(), r.final.omega.y(), r.final.omega.z());
    if (summary.contains("accuracy")) print_accuracy(summary["accuracy"]);
    if (series) print_subsurface_series(*series, true);
    if (summary.contains("temperature") && summary["temperature"]["max_rise"].is_number())
      std::printf("  flash temperature rise %.4g K at step %d (t = %.4g s; %s)\n",
                  summary["temperature"]["max_rise"].get<double>(), summary["temperature"]["step"].get<int>(),
                  summary["temperature"]["time"].get<double>(),
                  summary["temperature"]["model"].get<std::string>().c_str());
    if (summary.contains("wear")) {
      const json& w = summary["wear"];
      std::printf("  wear (%s): %.4g revolutions over %.4g m", w["law"].get<std::string>().c_str(),
                  w["cycles"].get<double>(), w["travel"].get<double>());
      for (const char* b : {"base", "body"})
        if (w.contains(b))
          std::printf(", %s max depth %.4g m, volume %.4g", b, w[b]["max_depth"].get<double>(), w[b]["volume"].get<double>());
      std::printf("\n");
    }
    std::printf("wrote %s\n", path.c_str());
    std::fflush(stdout);
  }
  if (r.interrupted) {
    std::cerr << "interrupted after " << r.steps << " step(s); the time series so far is in " << dir << "\n";
    return interrupted_exit_code();
  }
  if (!r.input_error.empty()) {  // input a step could not take: named as any input error
    std::cerr << "error: " << r.input_error << " (the run stopped there; the time series so far is in " << dir
              << ")\n";
    return kExitBadInput;
  }
  if (report_limits(out.limits, dir)) return kExitBadInput;
  if (accuracy_target_missed(summary)) {
    const json& a = summary["accuracy"];
    std::cerr << "error: accuracy: " << missed_target_message(a) << "; results written to " << dir << "\n";
    return kExitUnconverged;
  }
  if (!r.completed) {
    std::cerr << "error: dynamic run " << r.status << "; the time series so far is in " << dir << "\n";
    return kExitUnconverged;
  }
  return kExitOk;
}

int run_dynamic_sweep(const Case& c, const std::string& dir, bool quiet) {
  DynamicSweepOutcome out = simulate_dynamic_sweep(c, quiet);
  if (!out.root) return kExitOk;
  for (std::size_t k = 0; k < out.files.size(); ++k)
    output::write_file_whole((fs::path(dir) / out.files[k]).string(), out.texts[k]);
  for (std::size_t k = 0; k < out.energy_files.size(); ++k)
    output::write_file_whole((fs::path(dir) / out.energy_files[k]).string(), out.energy_texts[k]);
  json& summary = out.summary;
  json files = {{"summary", "summary.json"}, {"timeseries", out.files}, {"energy", out.energy_files}};
  if (c.output.plots && !out.interrupted) {  // an interrupted sweep writes its data, not figures
    std::vector<std::pair<std::string, std::string>> runs;
    for (std::size_t k = 0; k < out.files.size(); ++k) runs.emplace_back(out.files[k], out.labels[k]);
    json plots = json::array();
    for (const auto& img : output::render_gnuplot(dir, c.name, output::timeseries_figures(c, runs)))
      plots.push_back(fs::path(img).filename().string());
    files["plots"] = plots;
  }
  summary["files"] = files;
  const std::string path = output::write_summary(dir, summary);
  if (!quiet) {
    for (const json& r : summary["runs"])
      std::printf("%s %s: %s%s\n", c.name.c_str(), r["label"].get<std::string>().c_str(),
                  r["status"].get<std::string>().c_str(),
                  r.contains("message") && r["status"] != "completed" ? (", " + r["message"].get<std::string>()).c_str()
                                                                        : "");
    std::printf("wrote %s\n", path.c_str());
    std::fflush(stdout);
  }
  if (out.interrupted) {
    std::cerr << "interrupted after " << out.files.size() << " of " << out.planned
              << " run(s) (the last may be partial); see " << path << '\n';
    return interrupted_exit_code();
  }
  if (!out.input_error.empty()) {
    std::cerr << "error: " << out.input_error << " (that run stopped there; see " << path << ")\n";
    return kExitBadInput;
  }
  if (out.limit_error) {
    for (const json& l : summary["limits"])
      if (l["level"] == "error")
        std::cerr << "error: " << l["key"].get<std::string>() << ": " << l["run"].get<std::string>() << ": "
                  << l["message"].get<std::string>() << " (results written to " << dir << " for inspection)\n";
    return kExitBadInput;
  }
  if (!out.targets_missed.empty()) {
    for (const std::string& label : out.targets_missed)
      std::cerr << "error: accuracy: the target was not met in run " << label << " (see " << path << ")\n";
    return kExitUnconverged;
  }
  if (!out.all_completed) {
    std::cerr << "error: a run stopped early (see " << path << ")\n";
    return kExitUnconverged;
  }
  return kExitOk;
}

}  // namespace dc::runs
