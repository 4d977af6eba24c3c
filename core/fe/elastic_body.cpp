#include "elastic_body.hpp"

#include <chrono>
#include <cmath>

#include <Eigen/CholmodSupport>

#include "errors.hpp"
#include "interrupt.hpp"
#include "tet10.hpp"

namespace dc::fe {

struct ElasticBody::Factor {
  Eigen::CholmodSupernodalLLT<Eigen::SparseMatrix<double>, Eigen::Lower> llt;
};

TetNodes ElasticBody::element_nodes(std::size_t e) const {
  TetNodes x;
  for (int i = 0; i < 10; ++i) x.col(i) = mesh_.nodes[mesh_.elements[e][i]];
  return x;
}

ElasticBody::ElasticBody(BodyMesh mesh, std::vector<BodyMaterial> materials)
    : mesh_(std::move(mesh)), materials_(std::move(materials)) {
  for (int r : mesh_.region)
    if (r < 0 || static_cast<std::size_t>(r) >= materials_.size())
      throw InputError("fe_body", "an element's region has no material");
  for (const auto& m : materials_)
    if (!(m.density > 0.0)) throw InputError("fe_body.density", "must be positive");
  assemble();
  choose_supports();
  factorise();
}

ElasticBody::~ElasticBody() = default;

void ElasticBody::assemble() {
  const std::size_t ne = mesh_.elements.size();
  // Mass and centre of mass first (the rigid rotations are taken about it).
  Eigen::Vector3d moment = Eigen::Vector3d::Zero();
  for (std::size_t e = 0; e < ne; ++e) {
    const TetNodes x = element_nodes(e);
    const double m = materials_[mesh_.region[e]].density * tet_volume(x);
    mass_ += m;
    moment += m * 0.25 * (x.col(0) + x.col(1) + x.col(2) + x.col(3));
  }
  centre_ = moment / mass_;

  const auto n = static_cast<Eigen::Index>(dofs());
  std::vector<Eigen::Triplet<double>> triplets;
  triplets.reserve(ne * 30 * 30);
  MR_ = Eigen::MatrixXd::Zero(n, 6);
  for (std::size_t e = 0; e < ne; ++e) {
    const TetNodes x = element_nodes(e);
    const BodyMaterial& mat = materials_[mesh_.region[e]];
    const Tet10Matrix Ke = tet10_stiffness(x, mat.C);
    const Eigen::Matrix<double, 30, 6> Le = tet10_rigid_mode_loads(x, mat.density, centre_);
    const auto& nodes = mesh_.elements[e];
    for (int a = 0; a < 10; ++a)
      for (int i = 0; i < 3; ++i) {
        const int row = 3 * nodes[a] + i;
        MR_.row(row) += Le.row(3 * a + i);
        for (int b = 0; b < 10; ++b)
          for (int j = 0; j < 3; ++j) {
            const int col = 3 * nodes[b] + j;
            if (col <= row) triplets.emplace_back(row, col, Ke(3 * a + i, 3 * b + j));  // lower half
          }
      }
  }
  K_.resize(n, n);
  K_.setFromTriplets(triplets.begin(), triplets.end());
  R_.resize(n, 6);
  for (std::size_t k = 0; k < mesh_.nodes.size(); ++k)
    R_.block(3 * static_cast<Eigen::Index>(k), 0, 3, 6) = rigid_modes_at(mesh_.nodes[k], centre_);
  RMR_ = R_.transpose() * MR_;
  RMR_inv_ = RMR_.inverse();
}

void ElasticBody::choose_supports() {
  // Three far-apart nodes a, b, c: a holds x, y, z; b the two components least along ab;
  // c the component most along the normal of abc. Checked: the six held dofs see every rigid mode.
  const auto& X = mesh_.nodes;
  std::size_t a = 0, b = 0, c = 0;
  for (std::size_t k = 0; k < X.size(); ++k)
    if ((X[k] - centre_).norm() > (X[a] - centre_).norm()) a = k;
  for (std::size_t k = 0; k < X.size(); ++k)
    if ((X[k] - X[a]).norm() > (X[b] - X[a]).norm()) b = k;
  const Eigen::Vector3d ab = (X[b] - X[a]).normalized();
  for (std::size_t k = 0; k < X.size(); ++k) {
    const Eigen::Vector3d r = X[k] - X[a], rc = X[c] - X[a];
    if ((r - r.dot(ab) * ab).norm() > (rc - rc.dot(ab) * ab).norm()) c = k;
  }
  int along = 0;
  ab.cwiseAbs().maxCoeff(&along);
  int normal_axis = 0;
  ab.cross(X[c] - X[a]).cwiseAbs().maxCoeff(&normal_axis);
  supports_ = {static_cast<int>(3 * a), static_cast<int>(3 * a + 1), static_cast<int>(3 * a + 2)};
  for (int i = 0; i < 3; ++i)
    if (i != along) supports_.push_back(static_cast<int>(3 * b + i));
  supports_.push_back(static_cast<int>(3 * c + normal_axis));
  Eigen::Matrix<double, 6, 6> S;
  for (int i = 0; i < 6; ++i) S.row(i) = R_.row(supports_[i]);
  const Eigen::JacobiSVD<Eigen::Matrix<double, 6, 6>> svd(S);
  const double cond = svd.singularValues()(0) / svd.singularValues()(5);
  if (!(cond < 1e8)) throw InputError("fe_body", "the body is too thin or flat to support its rigid motion");
}

void ElasticBody::factorise() {
  // Ks: the supported dofs replaced by identity rows and columns (lower half stored).
  Ks_ = K_;
  Eigen::SparseMatrix<double>& Ks = Ks_;
  std::vector<char> held(dofs(), 0);
  for (int s : supports_) held[s] = 1;
  double diag_scale = 0.0;
  for (Eigen::Index k = 0; k < Ks.outerSize(); ++k)
    for (Eigen::SparseMatrix<double>::InnerIterator it(Ks, k); it; ++it)
      if (it.row() == it.col()) diag_scale = std::max(diag_scale, it.value());
  for (Eigen::Index k = 0; k < Ks.outerSize(); ++k)
    for (Eigen::SparseMatrix<double>::InnerIterator it(Ks, k); it; ++it)
      if (held[it.row()] || held[it.col()]) it.valueRef() = it.row() == it.col() ? diag_scale : 0.0;
  const auto start = std::chrono::steady_clock::now();
  factor_ = std::make_unique<Factor>();
  {
    const NonPollingSection section("factorising the body's stiffness (CHOLMOD)");
    factor_->llt.compute(Ks);
  }
  factor_seconds_ = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  if (factor_->llt.info() != Eigen::Success)
    throw InputError("fe_body", "the stiffness is singular: the mesh is not one connected solid");
}

void ElasticBody::deform(const Eigen::VectorXd& F, Eigen::VectorXd& u) const {
  // P F = F - M R (R'MR)^-1 R'F: the resultant balanced by rigid-body inertia.
  const Eigen::Matrix<double, 6, 1> a = RMR_inv_ * (R_.transpose() * F);
  work_ = F - MR_ * a;
  for (int s : supports_) work_(s) = 0.0;
  u = factor_->llt.solve(work_);
  // P'u = u - R (R'MR)^-1 (MR)'u: no mean rigid motion.
  const Eigen::Matrix<double, 6, 1> r = RMR_inv_ * (MR_.transpose() * u);
  u.noalias() -= R_ * r;
}

void ElasticBody::deform_columns(const Eigen::MatrixXd& F, Eigen::MatrixXd& u) const {
  // deform() column by column: P F, the supported solve, P'u.
  const Eigen::MatrixXd a = RMR_inv_ * (R_.transpose() * F);
  Eigen::MatrixXd balanced = F - MR_ * a;
  for (int s : supports_) balanced.row(s).setZero();
  u = factor_->llt.solve(balanced);
  const Eigen::MatrixXd r = RMR_inv_ * (MR_.transpose() * u);
  u.noalias() -= R_ * r;
}

std::vector<Eigen::Matrix<double, 6, 1>> ElasticBody::element_stress(const Eigen::VectorXd& u) const {
  std::vector<Eigen::Matrix<double, 6, 1>> out(mesh_.elements.size());
  for (std::size_t e = 0; e < mesh_.elements.size(); ++e) {
    const TetNodes x = element_nodes(e);
    Tet10Vector ue;
    for (int a = 0; a < 10; ++a) ue.segment<3>(3 * a) = u.segment<3>(3 * mesh_.elements[e][a]);
    out[e] = materials_[mesh_.region[e]].C * tet10_strain(x, Eigen::Vector4d::Constant(0.25)) * ue;
  }
  return out;
}

}  // namespace dc::fe
