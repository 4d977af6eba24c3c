#pragma once
// The sparse saddle form (a) of finite contact. The body's equilibrium stays as sparse equality
// rows instead of being condensed (DESIGN.md "Finite contact"): for tractions t on the grid,
//   Ks v = B t - M R a     (the body's equilibrium, six supported dofs held, (3.12))
//   R'M R a = R'B t        (the rigid modes: inertia relief of the resultant)
// over the body's unknowns (v, a), and the objective carries the body's energy 1/2 v'Ks v / A
// (per unit area, as the compliances are). On these rows v'Ks v = t'B'K+B t, so a program over
// (t, v, a) has the condensed program's minimiser (body_compliance.hpp): its result is
// certified with the condensed operators. The rows are a SparseBlock of the QuadraticProgram
// over t (sparse_block.hpp), which Ipopt takes sparse.
//
// The normal problem:
//   minimise   1/2 p'(A C_hs)p + 1/2 v'Ks v + A (h - delta)'p
//   subject to the rows above with t = p (z), sum A p = P (force control), p >= 0.
// The tangential problem (TangentialProblem::use_sparse_form): its program over tau = (tx, ty)
// with the half-space's Cerruti operator as Q and the rows above with t = tau (x, y).
#include <string>
#include <vector>

#include <Eigen/Dense>

#include "case_model.hpp"
#include "contact_face.hpp"
#include "elastic_body.hpp"
#include "linear_operator.hpp"
#include "quadratic_program.hpp"
#include "sparse_block.hpp"

namespace dc {

/// The body's rows for a program over tractions x (component components[c] of grid element k
/// at column c N + k) in units of `traction_unit` (Pa) and an objective in units of
/// `energy_unit` (Pa m: the compliances' t'C t): y = (v / v_unit, scaled a), every row of
/// order one when `force_scale` (N) is the order of the resultant.
struct SaddleBody {
  SparseBlock block;
  double v_unit = 1.0;  ///< m per unit of y's v part
};
SaddleBody saddle_body_block(const fe::ElasticBody& body, const fe::ContactFace& face, const Grid& grid,
                             const std::vector<int>& components, double traction_unit, double energy_unit,
                             double force_scale);
/// The body's displacement relative to its mean rigid motion (R'M u = 0) from a solution's
/// block unknowns y.
Eigen::VectorXd saddle_body_displacement(const fe::ElasticBody& body, const std::vector<double>& block_x,
                                         double v_unit);

/// The backends of the sparse form, in order: Ipopt for `auto` and `ipopt`. Throws
/// InputError("solver.backend") for the others: the native solvers take no sparse rows, and
/// NLopt's equality algorithms (AUGLAG) held the rows densely and did not converge (residual
/// 0.99 after 1000 evaluations on a 6 x 6 grid and the coarsest hemisphere).
std::vector<std::string> saddle_backend_order(const std::string& requested);

struct SaddleNormalOutcome {
  std::vector<double> pressure;        ///< Pa, one per grid element (>= 0)
  std::vector<double> displacement;    ///< w = C_hs p + B'u / A at the grid (m), the body's u from v
  Eigen::VectorXd body_displacement;   ///< u = v less its mean rigid motion (R'M u = 0)
  bool success = false;                ///< the backend's verdict (the certificate decides)
  bool exact_hessian = false;
  std::string message;
  int iterations = 0;
};

/// The normal problem by one backend (ipopt). Grid elements whose `heights` are
/// infinite cannot touch (p held at 0). `options.hessian`: exact, limited-memory or auto (exact
/// while the dense half-space block has at most kSaddleExactLimit rows).
SaddleNormalOutcome solve_saddle_normal(const fe::ElasticBody& body, const fe::ContactFace& face,
                                        const LinearOperator& halfspace, const Grid& grid,
                                        const std::vector<double>& heights, const NormalSpec& control,
                                        SolveOptions options, const std::string& backend);

/// The dense half-space block has N (N + 1) / 2 entries in the KKT matrix: 0.6 M at 32^2 (up
/// to which it is kept exact), 8 M at 64^2.
inline constexpr std::size_t kSaddleExactLimit = 1100;

}  // namespace dc
