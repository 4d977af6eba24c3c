// Downstream use of the installed library: a Hertz sphere pressed on a half-space (steel on
// steel), solved by NormalProblem and checked against the closed form within 5 %.
// Usage: dyncontact_consumer [backend]   (default "auto")
#include <dlfcn.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <exception>
#include <numbers>
#include <optional>
#include <string>
#include <vector>

#include <dyncontact/core/errors.hpp>
#include <dyncontact/core/grid.hpp>
#include <dyncontact/core/hertz.hpp>
#include <dyncontact/core/material.hpp>
#include <dyncontact/core/profile.hpp>
#include <dyncontact/nlp/normal_problem.hpp>
#include <dyncontact/nlp/solver_options.hpp>

namespace {

bool check(const char* what, double value, double expected, double tolerance) {
  const double error = std::abs(value / expected - 1.0);
  const bool ok = error <= tolerance;
  std::printf("%-16s %14.6e  Hertz %14.6e  error %6.2f %%  %s\n", what, value, expected,
              100.0 * error, ok ? "ok" : "FAIL");
  return ok;
}

/// The library changes nothing in a program that uses it: MUMPS's entry dmumps_c (which
/// `dyncontact` replaces to hand MUMPS its ordering) is MUMPS's own here, not one defined in
/// this program.
bool mumps_is_mumps() {
  void* entry = dlsym(RTLD_DEFAULT, "dmumps_c");
  Dl_info entry_info{}, own_info{};
  if (entry == nullptr) {
    std::printf("dmumps_c        not loaded (MUMPS linked statically or not at all)  ok\n");
    return true;
  }
  const bool found = dladdr(entry, &entry_info) != 0 &&
                     dladdr(reinterpret_cast<void*>(&mumps_is_mumps), &own_info) != 0;
  const bool own = found && std::string(entry_info.dli_fname) == own_info.dli_fname;
  std::printf("dmumps_c        from %s  %s\n", found ? entry_info.dli_fname : "?", found && !own ? "ok" : "FAIL");
  return found && !own;
}

}  // namespace

int main(int argc, char** argv) try {
  const double E = 2.1e11, nu = 0.3, R = 0.01, P = 100.0;
  const int n = 64;

  dc::MaterialPair materials;
  materials.body = dc::Elastic::from_E_nu(E, nu, "materials.body");
  materials.base = dc::Elastic::from_E_nu(E, nu, "materials.base");
  const dc::hertz::SphereSolution hertz = dc::hertz::sphere(R, P, materials.E_star());

  const double half = 1.3 * hertz.a;
  const dc::Grid grid = dc::Grid::make(3, n, n, -half, half, -half, half);
  dc::ProfileSpec profile;
  profile.type = dc::ProfileType::sphere;
  profile.radius = R;

  dc::NormalProblem problem(grid, materials, dc::profile_heights(profile, grid));
  dc::NormalSpec control;
  control.control = dc::Control::force;
  control.value = P;
  dc::SolverOptions solver;
  if (argc > 1) {
    const std::optional<dc::Backend> backend = dc::backend_from_string(argv[1]);
    if (!backend)
      throw dc::InputError("backend", std::string("unknown backend '") + argv[1] + "' (auto, ipopt, nlopt, native)");
    solver.backend = *backend;
  }

  const dc::NormalSolution solution = problem.solve(control, solver);
  const dc::SolverReport& report = solution.report;
  std::printf("backend %s (requested %s), status %s, %d iterations, certificate %.2e\n",
              report.backend.c_str(), report.requested.c_str(), dc::to_string(report.status),
              report.iterations, report.certificate.worst());

  const double p_max = *std::max_element(solution.pressure.begin(), solution.pressure.end());
  const auto n_contact = std::count_if(solution.pressure.begin(), solution.pressure.end(),
                                       [](double p) { return p > 0.0; });
  const double radius = std::sqrt(static_cast<double>(n_contact) * grid.area() / std::numbers::pi);

  bool ok = report.status == dc::SolveStatus::converged;
  ok = check("force (N)", solution.force, P, 0.05) && ok;
  ok = check("peak pressure", p_max, hertz.p0, 0.05) && ok;
  ok = check("approach (m)", solution.approach, hertz.approach, 0.05) && ok;
  ok = check("contact radius", radius, hertz.a, 0.05) && ok;
  ok = mumps_is_mumps() && ok;
  std::printf("%s\n", ok ? "consumer: PASSED" : "consumer: FAILED");
  return ok ? 0 : 1;
} catch (const std::exception& e) {
  std::fprintf(stderr, "consumer: error: %s\n", e.what());
  return 2;
}
