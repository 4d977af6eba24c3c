#include "normal_run.hpp"

#include <algorithm>
#include <chrono>

#include "progress.hpp"
#include "solve_case.hpp"
#include "summary_writer.hpp"

namespace dc::runs {

NormalRun run_normal(const Case& c, bool progress, const std::vector<double>* warm_pressure) {
  NormalRun run;
  {
    Progress reporter("solving " + c.name + " (" + to_string(c.solver.backend) + ")", progress);
    // time_s: the whole solve (set-up and every backend tried), not only the last attempt.
    const auto start = std::chrono::steady_clock::now();
    run.solution = solve_normal_case(c, reporter.callback(), warm_pressure);
    run.solution.report.time_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    reporter.finish();
  }
  // A solver leaves round-off pressures outside the contact; those within the certificate
  // tolerance of the peak count as free.
  run.fields = output::normal_fields(run.solution.pressure, std::max(c.solver.certificate_tol, 1e-12));
  run.summary = output::normal_summary(c, run.solution, run.fields);
  return run;
}

}  // namespace dc::runs
