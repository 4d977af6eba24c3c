#pragma once
// The sparse saddle form (a) of finite contact. The body's equilibrium stays as sparse equality
// rows instead of being condensed (DESIGN.md "Finite contact"), written in the body's stresses
// (core/fe/stress_equilibrium.hpp: one weighted stress s_q per quadrature point, K = Gt H^-1 Gt'
// with H block-diagonal): for tractions t on the grid,
//   Gt s = B t - M R a     (the body's equilibrium (3.12), at every dof but six held ones, whose
//                           rows follow from the next six)
//   R'M R a = R'B t        (the rigid modes: inertia relief of the resultant)
// over the body's unknowns (s, a), and the objective carries the body's complementary energy
// 1/2 s'H s, whose minimum on these rows is t'B'K+B t / 2: a program over (t, s, a) has the
// condensed program's minimiser (body_compliance.hpp), and its result is certified with the
// condensed operators. H's 6 x 6 blocks make the KKT matrix quasi-definite (MUMPS pivots 1 x 1;
// the stiffness form 1/2 v'Ks v with Ks v = B t - M R a gave [[Ks, Ks], [Ks, 0]], 2 x 2 pivots,
// 5-7 x slower). The rows are a SparseBlock of the QuadraticProgram over t (sparse_block.hpp):
// Ipopt takes them sparse.
//
// The normal problem:
//   minimise   1/2 p'(A C_hs)p + 1/2 s'H s + A (h - delta)'p
//   subject to the rows above with t = p (z), sum A p = P (force control), p >= 0.
// The tangential problem (TangentialProblem::use_sparse_form): its program over tau = (tx, ty)
// with the half-space's Cerruti operator as Q and the rows above with t = tau (x, y).
#include <string>
#include <vector>

#include <Eigen/Dense>

#include "contact_face.hpp"
#include "contact_spec.hpp"
#include "elastic_body.hpp"
#include "linear_operator.hpp"
#include "quadratic_program.hpp"
#include "sparse_block.hpp"
#include "stress_equilibrium.hpp"

namespace dc {

/// The body's rows for a program over tractions x (component components[c] of grid element k
/// at column c N + k) in units of `traction_unit` (Pa) and an objective in units of
/// `energy_unit` (Pa m: the compliances' t'C t): y = (s / s_unit, scaled a), every row of
/// order one when `force_scale` (N) is the order of the resultant. `stresses` is the body's
/// stress_equilibrium (set up once per body and kept: about 1.4 M nonzeros for 2k elements).
struct SaddleBody {
  SparseBlock block;
  double s_unit = 1.0;  ///< weighted stress (Pa m^3/2) per unit of y's s part
};
SaddleBody saddle_body_block(const fe::ElasticBody& body, const fe::StressEquilibrium& stresses,
                             const fe::ContactFace& face, const Grid& grid, const std::vector<int>& components, double traction_unit, double energy_unit,
                             double force_scale);
/// The body's displacement relative to its mean rigid motion (R'M u = 0) under the tractions
/// (Pa, grid elements) along `component` (0, 1, 2), from the kept factor.
Eigen::VectorXd saddle_body_displacement(const fe::ElasticBody& body, const fe::ContactFace& face, int component,
                                         const std::vector<double>& tractions);

/// The backends of the sparse form, in order: Ipopt for `auto` and `ipopt`. Throws
/// InputError("solver.backend") for the others: the native solvers take no sparse rows, and
/// NLopt's equality algorithms (AUGLAG) held the rows densely and did not converge (residual
/// 0.99 after 1000 evaluations on a 6 x 6 grid and the coarsest hemisphere).
std::vector<std::string> saddle_backend_order(Backend requested);
/// With backend "auto", a normal problem Ipopt fails on in the sparse form falls back to NLopt on
/// the condensed program (FiniteContact::solve_normal), a tangential one to the native solver,
/// then NLopt, on the condensed program (SparseTangentialForm::condensed_fallback), for bodies of
/// at most this many dofs.
inline constexpr std::size_t kSaddleFallbackDofs = 20000;

struct SaddleNormalOutcome {
  std::vector<double> pressure;        ///< Pa, one per grid element (>= 0)
  std::vector<double> displacement;    ///< w = C_hs p + B'u / A at the grid (m)
  Eigen::VectorXd body_displacement;   ///< u of the pressure, less its mean rigid motion (R'M u = 0)
  std::vector<double> weighted_stresses;  ///< the saddle point's s (Pa m^3/2, stress_equilibrium.hpp)
  bool success = false;                ///< the backend's verdict (the certificate decides)
  bool exact_hessian = false;
  std::string message;
  int iterations = 0;
};

/// The normal problem by one backend (ipopt). Grid elements whose `heights` are
/// infinite cannot touch (p held at 0). `options.hessian`: exact, limited-memory or auto (exact
/// while the dense half-space block has at most kSaddleExactLimit rows).
SaddleNormalOutcome solve_saddle_normal(const fe::ElasticBody& body, const fe::StressEquilibrium& stresses,
                                        const fe::ContactFace& face,
                                        const LinearOperator& halfspace, const Grid& grid,
                                        const std::vector<double>& heights, const NormalSpec& control,
                                        SolveOptions options, const std::string& backend);

/// The dense half-space block has N (N + 1) / 2 entries in the KKT matrix: 0.6 M at 32^2 (up
/// to which it is kept exact), 8 M at 64^2.
inline constexpr std::size_t kSaddleExactLimit = 1100;

}  // namespace dc
