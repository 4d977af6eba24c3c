// The "friction" block (CASES.md): Coulomb, Tresca or a table f(p), into FrictionSpec
// (core/friction_law.hpp).
#include "case_readers.hpp"

#include <cmath>
#include <string>

#include "errors.hpp"
#include "json_block.hpp"

namespace dc {

using namespace case_json;

FrictionSpec read_friction(const json& j) {
  JsonBlock o(j, "friction");
  FrictionSpec f;
  const std::string law = o.choice("law", "", {"coulomb", "tresca", "table"});
  f.law = law == "coulomb"  ? FrictionLawKind::coulomb
          : law == "tresca" ? FrictionLawKind::tresca
                            : FrictionLawKind::table;
  if (f.law == FrictionLawKind::coulomb) {
    o.allow({"law", "mu"});
    f.mu = o.number("mu");
    if (std::abs(f.mu) > 1e3) throw InputError(o.key("mu"), "must be at most 1000, got " + fmt(f.mu));
    if (f.mu < 0.0) throw InputError("friction.mu", "mu must be non-negative, got " + fmt(f.mu));
  } else if (f.law == FrictionLawKind::tresca) {
    o.allow({"law", "bound"});
    f.bound = o.positive_at_most("bound", 1e15, "Pa");
  } else {
    o.allow({"law", "pressure", "bound"});
    f.pressure = o.numbers("pressure");
    f.bound_table = o.numbers("bound");
    if (f.pressure.size() < 2) throw InputError("friction.pressure", "needs at least two values");
    if (f.bound_table.size() != f.pressure.size())
      throw InputError("friction.bound", "must have as many values as friction.pressure (" +
                                             std::to_string(f.pressure.size()) + "), got " +
                                             std::to_string(f.bound_table.size()));
    for (std::size_t i = 0; i < f.pressure.size(); ++i) {
      if (f.pressure[i] < 0.0) throw InputError("friction.pressure", "pressures must be non-negative");
      if (i > 0 && !(f.pressure[i] > f.pressure[i - 1]))
        throw InputError("friction.pressure", "pressures must be strictly increasing");
      if (f.bound_table[i] < 0.0) throw InputError("friction.bound", "bounds must be non-negative");
    }
  }
  return f;
}

}  // namespace dc
