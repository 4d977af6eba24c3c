#pragma once
// Finite contact (the paper's case (a)): an elastic finite-element body on the half-space.
// inf over u of (3.11) is the body's equilibrium K u = B t (+ the inertia relief of its
// rigid motion), so the minimax (3.14) becomes one convex program over the contact tractions
// with the condensed compliance C_halfspace + B'K+B / A (body_compliance.hpp). The normal
// problem is (4.7) with that compliance: every backend of NormalProblem solves it.
#include <memory>
#include <string>

#include "case_fe_body.hpp"
#include "contact_face.hpp"
#include "elastic_body.hpp"
#include "friction_law.hpp"
#include "normal_problem.hpp"
#include "tangential_problem.hpp"

namespace dc {

struct FiniteNormalSolution {
  NormalSolution contact;
  Eigen::VectorXd body_displacement;   ///< nodal (x, y, z) relative to the body's rigid motion
  double max_body_displacement = 0.0;  ///< m
};

class FiniteContact {
 public:
  /// Meshes and factorises the body once; `halfspace` is the substrate (the body's own
  /// compliance comes from the mesh).
  FiniteContact(const FeBodySpec& body, const Grid& grid, const Elastic& halfspace,
                OperatorKind kind = OperatorKind::automatic);

  /// The normal problem by the body's `program`: condensed (any backend) or the sparse saddle
  /// form (Ipopt; saddle_form.hpp), both certified on the condensed program.
  FiniteNormalSolution solve_normal(const NormalSpec& control, const SolverSpec& solver,
                                    const ProgressCallback& progress = {});
  /// The tangential problem (shift, torsion, histories; pressure-dependent friction through
  /// (3.31)-(3.32)) on the condensed compliances, built on first use with `friction`. The
  /// body's normal-tangential coupling is left out (Goodman), as for kappa = 0.
  TangentialProblem& tangential_problem(const FrictionLaw& friction);
  /// The body's displacement under contact tractions (tau_x, tau_y, p), each one per grid element.
  Eigen::VectorXd body_displacement(const std::vector<double>& tx, const std::vector<double>& ty,
                                    const std::vector<double>& p) const;

  const fe::ElasticBody& body() const { return *body_; }
  const fe::ContactFace& face() const { return *face_; }
  const Grid& grid() const { return grid_; }
  NormalProblem& normal_problem() { return *normal_; }
  /// Seconds spent meshing (Gmsh) and factorising (CHOLMOD).
  double mesh_seconds() const { return mesh_seconds_; }

 private:
  Grid grid_;
  std::unique_ptr<fe::ElasticBody> body_;
  std::unique_ptr<fe::ContactFace> face_;
  std::shared_ptr<const LinearOperator> normal_compliance_;
  std::shared_ptr<const class BodyCompliance> body_normal_;
  std::unique_ptr<NormalProblem> normal_;
  std::shared_ptr<const LinearOperator> halfspace_tangential_;
  std::unique_ptr<TangentialProblem> tangential_;
  double mesh_seconds_ = 0.0;
  std::string program_;
  std::shared_ptr<const LinearOperator> halfspace_normal_;

  NormalSolution solve_sparse(const NormalSpec& control, const SolverSpec& solver, const ProgressCallback& progress,
                              Eigen::VectorXd& body_displacement);
};

}  // namespace dc
