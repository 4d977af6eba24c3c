#include "contact_face.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <map>

#include "errors.hpp"
#include "tet10.hpp"

namespace dc::fe {

namespace {

/// A boundary face of a tet10 looking down: corners, then the mid-edge nodes of (0,1), (1,2), (2,0).
struct FaceTriangle {
  std::array<int, 6> nodes{};
  std::array<Eigen::Vector3d, 3> corners;
};

/// The 6-node triangle's shape functions at barycentric coordinates l.
std::array<double, 6> triangle6_shape(const std::array<double, 3>& l) {
  return {l[0] * (2 * l[0] - 1), l[1] * (2 * l[1] - 1), l[2] * (2 * l[2] - 1),
          4 * l[0] * l[1],       4 * l[1] * l[2],       4 * l[2] * l[0]};
}

int mid_node_of(const std::array<int, 10>& el, int a, int b) {
  for (int e = 0; e < 6; ++e) {
    const int p = kTetEdges[e][0], q = kTetEdges[e][1];
    if ((p == a && q == b) || (p == b && q == a)) return el[4 + e];
  }
  return -1;
}

/// Boundary faces (seen by one element only) whose outward normal points down.
std::vector<FaceTriangle> downward_faces(const BodyMesh& mesh) {
  static constexpr int kFaces[4][4] = {{1, 2, 3, 0}, {0, 2, 3, 1}, {0, 1, 3, 2}, {0, 1, 2, 3}};  // face, opposite
  std::map<std::array<int, 3>, std::pair<int, std::pair<std::size_t, int>>> seen;  // count, (element, face)
  for (std::size_t e = 0; e < mesh.elements.size(); ++e)
    for (int f = 0; f < 4; ++f) {
      std::array<int, 3> key{mesh.elements[e][kFaces[f][0]], mesh.elements[e][kFaces[f][1]],
                             mesh.elements[e][kFaces[f][2]]};
      std::sort(key.begin(), key.end());
      auto& entry = seen[key];
      entry.first += 1;
      entry.second = {e, f};
    }
  std::vector<FaceTriangle> out;
  for (const auto& [key, entry] : seen) {
    if (entry.first != 1) continue;
    const auto& el = mesh.elements[entry.second.first];
    const int* f = kFaces[entry.second.second];
    std::array<int, 3> c{f[0], f[1], f[2]};
    const Eigen::Vector3d &a = mesh.nodes[el[c[0]]], &b = mesh.nodes[el[c[1]]], &d = mesh.nodes[el[c[2]]];
    Eigen::Vector3d n = (b - a).cross(d - a);
    if (n.dot(mesh.nodes[el[f[3]]] - a) > 0.0) {
      n = -n;
      std::swap(c[1], c[2]);
    }
    if (!(n.z() < -1e-3 * n.norm())) continue;
    FaceTriangle t;
    for (int i = 0; i < 3; ++i) {
      t.nodes[i] = el[c[i]];
      t.corners[i] = mesh.nodes[el[c[i]]];
      t.nodes[3 + i] = mid_node_of(el, c[i], c[(i + 1) % 3]);
    }
    out.push_back(t);
  }
  return out;
}

/// Barycentric coordinates of (x, y) in the triangle's projection on the plane.
std::array<double, 3> projected_barycentric(const FaceTriangle& t, double x, double y) {
  const Eigen::Vector3d &a = t.corners[0], &b = t.corners[1], &c = t.corners[2];
  const double det = (b.x() - a.x()) * (c.y() - a.y()) - (c.x() - a.x()) * (b.y() - a.y());
  const double l1 = ((x - a.x()) * (c.y() - a.y()) - (c.x() - a.x()) * (y - a.y())) / det;
  const double l2 = ((b.x() - a.x()) * (y - a.y()) - (x - a.x()) * (b.y() - a.y())) / det;
  return {1.0 - l1 - l2, l1, l2};
}

double mean_edge_length(const FaceTriangle& t) {
  const auto& c = t.corners;
  return ((c[1] - c[0]).norm() + (c[2] - c[1]).norm() + (c[0] - c[2]).norm()) / 3.0;
}

}  // namespace

ContactFace::ContactFace(const BodyMesh& mesh, const Grid& grid, int samples) : grid_(grid) {
  if (grid.dimension != 3) throw InputError("grid.dimension", "a finite-element body needs a 3-D grid");
  const std::vector<FaceTriangle> faces = downward_faces(mesh);
  n_triangles_ = faces.size();
  lowest_z_ = std::numeric_limits<double>::infinity();
  for (const auto& t : faces)
    for (int i = 0; i < 6; ++i) lowest_z_ = std::min(lowest_z_, mesh.surface[t.nodes[i]].z());

  // Faces listed by the grid elements their projection's bounding box meets.
  const std::size_t N = grid.size();
  std::vector<std::vector<int>> bucket(N);
  for (std::size_t f = 0; f < faces.size(); ++f) {
    double x0 = faces[f].corners[0].x(), x1 = x0, y0 = faces[f].corners[0].y(), y1 = y0;
    for (const auto& c : faces[f].corners) {
      x0 = std::min(x0, c.x()); x1 = std::max(x1, c.x());
      y0 = std::min(y0, c.y()); y1 = std::max(y1, c.y());
    }
    const int i0 = std::max(0, static_cast<int>(std::floor((x0 - grid.x0) / grid.dx)));
    const int i1 = std::min(grid.nx - 1, static_cast<int>(std::floor((x1 - grid.x0) / grid.dx)));
    const int j0 = std::max(0, static_cast<int>(std::floor((y0 - grid.y0) / grid.dy)));
    const int j1 = std::min(grid.ny - 1, static_cast<int>(std::floor((y1 - grid.y0) / grid.dy)));
    for (int j = j0; j <= j1; ++j)
      for (int i = i0; i <= i1; ++i) bucket[grid.index(i, j)].push_back(static_cast<int>(f));
  }

  // The face point over (x, y): the lowest face containing it; false when none.
  auto locate = [&](std::size_t k, double x, double y, int& face, std::array<double, 3>& l) {
    double best_z = std::numeric_limits<double>::infinity();
    face = -1;
    for (int f : bucket[k]) {
      const auto b = projected_barycentric(faces[f], x, y);
      if (std::min({b[0], b[1], b[2]}) < -1e-10) continue;
      const auto N6 = triangle6_shape(b);
      double z = 0.0;
      for (int i = 0; i < 6; ++i) z += N6[i] * mesh.surface[faces[f].nodes[i]].z();
      if (z < best_z) {
        best_z = z;
        face = f;
        l = b;
      }
    }
    return face >= 0 ? best_z : std::numeric_limits<double>::infinity();
  };

  heights_.assign(N, std::numeric_limits<double>::infinity());
  face_sizes_.assign(N, 0.0);
  std::vector<Eigen::Triplet<double>> entries;
  const double w = grid.area() / (samples * samples);
  bool any = false;
  for (int j = 0; j < grid.ny; ++j)
    for (int i = 0; i < grid.nx; ++i) {
      const std::size_t k = grid.index(i, j);
      if (bucket[k].empty()) continue;
      int face = -1;
      std::array<double, 3> l{};
      const double zc = locate(k, grid.xc(i), grid.yc(j), face, l);
      if (face >= 0) {
        heights_[k] = zc - lowest_z_;
        face_sizes_[k] = mean_edge_length(faces[face]);
        any = true;
      }
      for (int sj = 0; sj < samples; ++sj)
        for (int si = 0; si < samples; ++si) {
          const double x = grid.x0 + (i + (si + 0.5) / samples) * grid.dx;
          const double y = grid.y0 + (j + (sj + 0.5) / samples) * grid.dy;
          if (!std::isfinite(locate(k, x, y, face, l))) continue;
          const auto N6 = triangle6_shape(l);
          for (int n = 0; n < 6; ++n)
            entries.emplace_back(static_cast<int>(k), faces[face].nodes[n], w * N6[n]);
        }
    }
  if (!any)
    throw InputError("fe_body", "no face of the body looks down over the contact grid (move the grid under the body)");
  Bt_.resize(static_cast<Eigen::Index>(N), static_cast<Eigen::Index>(mesh.nodes.size()));
  Bt_.setFromTriplets(entries.begin(), entries.end());
}

void ContactFace::add_forces(const double* traction, int component, double scale, Eigen::VectorXd& F) const {
  for (Eigen::Index k = 0; k < Bt_.outerSize(); ++k) {
    const double t = scale * traction[k];
    if (t == 0.0) continue;
    for (Eigen::SparseMatrix<double, Eigen::RowMajor>::InnerIterator it(Bt_, k); it; ++it)
      F(3 * it.col() + component) += it.value() * t;
  }
}

void ContactFace::mean_displacement(const Eigen::VectorXd& u, int component, double* w) const {
  const double inv_area = 1.0 / grid_.area();
  for (Eigen::Index k = 0; k < Bt_.outerSize(); ++k) {
    double s = 0.0;
    for (Eigen::SparseMatrix<double, Eigen::RowMajor>::InnerIterator it(Bt_, k); it; ++it)
      s += it.value() * u(3 * it.col() + component);
    w[k] = s * inv_area;
  }
}

}  // namespace dc::fe
