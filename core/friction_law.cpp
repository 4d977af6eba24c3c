#include "friction_law.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "errors.hpp"

namespace dc {

FrictionLaw FrictionLaw::coulomb(double mu) {
  if (!(mu >= 0.0) || !std::isfinite(mu))
    throw InputError("friction.mu", "the friction coefficient must be non-negative, got " + std::to_string(mu));
  FrictionLaw law;
  law.kind_ = Kind::coulomb;
  law.mu_ = mu;
  return law;
}

FrictionLaw FrictionLaw::tresca(double bound) {
  if (!(bound > 0.0) || !std::isfinite(bound))
    throw InputError("friction.bound", "the Tresca bound must be positive, got " + std::to_string(bound));
  FrictionLaw law;
  law.kind_ = Kind::tresca;
  law.tresca_ = bound;
  return law;
}

FrictionLaw FrictionLaw::table(std::vector<double> pressure, std::vector<double> bound) {
  if (pressure.size() < 2 || pressure.size() != bound.size())
    throw InputError("friction.pressure", "the table needs two or more pressures and as many bounds");
  for (std::size_t i = 0; i < pressure.size(); ++i) {
    if (i > 0 && !(pressure[i] > pressure[i - 1]))
      throw InputError("friction.pressure", "pressures must increase strictly");
    if (!(bound[i] >= 0.0)) throw InputError("friction.bound", "bounds must be non-negative");
  }
  FrictionLaw law;
  law.kind_ = Kind::table;
  law.p_ = std::move(pressure);
  law.f_ = std::move(bound);
  return law;
}

FrictionLaw FrictionLaw::from_spec(const FrictionSpec& spec) {
  switch (spec.law) {
    case Kind::coulomb: return coulomb(spec.mu);
    case Kind::tresca: return tresca(spec.bound);
    case Kind::table: return table(spec.pressure, spec.bound_table);
  }
  throw InputError("friction.law", "unknown law (coulomb, tresca, table)");
}

double FrictionLaw::bound(double p) const {
  if (!(p > 0.0)) return 0.0;
  switch (kind_) {
    case Kind::coulomb: return mu_ * p;
    case Kind::tresca: return tresca_;
    case Kind::table: {
      // Piecewise linear; constant beyond the last point, linear from (0, 0) before the first.
      if (p >= p_.back()) return f_.back();
      if (p <= p_.front()) return p_.front() > 0.0 ? f_.front() * p / p_.front() : f_.front();
      const auto it = std::upper_bound(p_.begin(), p_.end(), p);
      const std::size_t k = static_cast<std::size_t>(it - p_.begin());
      const double t = (p - p_[k - 1]) / (p_[k] - p_[k - 1]);
      return f_[k - 1] + t * (f_[k] - f_[k - 1]);
    }
  }
  return 0.0;
}

double FrictionLaw::max_slope() const {
  switch (kind_) {
    case Kind::coulomb: return mu_;
    case Kind::tresca: return 0.0;
    case Kind::table: {
      double s = p_.front() > 0.0 ? std::abs(f_.front() / p_.front()) : 0.0;
      for (std::size_t k = 1; k < p_.size(); ++k) s = std::max(s, std::abs((f_[k] - f_[k - 1]) / (p_[k] - p_[k - 1])));
      return s;
    }
  }
  return 0.0;
}

std::string FrictionLaw::name() const { return to_string(kind_); }

const char* to_string(FrictionLawKind law) {
  switch (law) {
    case FrictionLawKind::coulomb: return "coulomb";
    case FrictionLawKind::tresca: return "tresca";
    case FrictionLawKind::table: return "table";
  }
  return "unknown";
}

}  // namespace dc
