#pragma once
// Friction bounds f(p) of (2.4)-(2.5): Coulomb f = mu p, Tresca f = g(x) (3.18, here a
// constant bound on the contact), or a tabulated f(p) with bounded slope (piecewise linear).
#include <string>
#include <vector>

namespace dc {

/// The friction bound f(p): "coulomb", "tresca" or "table" in the case file.
enum class FrictionLawKind { coulomb, tresca, table };

struct FrictionSpec {
  FrictionLawKind law = FrictionLawKind::coulomb;
  double mu = 0.0;
  double bound = 0.0;                      ///< tresca
  std::vector<double> pressure, bound_table;  ///< table
};

class FrictionLaw {
 public:
  static FrictionLaw coulomb(double mu);
  static FrictionLaw tresca(double bound);
  static FrictionLaw table(std::vector<double> pressure, std::vector<double> bound);
  static FrictionLaw from_spec(const FrictionSpec& spec);

  /// f(p); 0 where p <= 0 (no contact, no friction).
  double bound(double p) const;
  /// Largest |df/dp| (the paper's bounded slope; mu for Coulomb, 0 for Tresca).
  double max_slope() const;
  /// True when f depends on p (the outer loop (3.31)-(3.32) is needed if p depends on tau).
  bool pressure_dependent() const { return kind_ != Kind::tresca; }
  std::string name() const;

 private:
  using Kind = FrictionLawKind;
  Kind kind_ = Kind::coulomb;
  double mu_ = 0.0, tresca_ = 0.0;
  std::vector<double> p_, f_;
};

/// "coulomb", "tresca", "table".
const char* to_string(FrictionLawKind law);

}  // namespace dc
