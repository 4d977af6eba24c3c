// The body's tilt (its rigid rotations about x and y) in finite normal contact. A given tilt
// shifts the profile: the approach at (x, y) is delta + theta_y x - theta_x y (small rotations
// about the grid origin, right-hand rule, z up). A given line of action of the normal force
// adds the two moment rows of the rigid motion, sum A p (x, y) = P (x_L, y_L), whose
// multipliers are the tilt: solved by a Broyden iteration on (theta_x, theta_y), one normal
// solve (warm-started) per iterate. The moment of the pressure is monotone in the tilt (the
// gradient of the convex dual), so the iteration converges from the untilted body.
#include <cmath>

#include <Eigen/Dense>

#include "errors.hpp"
#include "finite_contact.hpp"

namespace dc {

std::vector<double> tilted_heights(const std::vector<double>& heights, const Grid& grid, double theta_x,
                                   double theta_y) {
  std::vector<double> h = heights;
  for (int j = 0; j < grid.ny; ++j)
    for (int i = 0; i < grid.nx; ++i) {
      double& v = h[grid.index(i, j)];
      if (std::isfinite(v)) v += -theta_y * grid.xc(i) + theta_x * grid.yc(j);
    }
  return h;
}

namespace {

/// The pressure's first moments less P (x_L, y_L) (N m).
Eigen::Vector2d moment_residual(const NormalSolution& s, const Grid& g, const std::array<double, 2>& line,
                                double P) {
  Eigen::Vector2d m(-P * line[0], -P * line[1]);
  for (int j = 0; j < g.ny; ++j)
    for (int i = 0; i < g.nx; ++i) {
      const double f = s.pressure[g.index(i, j)] * g.area();
      m += f * Eigen::Vector2d(g.xc(i), g.yc(j));
    }
  return m;
}

/// The contact's size (m): the radius of a disk of the contact area, at least one element.
double contact_size(const NormalSolution& s, const Grid& g) {
  std::size_t n = 0;
  for (double p : s.pressure) n += p > 0.0 ? 1 : 0;
  return std::sqrt(std::max<double>(static_cast<double>(n), 1.0) * g.area() / M_PI);
}

}  // namespace

NormalSolution FiniteContact::solve_tilted(const NormalSpec& control, const SolverOptions& solver,
                                           const ProgressCallback& progress) {
  if (control.control != Control::force)
    throw InputError("fe_body.load_line", "a line of action needs the normal force (normal.force), not an approach");
  const std::array<double, 2> line = *load_line_;
  const double P = control.value;
  Eigen::Vector2d theta = Eigen::Vector2d::Zero();
  const auto solve_at = [&](const Eigen::Vector2d& t) {
    normal_->set_heights(tilted_heights(face_->heights(), grid_, t(0), t(1)));  // from the untilted face
    return normal_->solve(control, solver, progress);
  };
  NormalSolution sol = solve_at(theta);
  int solves = 1;
  if (sol.report.status != SolveStatus::converged) return sol;
  Eigen::Vector2d r = moment_residual(sol, grid_, line, P);
  // The Jacobian d r / d theta, first by differences with a tilt that moves the contact's edge
  // by about the approach, then Broyden's updates.
  const double L = contact_size(sol, grid_);
  const double step = std::max(std::abs(sol.approach), 1e-12) / L;
  Eigen::Matrix2d J;
  for (int k = 0; k < 2; ++k) {
    Eigen::Vector2d t = theta;
    t(k) += step;
    const NormalSolution s = solve_at(t);
    ++solves;
    if (s.report.status != SolveStatus::converged) return s;
    J.col(k) = (moment_residual(s, grid_, line, P) - r) / step;
  }
  constexpr int kMaxTiltIterations = 50;
  int it = 0;
  for (; it < kMaxTiltIterations && r.norm() > solver.certificate_tol * P * contact_size(sol, grid_); ++it) {
    const Eigen::Vector2d d = -J.fullPivLu().solve(r);
    theta += d;
    sol = solve_at(theta);
    ++solves;
    if (sol.report.status != SolveStatus::converged) break;
    const Eigen::Vector2d r_new = moment_residual(sol, grid_, line, P);
    J += (r_new - r - J * d) * d.transpose() / d.squaredNorm();
    r = r_new;
  }
  tilt_ = {theta(0), theta(1)};
  // The moment rows join the certificate's force residual: |M - P x_L| / (P a).
  const double moment_residual_rel = r.norm() / (P * contact_size(sol, grid_));
  sol.report.certificate.force_residual = std::max(sol.report.certificate.force_residual, moment_residual_rel);
  sol.report.message += " [tilt: " + std::to_string(it) + " Broyden iterations, " + std::to_string(solves) +
                        " normal solves, moment residual " + format_number(moment_residual_rel) + "]";
  if (sol.report.status == SolveStatus::converged && moment_residual_rel > solver.certificate_tol)
    sol.report.status = SolveStatus::not_converged;
  return sol;
}

}  // namespace dc
