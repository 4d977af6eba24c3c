#include "body_mesh.hpp"

#include <algorithm>
#include <cstdint>
#include <unordered_map>

#include "errors.hpp"
#include "tet10.hpp"

namespace dc::fe {

namespace {
/// The point of `candidates` nearest to `p`.
Eigen::Vector3d nearest(const std::array<Eigen::Vector3d, 6>& candidates, const Eigen::Vector3d& p) {
  std::size_t best = 0;
  for (std::size_t i = 1; i < candidates.size(); ++i)
    if ((candidates[i] - p).squaredNorm() < (candidates[best] - p).squaredNorm()) best = i;
  return candidates[best];
}
}  // namespace

BodyMesh quadratic_mesh_from_linear(const std::vector<Eigen::Vector3d>& all_vertices,
                                    const std::vector<std::array<int, 4>>& all_tets, const std::string& key,
                                    const std::vector<std::array<Eigen::Vector3d, 6>>* curved) {
  if (all_tets.empty()) throw InputError(key, "the mesh has no tetrahedra");
  // Only the vertices of tetrahedra are nodes (a file may hold geometry points besides).
  std::vector<int> renumber(all_vertices.size(), -1);
  std::vector<Eigen::Vector3d> vertices;
  std::vector<std::array<int, 4>> tets = all_tets;
  for (auto& t : tets)
    for (int& v : t) {
      if (v < 0 || static_cast<std::size_t>(v) >= all_vertices.size())
        throw InputError(key, "an element refers to a missing node");
      if (renumber[v] < 0) {
        renumber[v] = static_cast<int>(vertices.size());
        vertices.push_back(all_vertices[v]);
      }
      v = renumber[v];
    }
  BodyMesh mesh;
  mesh.nodes = vertices;
  mesh.elements.reserve(tets.size());
  mesh.region.assign(tets.size(), 0);
  // Extent of the mesh: volumes below eps * extent^3 are degenerate.
  Eigen::Vector3d lo = vertices.front(), hi = vertices.front();
  for (const auto& v : vertices) {
    lo = lo.cwiseMin(v);
    hi = hi.cwiseMax(v);
  }
  const double extent = (hi - lo).maxCoeff();
  // Orientation: a mesh is written with one handedness; an element of the other is inverted
  // (folded over its neighbours), which is an error, not something to repair.
  auto volume_of = [&](const std::array<int, 4>& t) {
    TetNodes x = TetNodes::Zero();
    for (int i = 0; i < 4; ++i) x.col(i) = vertices.at(static_cast<std::size_t>(t[i]));
    return tet_volume(x);
  };
  std::size_t n_negative = 0;
  for (const auto& t : tets) n_negative += volume_of(t) < 0.0 ? 1 : 0;
  const bool flip_all = 2 * n_negative > tets.size();
  mesh.surface = vertices;
  std::unordered_map<std::uint64_t, int> mid_node;
  const auto n_vertices = static_cast<std::uint64_t>(vertices.size());
  for (std::size_t e = 0; e < tets.size(); ++e) {
    std::array<int, 4> t = tets[e];
    const double V = volume_of(t);
    if (!(std::abs(V) > 1e-12 * extent * extent * extent))
      throw InputError(key, "element " + std::to_string(e) + " is degenerate (zero volume): the mesh is invalid");
    if ((V < 0.0) != flip_all)
      throw InputError(key, "element " + std::to_string(e) + " is inverted (its orientation differs from the mesh's)");
    if (flip_all) std::swap(t[1], t[2]);  // the file's handedness: the same tetrahedron
    std::array<int, 10> q{};
    for (int i = 0; i < 4; ++i) q[i] = t[i];
    for (int k = 0; k < 6; ++k) {
      const auto a = static_cast<std::uint64_t>(std::min(t[kTetEdges[k][0]], t[kTetEdges[k][1]]));
      const auto b = static_cast<std::uint64_t>(std::max(t[kTetEdges[k][0]], t[kTetEdges[k][1]]));
      const auto [it, inserted] = mid_node.try_emplace(a * n_vertices + b, static_cast<int>(mesh.nodes.size()));
      if (inserted) {
        const Eigen::Vector3d mid = 0.5 * (vertices[a] + vertices[b]);
        mesh.nodes.push_back(mid);
        mesh.surface.push_back(curved ? nearest((*curved)[e], mid) : mid);
      }
      q[4 + k] = it->second;
    }
    mesh.elements.push_back(q);
  }
  return mesh;
}

}  // namespace dc::fe
