#pragma once
// Small hand-made meshes for the element tests: a box of n^3 cubes, six tetrahedra each.
#include <array>
#include <vector>

#include "body_mesh.hpp"

namespace dc::fe::testing {

inline BodyMesh box_mesh(int n, double lx, double ly, double lz) {
  std::vector<Eigen::Vector3d> v;
  auto id = [n](int i, int j, int k) { return i + (n + 1) * (j + (n + 1) * k); };
  for (int k = 0; k <= n; ++k)
    for (int j = 0; j <= n; ++j)
      for (int i = 0; i <= n; ++i) v.emplace_back(lx * i / n, ly * j / n, lz * k / n);
  std::vector<std::array<int, 4>> tets;
  for (int k = 0; k < n; ++k)
    for (int j = 0; j < n; ++j)
      for (int i = 0; i < n; ++i) {
        const int c[8] = {id(i, j, k),         id(i + 1, j, k),         id(i + 1, j + 1, k),
                          id(i, j + 1, k),     id(i, j, k + 1),         id(i + 1, j, k + 1),
                          id(i + 1, j + 1, k + 1), id(i, j + 1, k + 1)};
        // Six tetrahedra around the diagonal 0-6 (Kuhn triangulation: conforming).
        const int paths[6][2] = {{1, 2}, {2, 3}, {3, 7}, {7, 4}, {4, 5}, {5, 1}};
        for (const auto& p : paths) {
          std::array<int, 4> t{c[0], c[p[0]], c[p[1]], c[6]};
          tets.push_back(t);
        }
      }
  // Orientation: make every element positive (the Kuhn cells alternate handedness).
  for (auto& t : tets) {
    const Eigen::Vector3d a = v[t[1]] - v[t[0]], b = v[t[2]] - v[t[0]], c = v[t[3]] - v[t[0]];
    if (a.dot(b.cross(c)) < 0.0) std::swap(t[1], t[2]);
  }
  return quadratic_mesh_from_linear(v, tets, "test");
}

}  // namespace dc::fe::testing
