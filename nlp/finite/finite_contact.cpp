#include "finite_contact.hpp"

#include <chrono>

#include "body_compliance.hpp"
#include "gmsh_mesher.hpp"

namespace dc {

FiniteContact::FiniteContact(const FeBodySpec& spec, const Grid& grid, const Elastic& halfspace, OperatorKind kind)
    : grid_(grid) {
  const auto start = std::chrono::steady_clock::now();
  fe::BodyMesh mesh = fe::mesh_body(spec);
  mesh_seconds_ = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  std::vector<fe::BodyMaterial> materials{spec.material};
  for (const auto& r : spec.regions) materials.push_back(r.material);
  face_ = std::make_unique<fe::ContactFace>(mesh, grid_);
  body_ = std::make_unique<fe::ElasticBody>(std::move(mesh), std::move(materials));
  // The half-space alone: the body's compliance is the mesh's.
  const MaterialPair pair{Elastic::make_rigid(), halfspace};
  const HalfSpace half_space(grid_, pair);
  std::shared_ptr<const LinearOperator> hs(half_space.normal(kind));
  halfspace_tangential_ = std::shared_ptr<const LinearOperator>(half_space.tangential(kind));
  body_normal_ = std::make_shared<BodyCompliance>(*body_, *face_, grid_, std::vector<int>{2});
  normal_compliance_ = std::make_shared<SumOperator>(hs, body_normal_);
  normal_ = std::make_unique<NormalProblem>(normal_compliance_, grid_, face_->heights());
}

FiniteNormalSolution FiniteContact::solve_normal(const NormalSpec& control, const SolverSpec& solver,
                                                 const ProgressCallback& progress) {
  FiniteNormalSolution out;
  out.contact = normal_->solve(control, solver, progress);
  body_normal_->displacement(out.contact.pressure.data(), out.body_displacement);
  out.max_body_displacement = 0.0;
  for (Eigen::Index k = 0; k + 2 < out.body_displacement.size(); k += 3)
    out.max_body_displacement = std::max(out.max_body_displacement, out.body_displacement.segment<3>(k).norm());
  return out;
}

TangentialProblem& FiniteContact::tangential_problem(const FrictionLaw& friction) {
  if (!tangential_) {
    auto body_t = std::make_shared<BodyCompliance>(*body_, *face_, grid_, std::vector<int>{0, 1});
    auto Ct = std::make_shared<SumOperator>(halfspace_tangential_, body_t);
    tangential_ = std::make_unique<TangentialProblem>(grid_, normal_compliance_, Ct, face_->heights(), friction);
  }
  return *tangential_;
}

Eigen::VectorXd FiniteContact::body_displacement(const std::vector<double>& tx, const std::vector<double>& ty,
                                                 const std::vector<double>& p) const {
  const std::size_t N = grid_.size();
  std::vector<double> t(3 * N, 0.0);
  std::copy(tx.begin(), tx.end(), t.begin());
  std::copy(ty.begin(), ty.end(), t.begin() + static_cast<std::ptrdiff_t>(N));
  std::copy(p.begin(), p.end(), t.begin() + static_cast<std::ptrdiff_t>(2 * N));
  const BodyCompliance all(*body_, *face_, grid_, {0, 1, 2});
  Eigen::VectorXd u;
  all.displacement(t.data(), u);
  return u;
}

}  // namespace dc
