#pragma once
// The "shakedown" block of a static run (CASES.md): Melan's static theorem for the solved load
// rolling (or sliding) along x over the base, as the convex program of nlp/shakedown_problem.hpp
// (2-D) or nlp/shakedown_3d.hpp (3-D). The history of a material point is the base's field along
// x at its depth (2-D) or its (y, depth) over every line of the grid (3-D: the load is
// translation-invariant); the residual stresses are rho_xx(z) and rho_yy(z) in 2-D, rho(y, z)
// of shakedown_3d.hpp in 3-D; the yield criterion is the base's (von Mises Y; Tresca k in the x-z
// plane in 2-D, through its inscribed cone sqrt(J2) <= k in 3-D). Reported: the limit load factor on
// the elastic field, the elastic limit, the verdict, and the point on Johnson's shakedown map.
#include <nlohmann/json.hpp>

#include "case_model.hpp"
#include "subsurface_run.hpp"

namespace dc::runs {

/// summary.json's "shakedown" from the base's field in `field` and the run's summary `s`
/// (max_pressure, normal_force, tangential_force); status "optimal" when certified.
nlohmann::json shakedown_json(const Case& c, const SubsurfaceRun& field, const nlohmann::json& s);

}  // namespace dc::runs
