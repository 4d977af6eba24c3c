// dyncontact table CASE.json --creepage A:B:N [--lateral ...] [--spin ...] [--out DIR]
// A creep-force table: steady rolling at every combination of the values, spread over the
// cores (threads) or, under mpirun, over the ranks (table/table_ranks.hpp).
#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <iostream>
#include <memory>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>

#include "cli_common.hpp"
#include "commands.hpp"
#include "errors.hpp"
#include "interrupt.hpp"
#include "interrupt_handler.hpp"
#include "normal_run.hpp"
#include "output_files.hpp"
#include "progress.hpp"
#include "result_limits.hpp"
#include "summary_entries.hpp"
#include "table_output.hpp"
#include "table_points.hpp"
#include "table_ranges.hpp"
#include "table_ranks.hpp"

namespace dc::cli {
namespace {

struct TableArgs {
  std::string case_path, out, backend, creepage, lateral, spin;
  std::vector<std::string> sets;
  bool quiet = false;
};

/// The option's values, or the case's own value when the option is not given.
std::vector<double> axis(const std::string& option, const std::string& text, double case_value) {
  return text.empty() ? std::vector<double>{case_value} : table::parse_table_range(option, text);
}

int run_table(const TableArgs& args, bool root) {
  const Case c = load_case(args.case_path, args.sets, args.backend);
  if (c.problem != ProblemKind::tangential || !c.tangential)
    throw InputError("problem", "a creep-force table needs a tangential case with \"regime\": \"rolling\"");
  const auto& modes = c.tangential->rolling.modes;
  table::TableAxes axes;
  axes.creepage_x = axis("--creepage", args.creepage, modes[0].value);
  axes.creepage_y = axis("--lateral", args.lateral, c.dimension == 2 ? 0.0 : modes[1].value);
  axes.spin = axis("--spin", args.spin, c.dimension == 2 ? 0.0 : modes[2].value);
  table::check_table_case(c, axes);
  // The contact every point shares (the same load): its result limits (grid edge, a/R,
  // resolution) before the table; an error refuses the table (exit 2, nothing written).
  runs::NormalRun contact = runs::run_normal(c, false);
  const std::vector<ResultLimit> limits = runs::attach_result_limits(c, contact.summary);
  if (std::any_of(limits.begin(), limits.end(), [](const ResultLimit& l) { return l.error; })) {
    if (root)
      for (const ResultLimit& l : limits)
        std::cerr << (l.error ? "error: " : "warning: ") << l.key << ": the contact of the table's load: "
                  << l.message << '\n';
    return runs::kExitBadInput;
  }
  // Only rank 0 writes; the folder is checked before anything is solved.
  const std::string dir = root ? prepare_output_dir(c, args.out) : std::string();
  if (root) runs::report_limits(limits, dir);  // warnings only

  runs::Progress progress("table of " + std::to_string(axes.size()) + " points", root && !args.quiet);
  const std::size_t per_line = axes.creepage_x.size();
  const std::vector<nlohmann::json> lines = table::run_distributed(
      axes.lines(), [&](std::size_t line) { return table::solve_table_line(c, axes, line); },
      [&](std::size_t done, std::size_t) { progress.count(done * per_line, axes.size()); });
  progress.finish();
  if (!root) return runs::kExitOk;

  // Interrupted: the lines before the first one not finished (whole lines, in table order).
  std::vector<table::TableRow> rows;
  bool interrupted = false;
  for (std::size_t l = 0; l < lines.size() && !interrupted; ++l) {
    interrupted = lines[l].is_null();
    if (interrupted) break;
    const std::vector<table::TableRow> r = table::rows_from_line(axes, l, lines[l]);
    rows.insert(rows.end(), r.begin(), r.end());
  }
  namespace fs = std::filesystem;
  const std::string csv = (fs::path(dir) / "table.csv").string();
  output::write_file_whole(csv, table::table_csv(rows));
  // The figures (none when interrupted: the data so far), then table.json last: a table.json
  // is there only when everything before it was written.
  const std::vector<std::string> images =
      c.output.plots && !interrupted ? table::table_plots(dir, c, axes, rows) : std::vector<std::string>{};
  nlohmann::json meta = table::table_json(c, axes, rows);
  meta["status"] = interrupted ? "interrupted" : "completed";
  meta["limits"] = output::limits_json(limits);
  output::write_file_whole((fs::path(dir) / "table.json").string(), meta.dump(2) + "\n");
  if (interrupted) {
    std::cerr << "interrupted after " << rows.size() << " of " << axes.size() << " points; wrote " << csv
              << ", table.json\n";
    return runs::interrupted_exit_code();
  }

  std::size_t bad = 0;
  for (const table::TableRow& r : rows) bad += r.status != "converged";
  std::printf("table %s: %zu points (%zu creepage_x x %zu creepage_y x %zu spin), %zu converged\n", c.name.c_str(),
              rows.size(), axes.creepage_x.size(), axes.creepage_y.size(), axes.spin.size(), rows.size() - bad);
  std::printf("wrote %s, table.json", csv.c_str());
  for (const auto& img : images) std::printf(", %s", fs::path(img).filename().c_str());
  std::printf("\n");
  std::fflush(stdout);
  if (bad > 0) {
    for (std::size_t i = 0; i < rows.size(); ++i)
      if (rows[i].status != "converged")
        std::cerr << "error: point " << i << " (creepage_x " << rows[i].creepage_x << ", creepage_y "
                  << rows[i].creepage_y << ", spin " << rows[i].spin << "): " << rows[i].status << ": "
                  << rows[i].message << '\n';
    std::cerr << "error: solver: " << bad << " of " << rows.size()
              << " points not converged (status in table.csv, messages in table.json)\n";
    return runs::kExitUnconverged;
  }
  return runs::kExitOk;
}

}  // namespace

void add_table_command(CLI::App& app, int& exit_code) {
  auto args = std::make_shared<TableArgs>();
  CLI::App* sub = app.add_subcommand("table", "Creep-force table of a steady rolling case (for multibody codes)");
  sub->footer(
      "Solves steady rolling at every combination of the creepage_x (--creepage), creepage_y (--lateral) and spin "
      "(--spin) values; an option not given keeps the case's own value. Values: start:stop:count (count values from "
      "start to stop) or a list a,b,c. Writes table.csv (creepage_x, creepage_y, spin, Fx, Fy, Mz, Fx_mu_P, Fy_mu_P, "
      "n_stick, certificate, status; one row per point, creepage_x fastest, then creepage_y, then spin), table.json "
      "(the case, the ranges, the points that failed) and the plots table_Fx / table_Fy. Forces act on the body; "
      "F/(mu P) is over the friction capacity sum f(p) A. The points run on the cores with threads "
      "(DYNCONTACT_THREADS), or over the ranks of `mpirun -n N dyncontact table ...` (same files). "
      "Exit code 0 when every point converged, 3 otherwise (the others are kept), 2 for bad input, 5 when a file "
      "cannot be written.");
  sub->add_option("case", args->case_path, "case file (JSON), a rolling tangential case")->required();
  sub->add_option("--creepage", args->creepage, "longitudinal creepage xi: start:stop:count or a,b,c");
  sub->add_option("--lateral", args->lateral, "lateral creepage eta (3-D): start:stop:count or a,b,c");
  sub->add_option("--spin", args->spin, "spin phi (1/m, 3-D): start:stop:count or a,b,c");
  sub->add_option("-o,--out", args->out, "output folder (default: output.dir of the case, else out/<name>)")
      ->check(non_empty_folder());
  sub->add_option("-b,--backend", args->backend, "solver backend (auto, ipopt, nlopt, native)");
  sub->add_option("-s,--set", args->sets, "override a case key: path=value (repeatable)")->allow_extra_args(false);
  sub->add_flag("-q,--quiet", args->quiet, "no progress line");
  sub->callback([args, &exit_code] {
    exit_code = report_input_errors_on_root([&] { return run_table(*args, table::launch_rank().root()); });
  });
}

}  // namespace dc::cli
