#pragma once
// Rolling-contact fatigue of a static run (CASES.md "fatigue"): the solved load rolled along x
// over each body with materials.<body>.fatigue. A material point at (y, depth) then sees the
// field along x as its stress history (the load is translation-invariant); on that path Dang
// Van's criterion (core/dang_van.hpp: the smallest ball enclosing the deviatoric path, the
// mesoscopic shear plus alpha times the hydrostatic stress, against beta) gives the fatigue
// index, and the range of sigma_xz the classical orthogonal-shear index.
#include <nlohmann/json.hpp>

#include "case_model.hpp"
#include "subsurface_run.hpp"

namespace dc::runs {

/// summary.json's "fatigue": per body dang_van_max (the index, > 1: fatigue predicted), at
/// [x, y, depth] (x where the index peaks along the passage; 2-D [x, depth]), alpha, beta,
/// orthogonal_shear_range (max - min of sigma_xz along the passage, Pa) and at_orthogonal_range.
nlohmann::json fatigue_json(const Case& c, const SubsurfaceRun& field);

}  // namespace dc::runs
