#include "shakedown_samples.hpp"

#include <limits>
#include <stdexcept>

namespace dc {

Voigt ShakedownSamples::residual(const double* y) const {
  Voigt rho{};
  for (int c = 0; c < p(); ++c)
    rho[static_cast<std::size_t>(index_of(components[static_cast<std::size_t>(c)]))] = residual_scale * y[c];
  return rho;
}

double exact_elastic_limit(const std::vector<Voigt>& stress, const YieldCriterion& criterion, std::size_t& worst) {
  double fmax = 0.0;
  worst = 0;
  for (std::size_t k = 0; k < stress.size(); ++k)
    if (const double f = criterion.exact_ratio(stress[k]); f > fmax) {
      fmax = f;
      worst = k;
    }
  return fmax > 0.0 ? 1.0 / fmax : std::numeric_limits<double>::infinity();
}

ShakedownSamples shakedown_samples(const StressHistory& history, const YieldCriterion& criterion,
                                   const ResidualModel& model) {
  if (const std::string why = history.validate(); !why.empty()) throw std::invalid_argument("shakedown: " + why);
  if (const std::string why = criterion.validate(); !why.empty()) throw std::invalid_argument("shakedown: " + why);
  if (const std::string why = model.validate(); !why.empty()) throw std::invalid_argument("shakedown: " + why);

  ShakedownSamples s;
  s.depths = history.n_depths();
  s.positions = history.n_positions();
  s.residual_scale = criterion.shear_yield();
  const Eigen::MatrixXd l = criterion.factor();
  const Eigen::Index q = l.rows();

  s.u.resize(q, static_cast<Eigen::Index>(s.depths) * s.positions);
  for (int j = 0; j < s.depths; ++j)
    for (int i = 0; i < s.positions; ++i) {
      const Eigen::Map<const Eigen::Matrix<double, 6, 1>> sigma(history.at(j, i).data());
      s.u.col(static_cast<Eigen::Index>(j) * s.positions + i) = l * sigma;
    }

  // The kept columns: each free component's k L e_c, unless within 1e-12 of the span of those kept.
  Eigen::MatrixXd kept(q, 0), basis(q, 0);
  for (const VoigtComponent c : model.free) {
    const Eigen::VectorXd column = s.residual_scale * l.col(index_of(c));
    Eigen::VectorXd v = column;
    for (int pass = 0; pass < 2; ++pass)
      for (Eigen::Index m = 0; m < basis.cols(); ++m) v -= basis.col(m).dot(v) * basis.col(m);
    if (!(v.norm() > 1e-12 * std::max(column.norm(), 1.0))) continue;
    kept.conservativeResize(q, kept.cols() + 1);
    kept.col(kept.cols() - 1) = column;
    basis.conservativeResize(q, basis.cols() + 1);
    basis.col(basis.cols() - 1) = v / v.norm();
    s.components.push_back(c);
  }
  s.w = kept;
  return s;
}

}  // namespace dc
