#include "dynamic_run.hpp"

#include <chrono>
#include <cstdio>
#include <filesystem>
#include <iostream>
#include <sstream>
#include <vector>

#include "cli_common.hpp"
#include "dynamic_simulation.hpp"
#include "fields_writer.hpp"
#include "gnuplot_figures.hpp"
#include "progress.hpp"
#include "summary_writer.hpp"

namespace dc::cli {
namespace {

using nlohmann::json;
namespace fs = std::filesystem;

const char* kColumns =
    "t,x,y,z,vx,vy,vz,wx,wy,wz,Fx,Fy,Fz,Mx,My,Mz,creepage,stick_fraction,approach,contact_area,n_contact,"
    "n_stick,n_slip,kinetic_energy,certificate,newton_iterations\n";

void append_row(std::ostringstream& out, const dynamics::DynamicSample& s) {
  const auto& st = s.state;
  const auto& cs = s.contact_state;
  char line[1024];
  std::snprintf(line, sizeof line,
                "%.10g,%.10g,%.10g,%.10g,%.10g,%.10g,%.10g,%.10g,%.10g,%.10g,%.8g,%.8g,%.8g,%.8g,%.8g,%.8g,%.8g,%.6g,"
                "%.8g,%.8g,%d,%d,%d,%.10g,%.3g,%d\n",
                st.time, st.position.x(), st.position.y(), st.position.z(), st.velocity.x(), st.velocity.y(),
                st.velocity.z(), st.omega.x(), st.omega.y(), st.omega.z(), s.contact.force.x(), s.contact.force.y(),
                s.contact.force.z(), s.contact.moment.x(), s.contact.moment.y(), s.contact.moment.z(), cs.creepage,
                cs.stick_fraction, cs.in_contact ? cs.approach : 0.0, cs.contact_area, cs.n_contact, cs.n_stick,
                cs.n_slip, s.kinetic_energy, cs.certificate, s.newton_iterations);
  out << line;
}

/// The contact fields of a step (fields.csv's columns); zero without contact.
StaticFields step_fields(const Case& c, const dynamics::ContactState& cs) {
  if (cs.fields) {
    const TangentialSolution& t = *cs.fields;
    return {t.normal.pressure, t.tx, t.ty, t.sx, t.sy, t.bound, t.state, 0.0};
  }
  if (cs.pressure) return normal_fields(*cs.pressure, 1e-9);
  return normal_fields(std::vector<double>(c.grid.size(), 0.0), 1e-9);
}

json vec(const Eigen::Vector3d& v) { return {v.x(), v.y(), v.z()}; }

std::vector<GnuplotFigure> figures(const Case& c) {
  struct Series {
    const char* stem;
    const char* ylabel;
    std::vector<std::pair<int, const char*>> columns;
  };
  const std::vector<Series> all = {
      {"position", "position (m)", {{2, "x"}, {3, "y"}, {4, "z"}}},
      {"velocity", "velocity (m/s)", {{5, "vx"}, {6, "vy"}, {7, "vz"}}},
      {"omega", "angular velocity (rad/s)", {{8, "wx"}, {9, "wy"}, {10, "wz"}}},
      {"force", "contact force (N)", {{11, "Fx"}, {12, "Fy"}, {13, "Fz"}}},
      {"moment", "contact moment about the centre of mass (N m)", {{14, "Mx"}, {15, "My"}, {16, "Mz"}}},
      {"creepage", "creepage (-)", {{17, "creepage"}}},
      {"stick", "stick fraction of the contact", {{18, "stick_fraction"}}},
      {"approach", "approach (m)", {{19, "approach"}}},
      {"contact_area", c.dimension == 2 ? "contact length (m)" : "contact area (m^2)", {{20, "contact area"}}},
      {"energy", "kinetic energy (J)", {{24, "kinetic energy"}}},
  };
  std::vector<GnuplotFigure> out;
  for (const Series& s : all) {
    std::ostringstream b;
    b << "set datafile separator \",\"\nset key top right noenhanced\nset grid\nset xlabel \"time (s)\"\n"
      << "set ylabel \"" << s.ylabel << "\"\nset title \"" << c.name << "\" noenhanced\nplot ";
    for (std::size_t k = 0; k < s.columns.size(); ++k)
      b << (k ? ", " : "") << "\"timeseries.csv\" using 1:" << s.columns[k].first << " skip 1 with lines lw 2 title \""
        << s.columns[k].second << "\"";
    b << "\n";
    out.push_back({s.stem, b.str()});
  }
  return out;
}

}  // namespace

int run_dynamic(const Case& c, const std::string& dir, bool quiet) {
  dynamics::DynamicSimulation sim(c);
  std::ostringstream series;
  series << kColumns;
  const auto start = std::chrono::steady_clock::now();
  const double t_end = c.dynamic->t_end;
  Progress progress("dynamic", !quiet);
  const ProgressCallback report = progress.callback();
  json snapshots = json::array();
  const int every = c.output.snapshot_every;
  const dynamics::DynamicResult r = sim.run([&](const dynamics::DynamicSample& s) {
    append_row(series, s);
    if (every > 0 && s.step % every == 0) {
      const std::string name = "fields_" + std::to_string(s.step) + ".csv";
      write_fields(dir, c.grid, step_fields(c, s.contact_state), name);
      snapshots.push_back({{"step", s.step}, {"time", s.state.time}, {"file", name}});
    }
    if (report) report({s.step, s.state.time, s.contact_state.certificate});
    (void)t_end;
  });
  progress.finish();
  const double elapsed = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  write_text_file((fs::path(dir) / "timeseries.csv").string(), series.str());

  const auto& sp = *c.dynamic;
  json summary = summary_header(c);
  summary["status"] = r.completed ? "completed" : "stopped";
  summary["message"] = r.status;
  summary["steps"] = r.steps;
  summary["rejected_steps"] = r.rejected_steps;
  summary["final"] = {{"time", r.final.time}, {"position", vec(r.final.position)},
                      {"velocity", vec(r.final.velocity)}, {"omega", vec(r.final.omega)}};
  summary["timeseries"] = "timeseries.csv";
  summary["models"] = {{"normal_model", to_string(sp.normal_model)},
                       {"contact_model", to_string(sp.contact_model)},
                       {"contact_model_used", r.contact_model},
                       {"scheme", sp.bdf2 ? "bdf2" : "bdf1"},
                       {"friction", c.friction ? c.friction->law : "none (frictionless)"}};
  summary["solver"] = {{"backend", c.solver.backend},
                       {"backends_used", r.backends},
                       {"fallback_steps", r.fallback_steps},
                       {"status", r.completed ? "converged" : "stopped"},
                       {"newton_iterations", r.newton_iterations},
                       {"contact_solves", r.contact_solves},
                       {"time_s", elapsed},
                       {"certificate", {{"worst", r.worst_certificate}, {"last", r.last_certificate}}}};
  summary["balances"] = {{"momentum", r.momentum_imbalance}, {"energy", r.energy_imbalance}};
  json files = {{"summary", "summary.json"}, {"timeseries", "timeseries.csv"}};
  if (!snapshots.empty()) files["snapshots"] = snapshots;
  if (c.output.plots) {
    json plots = json::array();
    for (const auto& img : render_gnuplot(dir, c.name, figures(c))) plots.push_back(fs::path(img).filename().string());
    files["plots"] = plots;
  }
  summary["files"] = files;
  const std::string path = write_summary(dir, summary);
  if (!quiet) {
    std::printf("%s: %s, %d steps (%d rejected), contact model %s, %.3g s; worst certificate %.2e\n", c.name.c_str(),
                r.completed ? "completed" : "stopped", r.steps, r.rejected_steps, r.contact_model.c_str(), elapsed,
                r.worst_certificate);
    std::printf("  final t %.6g s: position [%.6g, %.6g, %.6g] m, velocity [%.6g, %.6g, %.6g] m/s, omega [%.6g, %.6g, "
                "%.6g] rad/s\n",
                r.final.time, r.final.position.x(), r.final.position.y(), r.final.position.z(), r.final.velocity.x(),
                r.final.velocity.y(), r.final.velocity.z(), r.final.omega.x(), r.final.omega.y(), r.final.omega.z());
    if (r.fallback_steps > 0)
      std::printf("  %d steps fell back from the first backend (backends used: %s)\n", r.fallback_steps,
                  json(r.backends).dump().c_str());
    std::printf("wrote %s\n", path.c_str());
    std::fflush(stdout);
  }
  if (!r.completed) {
    std::cerr << "error: dynamic run " << r.status << "; the time series so far is in " << dir << "\n";
    return kExitUnconverged;
  }
  return kExitOk;
}

}  // namespace dc::cli
