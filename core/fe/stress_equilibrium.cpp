#include "stress_equilibrium.hpp"

#include <cmath>

namespace dc::fe {

StressEquilibrium stress_equilibrium(const ElasticBody& body) {
  const BodyMesh& mesh = body.mesh();
  const std::size_t ne = mesh.elements.size();
  StressEquilibrium out;
  out.compliance.reserve(4 * ne);
  out.root_weight.reserve(4 * ne);
  std::vector<Eigen::Triplet<double>> triplets;
  triplets.reserve(ne * 4 * 6 * 30);
  for (std::size_t e = 0; e < ne; ++e) {
    const Eigen::Matrix<double, 6, 6> S = body.element_stiffness(e).inverse();
    const auto& nodes = mesh.elements[e];
    for (const auto& point : tet10_strain_points(body.element_nodes(e))) {
      const auto column = static_cast<int>(out.stresses());
      out.compliance.push_back(S);
      out.root_weight.push_back(std::sqrt(point.weight));
      for (int a = 0; a < 10; ++a)
        for (int i = 0; i < 3; ++i)
          for (int k = 0; k < 6; ++k) {
            const double value = out.root_weight.back() * point.B(k, 3 * a + i);
            if (value != 0.0) triplets.emplace_back(3 * nodes[a] + i, column + k, value);
          }
    }
  }
  out.forces.resize(static_cast<Eigen::Index>(body.dofs()), static_cast<Eigen::Index>(out.stresses()));
  out.forces.setFromTriplets(triplets.begin(), triplets.end());
  return out;
}

}  // namespace dc::fe
