#pragma once
// Isotropic linear elastic materials and the combined constants of two bodies in contact.
#include <string>

namespace dc {

/// One isotropic elastic body. `rigid` bodies contribute no compliance.
struct Elastic {
  double E = 0.0;   ///< Young's modulus (Pa)
  double nu = 0.0;  ///< Poisson's ratio, in (-1, 0.5)
  double G = 0.0;   ///< shear modulus (Pa)
  bool rigid = false;

  /// Validates and completes; `key` prefixes error messages (e.g. "materials.body").
  static Elastic from_E_nu(double E, double nu, const std::string& key = "material");
  static Elastic from_G_nu(double G, double nu, const std::string& key = "material");
  static Elastic make_rigid();

  double normal_compliance() const;  ///< (1 - nu^2)/E, 0 if rigid
  double one_minus_nu_over_G() const;  ///< (1 - nu)/G
  double nu_over_G() const;            ///< nu/G
  double one_minus_2nu_over_G() const; ///< (1 - 2nu)/G
};

/// The body (+) on the substrate (-): constants of the relative displacement u+ - u-.
struct MaterialPair {
  Elastic body;
  Elastic base;

  /// 1/E* = (1-nu+^2)/E+ + (1-nu-^2)/E-.
  double E_star() const;
  /// The paper's kappa (4.3): (1-2nu+)/G+ - (1-2nu-)/G-; 0 for identical constants.
  double kappa() const;
  /// Tangential (Cerruti) constants: sum (1-nu)/G and sum nu/G over both bodies.
  double tangential_a() const;
  double tangential_b() const;
  /// Effective shear compliance used by Cattaneo-Mindlin: sum (2-nu)/G.
  double mindlin_compliance() const;
};

}  // namespace dc
