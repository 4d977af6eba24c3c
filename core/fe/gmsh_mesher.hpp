#pragma once
// Meshes of the body through Gmsh's C++ API: the generated shapes (block, cylinder flat end
// down, hemisphere curved face down), refined towards the lowest point where contact starts,
// or any Gmsh file of tetrahedra. Errors name the fe_body key.
#include "body_mesh.hpp"
#include "fe_body_spec.hpp"

namespace dc::fe {

/// The body's quadratic mesh with the regions of `spec` assigned; the lowest point of a
/// generated shape is the origin.
BodyMesh mesh_body(const FeBodySpec& spec);

}  // namespace dc::fe
