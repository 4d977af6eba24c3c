#include "paper_cylinder.hpp"

#include <algorithm>
#include <cmath>

#include "errors.hpp"
#include "interrupt.hpp"

namespace dc::paper_cylinder {
namespace {

void require(bool ok, const std::string& key, const std::string& reason) {
  if (!ok) throw InputError("dimensionless." + key, reason);
}

Sample sample_at(double t, double u, double w, const TractionLaw& law) {
  Sample s;
  s.t_bar = t;
  s.u = u;
  s.w = w;
  const double ratio = w / u;
  s.F_bar = std::abs(law.force_ratio(ratio));
  s.sliding = std::abs(ratio) >= 1.0;
  s.l_bar = s.sliding ? 0.0 : std::sqrt(std::max(0.0, 1.0 - s.F_bar));
  s.v_bar = std::abs(w);
  return s;
}

}  // namespace

double force_ratio(double s) {
  if (std::abs(s) >= 1.0) return s > 0.0 ? 1.0 : -1.0;
  return 2.0 * s - s * std::abs(s);
}

double force_ratio_slope(double s) { return std::abs(s) >= 1.0 ? 0.0 : 2.0 * (1.0 - std::abs(s)); }

void check(const Parameters& p) {
  require(p.eta > 0.0, "eta", "must be positive (M R^2 / I; \"inf\" for no rotational inertia)");
  require(p.epsilon > 0.0 && std::isfinite(p.epsilon), "epsilon", "must be positive and finite (l / R)");
  require(p.mu > 0.0 && std::isfinite(p.mu), "mu", "the friction coefficient must be positive");
  require(p.v_bar0 >= 0.0 && std::isfinite(p.v_bar0), "v_bar0", "must be >= 0 (a magnitude)");
  require(p.t_bar_end > 0.0 && std::isfinite(p.t_bar_end), "t_bar_end", "must be positive");
  require(std::isfinite(p.gamma_bar), "gamma_bar", "must be finite");
  require(std::isfinite(p.M0_bar), "M0_bar", "must be finite");
  require(std::isfinite(p.T_bar), "T_bar", "must be finite");
  require(std::isnan(p.w0) || std::isfinite(p.w0), "v_bar0", "the initial slip must be finite");
}

Run simulate(const Parameters& p, double dt, Scheme scheme, const TractionLaw& law) {
  check(p);
  if (!(dt > 0.0) || !std::isfinite(dt)) throw InputError("time.dt", "must be positive");
  const double c = std::isinf(p.eta) ? 0.0 : 1.0 / (1.0 + p.eta);  // c eps is the slip's "mass"
  const double ce = c * p.mu * p.epsilon;
  const int steps = static_cast<int>(std::ceil(p.t_bar_end / dt - 1e-9));

  Run run;
  double u0 = 1.0, w0 = std::isnan(p.w0) ? -p.v_bar0 : p.w0, u_old = u0, w_old = w0;  // y_n, y_{n-1}
  if (c == 0.0) {
    // No rotational inertia: the slip is algebraic from the start, phi(w/u) = -M^(0).
    if (std::abs(p.M0_bar) >= 1.0) {
      run.ok = false;
      run.message = "eta = inf and |M0_bar| >= 1: no rolling state (the cylinder spins freely)";
      run.samples.push_back(sample_at(0.0, u0, w0, law));
      return run;
    }
    const double target = -p.M0_bar;  // phi(s) = target, s in (-1, 1)
    const double s = target >= 0.0 ? 1.0 - std::sqrt(1.0 - target) : -(1.0 - std::sqrt(1.0 + target));
    w0 = s * u0;
    w_old = w0;
  }
  run.samples.push_back(sample_at(0.0, u0, w0, law));
  for (int n = 1; n <= steps; ++n) {
    if (interrupt_requested()) {  // the samples so far are complete steps
      run.ok = false;
      run.interrupted = true;
      run.message = "interrupted at t_bar = " + std::to_string((n - 1) * dt);
      break;
    }
    const double t = n * dt;
    const double M = p.M0_bar + p.gamma_bar * t;
    // Backward differences a y_{n+1} - hist = dt f(y_{n+1}): BDF1 a = 1, hist = y_n; BDF2
    // (from the second step) a = 3/2, hist = 2 y_n - y_{n-1}/2.
    const bool second = scheme == Scheme::bdf2 && n > 1;
    const double a = second ? 1.5 : 1.0;
    const double hist_u = second ? 2.0 * u0 - 0.5 * u_old : u0;
    const double hist_w = second ? 2.0 * w0 - 0.5 * w_old : w0;
    double u = u0, w = w0;
    int it = 0;
    bool converged = false;
    for (; it < 50; ++it) {
      const double s = w / u;
      const double phi = law.force_ratio(s), dphi = law.slope(s);
      const double r1 = a * u - hist_u - dt * (-phi + p.T_bar);
      const double r2 = ce * (a * w - hist_w) - dt * (-phi + c * p.T_bar - (1.0 - c) * M);
      const double scale = std::max(1.0, std::abs(u));
      if (std::abs(r1) <= 1e-13 * scale && std::abs(r2) <= 1e-13 * scale) {
        converged = true;
        break;
      }
      // d phi / du = dphi (-w/u^2), d phi / dw = dphi / u.
      const double pu = dphi * (-w / (u * u)), pw = dphi / u;
      const double j11 = a + dt * pu, j12 = dt * pw;
      const double j21 = dt * pu, j22 = ce * a + dt * pw;
      const double det = j11 * j22 - j12 * j21;
      if (!(std::abs(det) > 0.0)) break;  // eta = inf beyond saturation: no solution
      double du = -(j22 * r1 - j12 * r2) / det, dw = -(j11 * r2 - j21 * r1) / det;
      // Keep the rolling speed positive (s = w/u): halve a step that would reverse it.
      while (u + du <= 0.5 * u) {
        du *= 0.5;
        dw *= 0.5;
      }
      u += du;
      w += dw;
    }
    if (!converged) {
      run.ok = false;
      run.message = "step " + std::to_string(n) + " (t_bar = " + std::to_string(t) +
                    "): the implicit step did not converge" +
                    (c == 0.0 ? " (eta = inf: the driving moment exceeds mu P R, the cylinder spins freely)" : "");
      break;
    }
    u_old = u0;
    w_old = w0;
    u0 = u;
    w0 = w;
    Sample s = sample_at(t, u, w, law);
    s.newton_iterations = it;
    run.samples.push_back(s);
  }
  return run;
}

Sample quasi_static(const Parameters& p, double t) {
  const double k = std::isinf(p.eta) ? 1.0 : p.eta / (1.0 + p.eta);
  Sample s;
  s.t_bar = t;
  const double M = p.M0_bar + p.gamma_bar * t;
  s.F_bar = std::abs(k * M);
  s.u = 1.0 + k * (p.M0_bar * t + 0.5 * p.gamma_bar * t * t);
  s.sliding = s.F_bar >= 1.0;
  s.l_bar = s.sliding ? 0.0 : std::sqrt(1.0 - s.F_bar);
  s.v_bar = s.sliding ? std::numeric_limits<double>::infinity() : s.u * (1.0 - s.l_bar);
  s.w = k * M >= 0.0 ? -s.v_bar : s.v_bar;
  return s;
}

}  // namespace dc::paper_cylinder
