#pragma once
// Finite contact (the paper's case (a)): an elastic finite-element body on the half-space.
// inf over u of (3.11) is the body's equilibrium K u = B t (+ the inertia relief of its
// rigid motion), so the minimax (3.14) becomes one convex program over the contact tractions
// with the condensed compliance C_halfspace + B'K+B / A (body_compliance.hpp). The normal
// problem is (4.7) with that compliance: every backend of NormalProblem solves it.
#include <array>
#include <memory>
#include <optional>
#include <string>

#include "fe_body_spec.hpp"
#include "contact_face.hpp"
#include "elastic_body.hpp"
#include "friction_law.hpp"
#include "normal_problem.hpp"
#include "stress_equilibrium.hpp"
#include "tangential_problem.hpp"

namespace dc {

struct FiniteNormalSolution {
  NormalSolution contact;
  Eigen::VectorXd body_displacement;   ///< nodal (x, y, z) relative to the body's rigid motion
  double max_body_displacement = 0.0;  ///< m
};

/// The heights of a profile tilted by rotations (theta_x, theta_y) about the grid origin: the
/// approach at (x, y) grows by theta_y x - theta_x y (finite_tilt.cpp).
std::vector<double> tilted_heights(const std::vector<double>& heights, const Grid& grid, double theta_x,
                                   double theta_y);

class FiniteContact {
 public:
  /// Meshes and factorises the body once; `halfspace` is the substrate (the body's own
  /// compliance comes from the mesh).
  FiniteContact(const FeBodySpec& body, const Grid& grid, const Elastic& halfspace,
                OperatorKind kind = OperatorKind::automatic);

  /// The normal problem by the body's `program`: condensed (any backend) or the sparse saddle
  /// form (Ipopt; saddle_form.hpp), both certified on the condensed program.
  FiniteNormalSolution solve_normal(const NormalSpec& control, const SolverOptions& solver,
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
  /// The body's tilt (rad, rotations about x and y): given, or solved with the moment rows.
  std::array<double, 2> tilt() const { return tilt_; }
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
  std::optional<std::array<double, 2>> load_line_;
  std::array<double, 2> tilt_{0.0, 0.0};
  std::unique_ptr<fe::StressEquilibrium> stresses_;  ///< the sparse form's rows, built on first use

  /// The body's equilibrium in its stresses (stress_equilibrium.hpp) for the sparse form: set up
  /// once per body, kept for every sparse solve (histories, time steps).
  const fe::StressEquilibrium& stress_rows();

  /// The face's heights tilted by the given tilt.
  std::vector<double> profile_heights() const;
  /// The moment rows of a load line (finite_tilt.cpp).
  NormalSolution solve_tilted(const NormalSpec& control, const SolverOptions& solver, const ProgressCallback& progress);

  /// The sparse saddle form (saddle_form.hpp) on the profile's heights or on given ones: the
  /// backends of saddle_backend_order in turn, each certified on the condensed program.
  NormalSolution solve_sparse(const NormalSpec& control, const SolverOptions& solver, const ProgressCallback& progress,
                              Eigen::VectorXd& body_displacement);
  NormalSolution solve_sparse(const std::vector<double>& heights, const NormalSpec& control, const SolverOptions& solver,
                              const ProgressCallback& progress, Eigen::VectorXd& body_displacement);
  /// The tangential problem by the sparse form (TangentialProblem::use_sparse_form).
  void use_sparse_tangential();
  NormalSolution solve_sparse_by(const std::string& backend, const std::vector<double>& heights,
                                 const NormalSpec& control, const SolverOptions& solver, const ProgressCallback& progress,
                                 Eigen::VectorXd& body_displacement);
};

}  // namespace dc
