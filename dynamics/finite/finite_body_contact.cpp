#include "finite_body_contact.hpp"

#include <cmath>
#include <limits>

#include "errors.hpp"

namespace dc::dynamics {

FiniteBodyContact::FiniteBodyContact(const DynamicContactSpec& c) : grid_(c.grid), material_(c.fe_body->material) {
  const OperatorKind kind = c.solver.operator_kind == OperatorKind::dense ? OperatorKind::dense : OperatorKind::fft;
  contact_ = std::make_unique<FiniteContact>(*c.fe_body, c.grid, c.materials.base, kind);
  const fe::ElasticBody& body = contact_->body();
  const Eigen::Vector3d& centre = body.centre_of_mass();
  centre_height_ = centre.z() - contact_->face().lowest_z();
  centre_xy_ = centre.head<2>();
  // The rotation columns of M R hold int rho N_a (omega x r) for omega = e_x, e_y, e_z
  // (core/fe/tet10.cpp rigid_modes_at): their components are the first moments.
  const Eigen::MatrixXd& MR = body.mass_rigid_modes();
  const Eigen::Index n = static_cast<Eigen::Index>(body.mesh().nodes.size());
  first_moments_.resize(3, n);
  for (Eigen::Index a = 0; a < n; ++a) {
    first_moments_(0, a) = MR(3 * a + 1, 5);   // (e_z x r)_y = r_x
    first_moments_(1, a) = MR(3 * a + 2, 3);   // (e_x x r)_z = r_y
    first_moments_(2, a) = MR(3 * a, 4);       // (e_y x r)_x = r_z
  }
  heights_ = contact_->face().heights();
  opening_.assign(grid_.size(), 0.0);
  displacement_.setZero(static_cast<Eigen::Index>(body.dofs()));
  load_.setZero(static_cast<Eigen::Index>(body.dofs()));
  traction_.assign(grid_.size(), 0.0);
}

double FiniteBodyContact::plane_modulus() const {
  // Isotropic estimates of the (first region's) constants: mu, lambda from the Voigt matrix's
  // shear and off-diagonal means; E / (1 - nu^2) = 4 mu (lambda + mu) / (lambda + 2 mu).
  const auto& C = material_.C;
  const double mu = (C(3, 3) + C(4, 4) + C(5, 5)) / 3.0, lambda = (C(0, 1) + C(0, 2) + C(1, 2)) / 3.0;
  return 4.0 * mu * (lambda + mu) / (lambda + 2.0 * mu);
}

RigidBody FiniteBodyContact::rigid_body() const {
  // The rotational block of R'M R about the centre of mass is the inertia tensor.
  const Eigen::Matrix3d inertia = contact_->body().rigid_mass().block<3, 3>(3, 3);
  return RigidBody(contact_->body().mass(), 0.5 * (inertia + inertia.transpose()), "fe_body");
}

void FiniteBodyContact::centripetal_load(const Eigen::Vector3d& w, Eigen::VectorXd& F) const {
  // -rho Omega x (Omega x r) = rho (|Omega|^2 I - Omega Omega') r: F_a = S int rho N_a r dV.
  const Eigen::Matrix3d S = w.squaredNorm() * Eigen::Matrix3d::Identity() - w * w.transpose();
  for (Eigen::Index a = 0; a < first_moments_.cols(); ++a) F.segment<3>(3 * a) = S * first_moments_.col(a);
}

bool FiniteBodyContact::update(const StepKinematics& k) {
  // Small rotations: the rotation vector's x, y components are the tilt (about the centre of
  // mass; to first order the approach at (x, y) grows by theta_y x - theta_x y about it).
  const Eigen::AngleAxisd turn(k.orientation);
  const Eigen::Vector3d theta = turn.angle() * turn.axis();
  const double tilt = std::hypot(theta.x(), theta.y());
  if (tilt > kMaxTilt)
    throw InputError("body.initial.omega", "the finite body tilted by " + std::to_string(tilt) + " rad at t = " +
                                               std::to_string(k.time) + " s: shift and torsion only (2.16)");
  const Eigen::Vector3d omega_body = k.orientation.conjugate() * k.omega;
  const std::array<double, 2> tilt_now{theta.x(), theta.y()};
  if (tilt_now == tilt_ && omega_body == omega_body_) return false;
  tilt_ = tilt_now;
  omega_body_ = omega_body;
  spinning_ = omega_body.squaredNorm() > 0.0;
  const std::vector<double>& face = contact_->face().heights();
  if (spinning_) {
    // The centripetal deformation (one pair of triangular solves with the kept factor).
    centripetal_load(omega_body, load_);
    contact_->body().deform(load_, spin_u_);
    contact_->face().mean_displacement(spin_u_, 2, opening_.data());
  } else {
    std::fill(opening_.begin(), opening_.end(), 0.0);
  }
  for (std::size_t e = 0; e < grid_.size(); ++e) {
    const auto i = static_cast<int>(e % grid_.nx), j = static_cast<int>(e / grid_.nx);
    const double x = grid_.xc(i) - centre_xy_.x(), y = grid_.yc(j) - centre_xy_.y();
    heights_[e] = std::isfinite(face[e]) ? face[e] + opening_[e] - tilt_[1] * x + tilt_[0] * y
                                         : std::numeric_limits<double>::infinity();
  }
  return true;
}

void FiniteBodyContact::accept(const std::vector<double>& tx, const std::vector<double>& ty,
                               const std::vector<double>& p) {
  const fe::ContactFace& face = contact_->face();
  load_.setZero();
  if (spinning_) centripetal_load(omega_body_, load_);
  if (!p.empty()) face.add_forces(p.data(), 2, 1.0, load_);
  if (!tx.empty()) face.add_forces(tx.data(), 0, 1.0, load_);
  if (!ty.empty()) face.add_forces(ty.data(), 1, 1.0, load_);
  contact_->body().deform(load_, displacement_);
  for (Eigen::Index a = 0; a + 2 < displacement_.size(); a += 3)
    max_displacement_ = std::max(max_displacement_, displacement_.segment<3>(a).norm());
}

std::unique_ptr<FiniteBody> make_finite_body(const DynamicContactSpec& c) {
  if (!c.fe_body || !c.dynamic) return nullptr;
  return std::make_unique<FiniteBodyContact>(c);
}

}  // namespace dc::dynamics
