#pragma once
// A finite-element body in a dynamic run (the paper's case (a) in every time step): what the
// contact wrench and the stepper ask of it. Implemented by dynamics/finite/ (built with
// finite-element support); the dynamics library itself needs no finite elements.
#include <memory>
#include <vector>

#include <Eigen/Core>

#include "normal_problem.hpp"
#include "rigid_body.hpp"
#include "tangential_problem.hpp"
#include "wrench.hpp"

namespace dc::fe {
class ElasticBody;
}

namespace dc::dynamics {

class FiniteBody {
 public:
  virtual ~FiniteBody() = default;
  /// The rigid body of the mesh: its mass and inertia about its centre of mass.
  virtual RigidBody rigid_body() const = 0;
  /// Height of the centre of mass over the body's lowest point: the approach at centre height z
  /// is centre_height() - z.
  virtual double centre_height() const = 0;
  /// The centre of mass's (x, y) on the grid (the contact's moments are taken about it).
  virtual Eigen::Vector2d centre_xy() const = 0;
  /// E / (1 - nu^2) of the body's material (an isotropic estimate, for Newton's normal stiffness).
  virtual double plane_modulus() const = 0;
  /// The gap at trial kinematics; true when the heights changed. InputError for a motion the
  /// finite program cannot take.
  virtual bool update(const StepKinematics& k) = 0;
  virtual const std::vector<double>& heights() const = 0;
  /// The finite program's problems (the condensed compliance; kept for the run).
  virtual NormalProblem& normal_problem() = 0;
  virtual TangentialProblem& tangential_problem(const FrictionLaw& law) = 0;
  /// The body's deformation at an accepted step under the contact tractions (one value per grid
  /// element; tx, ty, p may be empty: none).
  virtual void accept(const std::vector<double>& tx, const std::vector<double>& ty, const std::vector<double>& p) = 0;
  /// The nodal displacement of the last accepted step (relative to the mean rigid motion).
  virtual const Eigen::VectorXd& displacement() const = 0;
  /// The largest nodal |u| over the accepted steps (m).
  virtual double max_displacement() const = 0;
  virtual const fe::ElasticBody& elastic_body() const = 0;
  /// Seconds spent meshing and factorising.
  virtual double mesh_seconds() const = 0;
};

}  // namespace dc::dynamics
