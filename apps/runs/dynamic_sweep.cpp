#include "dynamic_sweep.hpp"

#include "accuracy_run.hpp"
#include "dynamic_accuracy.hpp"
#include "dynamic_limits.hpp"
#include "dynamic_run.hpp"
#include "errors.hpp"
#include "progress.hpp"
#include "table_ranks.hpp"

namespace dc::runs {

using nlohmann::json;

DynamicSweepOutcome simulate_dynamic_sweep(const Case& c, bool quiet) {
  const std::vector<SweepPoint> points = sweep_points(c);
  for (const SweepPoint& p : points) {  // what is known wrong before any run
    try {
      dynamics::dynamic_limits_before(p.run);
    } catch (const InputError& e) {
      throw InputError(e.key(), std::string(e.what()).substr(e.key().size() + 2) + " (sweep run " + p.label + ")");
    }
  }
  const table::LaunchRank launched = table::launch_rank();
  Progress progress("sweep", launched.root() && !quiet);
  // One unit per run: its summary, its time series and how it ended (null: not run, interrupted).
  const std::vector<json> units = table::run_distributed(
      points.size(),
      [&](std::size_t k) -> json {
        // Each run with its error estimate and target where the case asks (dynamic_accuracy.hpp).
        const DynamicOutcome run = simulate_dynamic_with_accuracy(points[k].run, false);
        return {{"summary", run.summary},
                {"timeseries", run.timeseries},
                {"energy", run.energy},
                {"completed", run.result.completed},
                {"interrupted", run.result.interrupted},
                {"input_error", run.result.input_error}};
      },
      [&](std::size_t done, std::size_t total) { progress.count(done, total, "runs"); });
  progress.finish();
  DynamicSweepOutcome out;
  out.root = launched.root();
  if (!out.root) return out;
  out.planned = points.size();

  json runs = json::array(), limits = json::array();
  for (std::size_t k = 0; k < units.size() && !out.interrupted; ++k) {
    const json& u = units[k];
    if (u.is_null()) {  // not run (interrupted): the runs before it
      out.interrupted = true;
      break;
    }
    json run = {{"label", points[k].label}, {"value", points[k].value}};
    if (u.contains("error")) {  // a run that failed: reported, the others kept
      run["status"] = "failed";
      run["message"] = u["error"];
      out.all_completed = false;
      runs.push_back(run);
      continue;
    }
    const std::string file = "timeseries_" + std::to_string(k) + ".csv";
    for (auto it = u["summary"].begin(); it != u["summary"].end(); ++it) run[it.key()] = it.value();
    run["timeseries"] = file;
    for (json l : u["summary"]["limits"]) {
      out.limit_error = out.limit_error || l["level"] == "error";
      l["run"] = points[k].label;
      limits.push_back(l);
    }
    runs.push_back(run);
    out.files.push_back(file);
    out.texts.push_back(u["timeseries"].get<std::string>());
    out.energy_files.push_back("energy_" + std::to_string(k) + ".csv");
    out.energy_texts.push_back(u["energy"].get<std::string>());
    out.labels.push_back(points[k].label);
    out.all_completed = out.all_completed && u["completed"].get<bool>();
    if (accuracy_target_missed(u["summary"])) out.targets_missed.push_back(points[k].label);
    out.interrupted = u["interrupted"].get<bool>();
    if (out.input_error.empty()) out.input_error = u["input_error"].get<std::string>();
  }
  out.summary = {{"name", c.name},
                 {"problem", "dynamic"},
                 {"sweep", {{"key", c.sweep->key}, {"values", c.sweep->values}}},
                 {"status", out.interrupted ? "interrupted" : out.all_completed ? "completed" : "stopped"},
                 {"limits", limits},
                 {"runs", runs}};
  return out;
}

}  // namespace dc::runs
