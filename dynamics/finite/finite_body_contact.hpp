#pragma once
// The finite-element body of a dynamic case (the paper's case (a) in every time step,
// (3.3)-(3.17)): the finite program of nlp/finite/ (its CHOLMOD factor kept for the run, its
// problems warm-started step to step) at the trial kinematics of the rigid-body stepper.
//
// The body's elastic load is F* + B t with F* = rho (b - a+) of (2.22)-(2.24). The body forces
// b and the parts Omega_dot x r + R_ddot of a+ are rigid-mode fields: with the converged step's
// m a+ = F_external + F_contact (the external loads act as body forces, distributed with the
// mass) they balance the contact's resultant, which is the inertia relief of the free body
// (core/fe/elastic_body.hpp). The centripetal part Omega x (Omega x r) is not a rigid mode:
// its deformation opens the gap by its mean normal displacement over each grid element.
// Shift and torsion only (2.16): the body's tilt enters the gap to first order, its turn about
// z is not followed (the grid moves with the centre of mass).
#include <array>
#include <memory>
#include <vector>

#include <Eigen/Dense>

#include "dynamic_spec.hpp"
#include "finite_body.hpp"
#include "finite_contact.hpp"

namespace dc::dynamics {

class FiniteBodyContact final : public FiniteBody {
 public:
  /// Beyond this tilt (rad) the first-order gap of a tilted face is no longer the body's:
  /// the step is an input error (shift and torsion only).
  static constexpr double kMaxTilt = 0.05;

  /// Meshes and factorises the body (c.fe_body on c.grid over c.materials.base).
  explicit FiniteBodyContact(const DynamicContactSpec& c);

  /// The rigid body of the mesh: its mass and inertia about its centre of mass.
  RigidBody rigid_body() const override;
  /// Height of the centre of mass over the body's lowest point: the approach at centre height
  /// z is centre_height() - z.
  double centre_height() const override { return centre_height_; }
  /// E / (1 - nu^2) of the body's material (isotropic estimate): for Newton's normal stiffness.
  double plane_modulus() const override;
  /// The centre of mass's (x, y) on the grid (moments are taken about it).
  Eigen::Vector2d centre_xy() const override { return centre_xy_; }

  /// The gap at trial kinematics (tilt, centripetal deformation). True when the heights changed.
  /// Throws InputError("body.initial.omega") for a tilt beyond kMaxTilt.
  bool update(const StepKinematics& k) override;
  const std::vector<double>& heights() const override { return heights_; }

  NormalProblem& normal_problem() override { return contact_->normal_problem(); }
  TangentialProblem& tangential_problem(const FrictionLaw& law) override { return contact_->tangential_problem(law); }
  /// The body's deformation at an accepted step: contact tractions (one value per grid
  /// element; tx, ty may be empty: frictionless) plus the centripetal load of the last update.
  void accept(const std::vector<double>& tx, const std::vector<double>& ty,
              const std::vector<double>& p) override;
  /// The nodal displacement of the last accepted step (relative to the mean rigid motion).
  const Eigen::VectorXd& displacement() const override { return displacement_; }
  /// The largest |u| over the accepted steps (m).
  double max_displacement() const override { return max_displacement_; }

  const fe::ElasticBody& elastic_body() const override { return contact_->body(); }
  double mesh_seconds() const override { return contact_->mesh_seconds(); }

 private:
  /// The nodal load of the centripetal inertia -rho Omega x (Omega x r) (Omega in body axes).
  void centripetal_load(const Eigen::Vector3d& omega_body, Eigen::VectorXd& F) const;

  const Grid& grid_;
  fe::BodyMaterial material_;
  std::unique_ptr<FiniteContact> contact_;
  double centre_height_ = 0.0;
  Eigen::Vector2d centre_xy_ = Eigen::Vector2d::Zero();
  // first_moments_(j, a) = int rho N_a r_j dV about the centre of mass (the consistent mass
  // matrix times the linear field r_j: the centripetal load's pieces).
  Eigen::Matrix<double, 3, Eigen::Dynamic> first_moments_;
  std::vector<double> heights_, opening_;
  std::array<double, 2> tilt_{0.0, 0.0};
  Eigen::Vector3d omega_body_ = Eigen::Vector3d::Zero();
  bool spinning_ = false;
  Eigen::VectorXd load_, spin_u_, displacement_;
  std::vector<double> traction_;
  double max_displacement_ = 0.0;
};

/// The finite body of a dynamic case with an fe_body (null without one).
std::unique_ptr<FiniteBody> make_finite_body(const DynamicContactSpec& c);

}  // namespace dc::dynamics
