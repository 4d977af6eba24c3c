#pragma once
// The body's mesh: quadratic tetrahedra with straight edges, a region (material index) each.
#include <array>
#include <string>
#include <vector>

#include <Eigen/Dense>

namespace dc::fe {

struct BodyMesh {
  std::vector<Eigen::Vector3d> nodes;  ///< straight-edged: mid-edge nodes at the edge midpoints
  /// The nodes on the true geometry: mid-edge nodes where the mesher curved them (Gmsh's
  /// second-order nodes), else as `nodes`. The contact face's heights (the initial gap) come
  /// from these, so a curved face is not seen as facets; the stiffness uses `nodes`.
  std::vector<Eigen::Vector3d> surface;
  std::vector<std::array<int, 10>> elements;  ///< tet10 node indices (see tet10.hpp ordering)
  std::vector<int> region;                    ///< material index per element

  std::size_t dofs() const { return 3 * nodes.size(); }
};

/// Builds the quadratic mesh from linear tetrahedra: mid-edge nodes shared between elements.
/// `curved` (optional, one entry per tetrahedron): the six mid-edge points of a second-order
/// mesh in any order, matched to the edges by distance, kept in BodyMesh::surface. Throws
/// InputError(key) for an empty mesh, a degenerate (zero volume) or an inverted element (the
/// other handedness than the mesh's).
BodyMesh quadratic_mesh_from_linear(const std::vector<Eigen::Vector3d>& vertices,
                                    const std::vector<std::array<int, 4>>& tets, const std::string& key,
                                    const std::vector<std::array<Eigen::Vector3d, 6>>* curved = nullptr);

}  // namespace dc::fe
