#pragma once
// The size of an fe_body before it is meshed (`validate`, and the refusal of a body the machine
// cannot hold): tetrahedra from the mesh size field (core/fe_body_spec.hpp: the contact element
// size over the grid's disk, growing at kFaceSizeGrowth to the coarse size), dofs, the sparse
// factor's memory and the solve's time, calibrated on Gmsh meshes of hemispheres (docs/limits.md).
#include <optional>
#include <string>

#include "case_model.hpp"
#include "resource_estimate.hpp"  // available_memory_bytes

namespace dc::runs {

struct FeBodyEstimate {
  double tetrahedra = 0.0;
  double dofs = 0.0;           ///< 3 per node of the quadratic tetrahedra
  double memory_bytes = 0.0;   ///< peak of the whole run (the factor dominates)
  double seconds = 0.0;        ///< meshing, factorisation and the contact solve, one thread
  double refined_share = 0.0;  ///< of the tetrahedra, in the refined zone about the contact
  /// The key to reduce when the body is too large: fe_body.contact_size when the refined zone
  /// holds most tetrahedra, else fe_body.elements.
  std::string key;
};

/// None for a body given as a mesh file (its size is the file's) or a case without an fe_body.
std::optional<FeBodyEstimate> estimate_fe_body(const Case& c);

/// Throws InputError naming the estimate's key when the body's estimated memory exceeds what is
/// available (the message gives both, and what to reduce).
void check_fe_body_fits(const Case& c);

}  // namespace dc::runs
