#include "dynamic_run.hpp"

#include <cstdio>
#include <filesystem>
#include <iostream>
#include <sstream>
#include <vector>

#include "cli_common.hpp"
#include "dynamic_series.hpp"
#include "fields_writer.hpp"
#include "gnuplot_figures.hpp"
#include "interrupt_handler.hpp"
#include "summary_writer.hpp"

namespace dc::cli {
namespace {

using nlohmann::json;
namespace fs = std::filesystem;

/// The contact fields of a step (fields.csv's columns); zero without contact.
StaticFields step_fields(const Case& c, const dynamics::ContactState& cs) {
  if (cs.fields) {
    const TangentialSolution& t = *cs.fields;
    return {t.normal.pressure, t.tx, t.ty, t.sx, t.sy, t.bound, t.state, 0.0};
  }
  if (cs.pressure) return normal_fields(*cs.pressure, 1e-9);
  return normal_fields(std::vector<double>(c.grid.size(), 0.0), 1e-9);
}

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
  json snapshots = json::array();
  const int every = c.output.snapshot_every;
  const DynamicOutcome out = simulate_dynamic(c, !quiet, [&](const dynamics::DynamicSample& s) {
    if (every > 0 && s.step % every == 0) {
      const std::string name = "fields_" + std::to_string(s.step) + ".csv";
      write_fields(dir, c.grid, step_fields(c, s.contact_state), name);
      snapshots.push_back({{"step", s.step}, {"time", s.state.time}, {"file", name}});
    }
  });
  const dynamics::DynamicResult& r = out.result;
  const double elapsed = out.elapsed;
  write_text_file((fs::path(dir) / "timeseries.csv").string(), out.timeseries);
  json summary = out.summary;
  json files = {{"summary", "summary.json"}, {"timeseries", "timeseries.csv"}};
  if (!snapshots.empty()) files["snapshots"] = snapshots;
  if (c.output.plots && !r.interrupted) {  // an interrupted run writes its data, not figures
    json plots = json::array();
    for (const auto& img : render_gnuplot(dir, c.name, figures(c))) plots.push_back(fs::path(img).filename().string());
    files["plots"] = plots;
  }
  summary["files"] = files;
  const std::string path = write_summary(dir, summary);
  if (!quiet) {
    std::printf("%s: %s, %d steps (%d rejected), contact model %s, %.3g s; worst certificate %.2e\n", c.name.c_str(),
                r.completed ? "completed" : r.interrupted ? "interrupted" : "stopped", r.steps, r.rejected_steps, r.contact_model.c_str(), elapsed,
                r.worst_certificate);
    if (r.fallback_steps > 0)
      std::printf("  %d steps fell back from the first backend (backends used: %s)\n", r.fallback_steps,
                  json(r.backends).dump().c_str());
    std::printf("  final t %.6g s: position [%.6g, %.6g, %.6g] m, velocity [%.6g, %.6g, %.6g] m/s, omega [%.6g, %.6g, "
                "%.6g] rad/s\n",
                r.final.time, r.final.position.x(), r.final.position.y(), r.final.position.z(), r.final.velocity.x(),
                r.final.velocity.y(), r.final.velocity.z(), r.final.omega.x(), r.final.omega.y(), r.final.omega.z());
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
  if (!r.completed) {
    std::cerr << "error: dynamic run " << r.status << "; the time series so far is in " << dir << "\n";
    return kExitUnconverged;
  }
  return kExitOk;
}

}  // namespace dc::cli
