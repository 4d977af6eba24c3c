#include "dang_van.hpp"

#include <cmath>
#include <limits>
#include <stdexcept>

#include "number_text.hpp"

namespace dc {

DangVanParameters DangVanParameters::from_fatigue_limits(double torsion_limit, double bending_limit) {
  DangVanParameters p;
  p.beta = torsion_limit;
  p.alpha = 3.0 * (torsion_limit / bending_limit - 0.5);
  return p;
}

std::string DangVanParameters::validate() const {
  if (!std::isfinite(alpha)) return "alpha: must be finite, got " + six_digits(alpha);
  if (!std::isfinite(beta) || beta <= 0.0) return "beta: must be positive and finite, got " + six_digits(beta);
  return "";
}

DangVanResult dang_van(const std::vector<Voigt>& path, const DangVanParameters& parameters) {
  if (const std::string why = parameters.validate(); !why.empty())
    throw std::invalid_argument("Dang Van: " + why);
  if (path.empty()) throw std::invalid_argument("Dang Van: empty stress path");
  const int n = static_cast<int>(path.size());
  Eigen::MatrixXd u(5, n);
  for (int t = 0; t < n; ++t) {
    for (const double v : path[static_cast<std::size_t>(t)])
      if (!std::isfinite(v)) throw std::invalid_argument("Dang Van: non-finite stress at instant " + std::to_string(t));
    u.col(t) = deviatoric_coordinates(path[static_cast<std::size_t>(t)]);
  }

  DangVanResult out;
  out.ball = smallest_enclosing_ball(u);
  out.radius = out.ball.radius();
  const Eigen::Matrix<double, 5, 1> centre = out.ball.centre;
  out.residual_deviator = from_deviatoric_coordinates(centre);
  out.mesoscopic_shear.resize(path.size());
  out.hydrostatic.resize(path.size());
  out.index = -std::numeric_limits<double>::infinity();
  for (int t = 0; t < n; ++t) {
    const Eigen::Matrix<double, 5, 1> shifted = u.col(t) - centre;
    const double tau = tresca_shear(from_deviatoric_coordinates(shifted));
    const double p_h = hydrostatic(path[static_cast<std::size_t>(t)]);
    out.mesoscopic_shear[static_cast<std::size_t>(t)] = tau;
    out.hydrostatic[static_cast<std::size_t>(t)] = p_h;
    if (const double value = (tau + parameters.alpha * p_h) / parameters.beta; value > out.index) {
      out.index = value;
      out.critical_instant = t;
    }
  }
  return out;
}

}  // namespace dc
