// dyncontact_subsurface_bench: the subsurface field against the normal solve it follows
// (docs/subsurface.md "Speed"), one thread. The case of dyncontact_bench: a Hertz sphere on a
// half-space, steel on steel (E = 210 GPa, nu = 0.3), R = 0.01 m, P = 100 N, n x n elements over
// +-1.3 Hertz radii. Per size and repeat:
//   normal solve      NormalProblem set-up (profile, compliance, plans) and solve (native);
//   field + measures  what a run's subsurface block computes for one body from that solution
//                     (apps/runs/subsurface_run.cpp): SubsurfaceField set-up, the nine
//                     components at `--depths` depths from 0 to 1.5 a (the block's default),
//                     von Mises, Tresca and the hydrostatic stress at every point and their
//                     extremes, and the largest orthogonal shear |sigma_xz|.
// Times are the thread's CPU time (less sensitive to a loaded machine than the wall clock;
// page faults included), the median over --repeat runs; the ratio is of the medians.
//   dyncontact_subsurface_bench [--sizes 64,128,256] [--repeat 5] [--depths 32]
#include <time.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <stdexcept>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>

#include "grid.hpp"
#include "hertz.hpp"
#include "material.hpp"
#include "normal_problem.hpp"
#include "profile.hpp"
#include "solver_report.hpp"
#include "subsurface_field.hpp"
#include "bench_sphere.hpp"

namespace {

double thread_seconds() {
  timespec t{};
  clock_gettime(CLOCK_THREAD_CPUTIME_ID, &t);
  return static_cast<double>(t.tv_sec) + 1e-9 * static_cast<double>(t.tv_nsec);
}

double median(std::vector<double> v) {
  std::sort(v.begin(), v.end());
  const std::size_t h = v.size() / 2;
  return v.size() % 2 ? v[h] : 0.5 * (v[h - 1] + v[h]);
}

struct Timing {
  double solve = 0.0, field = 0.0, measures = 0.0;
  double max_tresca_over_p0 = 0.0, depth_over_a = 0.0;
};

Timing run_once(int n, int depth_count) {
  const dc::bench::BenchSphere sphere;
  const dc::MaterialPair& materials = sphere.materials;
  const dc::Elastic& steel = materials.body;
  const dc::hertz::SphereSolution& hertz = sphere.hertz;
  const dc::ProfileSpec& profile = sphere.profile;
  const dc::NormalSpec& control = sphere.normal;
  dc::SolverOptions solver;
  solver.backend = dc::Backend::native;
  solver.fallback = false;

  Timing t;
  const double t0 = thread_seconds();
  const dc::Grid grid = sphere.grid(n);
  dc::NormalProblem problem(grid, materials, dc::profile_heights(profile, grid), solver.operator_kind);
  const dc::NormalSolution solution = problem.solve(control, solver);
  const double t1 = thread_seconds();
  if (solution.report.status != dc::SolveStatus::converged)
    throw std::runtime_error("normal solve did not converge on " + std::to_string(n) + "^2");

  std::vector<double> depths;
  for (int k = 0; k < depth_count; ++k) depths.push_back(1.5 * hertz.a * k / std::max(1, depth_count - 1));
  dc::SurfaceTractions tractions;
  tractions.p = solution.pressure;
  const double t2 = thread_seconds();
  dc::SubsurfaceField field(grid, steel, dc::BodySide::body);
  const dc::SubsurfaceResult result = field.compute(tractions, depths);
  const double t3 = thread_seconds();
  const dc::SubsurfaceMeasures measures = dc::subsurface_measures(result);
  double orthogonal = 0.0;
  for (std::size_t k = 0; k < depths.size(); ++k) {
    const double* sxz = result.component(k, dc::kSxz);
    for (std::size_t e = 0; e < grid.size(); ++e) orthogonal = std::max(orthogonal, std::abs(sxz[e]));
  }
  const double t4 = thread_seconds();
  t.solve = t1 - t0;
  t.field = t3 - t2;
  t.measures = t4 - t3;
  const double p0 = *std::max_element(solution.pressure.begin(), solution.pressure.end());
  t.max_tresca_over_p0 = orthogonal > 0.0 ? measures.max_tresca.value / p0 : 0.0;
  t.depth_over_a = measures.max_tresca.depth / hertz.a;
  return t;
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"dyncontact_subsurface_bench: subsurface field and measures against one normal solve"};
  std::vector<int> sizes{64, 128, 256};
  int repeat = 5, depth_count = 32;
  app.add_option("--sizes", sizes, "grid sizes n (n x n elements)")->delimiter(',');
  app.add_option("--repeat", repeat, "runs per size (medians)")->check(CLI::PositiveNumber);
  app.add_option("--depths", depth_count, "depths from 0 to 1.5 a")->check(CLI::PositiveNumber);
  CLI11_PARSE(app, argc, argv);

  std::printf("%-9s %7s %10s %10s %10s %10s %8s %9s  %s\n", "grid", "depths", "solve(s)", "field(s)",
              "measure(s)", "total(s)", "ratio", "ms/depth", "max tau_1 (p0, at a)");
  for (const int n : sizes) {
    std::vector<double> solve, field, measures, total;
    Timing last;
    for (int r = 0; r < repeat; ++r) {
      last = run_once(n, depth_count);
      solve.push_back(last.solve);
      field.push_back(last.field);
      measures.push_back(last.measures);
      total.push_back(last.field + last.measures);
    }
    const double s = median(solve), f = median(field), m = median(measures), tot = median(total);
    std::printf("%4dx%-4d %7d %10.3f %10.3f %10.3f %10.3f %8.2f %9.1f  %.4f at %.3f\n", n, n, depth_count, s, f, m,
                tot, tot / s, 1e3 * f / depth_count, last.max_tresca_over_p0, last.depth_over_a);
  }
  std::printf("\nsolve: NormalProblem set-up and solve (native); field: SubsurfaceField set-up and compute (one body,\n"
              "depths 0..1.5 a); measure: von Mises, Tresca, hydrostatic and |sigma_xz| extremes; ratio = total / solve.\n"
              "Thread CPU time, medians of the repeats.\n");
  return 0;
}
