#include "elastic_stiffness.hpp"

#include <cmath>

#include "errors.hpp"
#include "number_text.hpp"

namespace dc::fe {

void check_stiffness(const Stiffness& C, const std::string& key) {
  if (!C.allFinite()) throw InputError(key, "stiffness has non-finite entries");
  const double scale = C.cwiseAbs().maxCoeff();
  if (!(scale > 0.0)) throw InputError(key, "stiffness is zero");
  if ((C - C.transpose()).cwiseAbs().maxCoeff() > 1e-12 * scale)
    throw InputError(key, "stiffness is not symmetric");
  const Eigen::SelfAdjointEigenSolver<Stiffness> eig(C);
  const double lmin = eig.eigenvalues().minCoeff();
  if (!(lmin > 1e-12 * scale))
    throw InputError(key, "stiffness is not positive definite (smallest eigenvalue " + six_digits(lmin) +
                              " Pa): not a stable elastic material");
}

Stiffness isotropic_stiffness(double E, double nu, const std::string& key) {
  if (!(E > 0.0) || !std::isfinite(E)) throw InputError(key + ".E", "must be positive, got " + six_digits(E));
  if (!(nu > -1.0 && nu < 0.5)) throw InputError(key + ".nu", "must lie in (-1, 0.5), got " + six_digits(nu));
  const double lambda = E * nu / ((1.0 + nu) * (1.0 - 2.0 * nu));
  const double mu = E / (2.0 * (1.0 + nu));
  Stiffness C = Stiffness::Zero();
  for (int i = 0; i < 3; ++i) {
    for (int j = 0; j < 3; ++j) C(i, j) = lambda;
    C(i, i) = lambda + 2.0 * mu;
    C(i + 3, i + 3) = mu;
  }
  return C;
}

Stiffness cubic_stiffness(double c11, double c12, double c44, const std::string& key) {
  Stiffness C = Stiffness::Zero();
  for (int i = 0; i < 3; ++i) {
    for (int j = 0; j < 3; ++j) C(i, j) = c12;
    C(i, i) = c11;
    C(i + 3, i + 3) = c44;
  }
  check_stiffness(C, key);
  return C;
}

Stiffness anisotropic_stiffness(const std::array<double, 21>& upper, const std::string& key) {
  Stiffness C;
  int k = 0;
  for (int i = 0; i < 6; ++i)
    for (int j = i; j < 6; ++j) C(i, j) = C(j, i) = upper[k++];
  check_stiffness(C, key);
  return C;
}

}  // namespace dc::fe
