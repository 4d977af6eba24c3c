#pragma once
// The "shakedown" block of a 2-D static run (CASES.md): Melan's static theorem for the solved
// load rolling (or sliding) over the base, as the convex program of nlp/shakedown_problem.hpp.
// The history of a material point is the base's field along x at each depth (the load is
// translation-invariant); the residual stresses are rho_xx(z) and rho_yy(z); the yield criterion
// is the base's (von Mises Y, or Tresca k in the x-z plane). Reported: the limit load factor on
// the elastic field, the elastic limit, the verdict, and the point on Johnson's shakedown map.
#include <nlohmann/json.hpp>

#include "case_model.hpp"
#include "subsurface_run.hpp"

namespace dc::runs {

/// summary.json's "shakedown" from the base's field in `field` and the run's summary `s`
/// (max_pressure, normal_force, tangential_force); status "optimal" when certified.
nlohmann::json shakedown_json(const Case& c, const SubsurfaceRun& field, const nlohmann::json& s);

}  // namespace dc::runs
