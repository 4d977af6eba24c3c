#include "material.hpp"

#include <cmath>

#include "errors.hpp"
#include "number_text.hpp"

namespace dc {
namespace {
void check_nu(double nu, const std::string& key) {
  if (!std::isfinite(nu) || nu <= -1.0 || nu >= 0.5)
    throw InputError(key + ".nu", "Poisson's ratio must lie in (-1, 0.5), got " + six_digits(nu));
}

/// Moduli far outside every material (soft gels ~1e2 Pa, diamond ~1e12 Pa) overflow the
/// compliance arithmetic: rejected with the range this program handles.
void check_modulus_range(double v, const std::string& key) {
  if (v < 1e-6 || v > 1e20)
    throw InputError(key, "got " + six_digits(v) + " Pa: outside the range this program handles (1e-6 to 1e20 Pa)");
}
}  // namespace

Elastic Elastic::from_E_nu(double E, double nu, const std::string& key) {
  if (!std::isfinite(E) || E <= 0.0)
    throw InputError(key + ".E", "Young's modulus must be positive and finite, got " + six_digits(E));
  check_modulus_range(E, key + ".E");
  check_nu(nu, key);
  return Elastic{E, nu, E / (2.0 * (1.0 + nu)), false};
}

Elastic Elastic::from_G_nu(double G, double nu, const std::string& key) {
  if (!std::isfinite(G) || G <= 0.0)
    throw InputError(key + ".G", "shear modulus must be positive and finite, got " + six_digits(G));
  check_modulus_range(G, key + ".G");
  check_nu(nu, key);
  return Elastic{2.0 * G * (1.0 + nu), nu, G, false};
}

Elastic Elastic::make_rigid() { return Elastic{INFINITY, 0.0, INFINITY, true}; }

double Elastic::normal_compliance() const { return rigid ? 0.0 : (1.0 - nu * nu) / E; }
double Elastic::one_minus_nu_over_G() const { return rigid ? 0.0 : (1.0 - nu) / G; }
double Elastic::nu_over_G() const { return rigid ? 0.0 : nu / G; }
double Elastic::one_minus_2nu_over_G() const { return rigid ? 0.0 : (1.0 - 2.0 * nu) / G; }

double MaterialPair::E_star() const {
  return 1.0 / (body.normal_compliance() + base.normal_compliance());
}
double MaterialPair::kappa() const {
  return body.one_minus_2nu_over_G() - base.one_minus_2nu_over_G();
}
double MaterialPair::tangential_a() const {
  return body.one_minus_nu_over_G() + base.one_minus_nu_over_G();
}
double MaterialPair::tangential_b() const { return body.nu_over_G() + base.nu_over_G(); }
double MaterialPair::mindlin_compliance() const {
  auto term = [](const Elastic& m) { return m.rigid ? 0.0 : (2.0 - m.nu) / m.G; };
  return term(body) + term(base);
}

}  // namespace dc
