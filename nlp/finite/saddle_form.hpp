#pragma once
// The sparse saddle form (a) of finite normal contact, handed to Ipopt. The body's equilibrium
// stays as sparse equality rows instead of being condensed (DESIGN.md "Finite contact"), written
// in the body's stresses (core/fe/stress_equilibrium.hpp: one weighted stress s_q per quadrature
// point, K = Gt H^-1 Gt'):
//   minimise   1/2 p'(A C_hs)p + 1/2 s'H s + A (h - delta)'p
//   subject to Gt s = B p - M R a     (the body's equilibrium (3.12), at all dofs but six held
//                                      ones, whose rows follow from the next six)
//              R'M R a = R'B p        (the rigid modes: inertia relief of the resultant)
//              sum A p = P            (force control; delta is then its multiplier)
//              p >= 0                 ((2.2)-(2.3))
// over (p, s, a). The inner minimum over s is the body's complementary energy 1/2 F'K+F of
// the nodal forces F = B p - M R a, so the program is the condensed one of body_compliance.hpp
// with the same minimiser: the saddle point gives the condensed program's pressure, and its
// certificate is measured with the condensed operator. The multipliers of the equilibrium rows
// are the body's displacement. H is block-diagonal (6 x 6 per point), so the KKT matrix is
// quasi-definite and MUMPS factorises it with 1 x 1 pivots; the stiffness form (v with Ks v =
// B p - M R a and 1/2 v'Ks v) had the block [[Ks, Ks], [Ks, 0]] that needs 2 x 2 pivots and
// was several times slower. The half-space block A C_hs is dense: the exact Hessian (dense block
// + H) while it fits, Ipopt's limited-memory Hessian beyond.
#include <string>
#include <vector>

#include <Eigen/Dense>

#include "case_model.hpp"
#include "contact_face.hpp"
#include "elastic_body.hpp"
#include "linear_operator.hpp"
#include "quadratic_program.hpp"

namespace dc {

struct SaddleNormalOutcome {
  std::vector<double> pressure;        ///< Pa, one per grid element (>= 0)
  std::vector<double> displacement;    ///< w = C_hs p + B'u / A at the grid (m)
  Eigen::VectorXd body_displacement;   ///< u from the equilibrium rows' multipliers, less its mean rigid motion (R'M u = 0)
  bool success = false;                ///< Ipopt's verdict (the certificate decides)
  bool exact_hessian = false;
  std::string message;
  int iterations = 0;
};

/// Grid elements whose `heights` are infinite cannot touch (p held at 0). `options.hessian`:
/// exact, limited-memory or auto (exact while the dense half-space block has at most
/// kSaddleExactLimit rows).
SaddleNormalOutcome solve_saddle_normal(const fe::ElasticBody& body, const fe::ContactFace& face,
                                        const LinearOperator& halfspace, const Grid& grid,
                                        const std::vector<double>& heights, const NormalSpec& control,
                                        const SolveOptions& options);

/// The dense half-space block has N (N + 1) / 2 entries in the KKT matrix: 0.6 M at 32^2 (up
/// to which it is kept exact), 8 M at 64^2.
inline constexpr std::size_t kSaddleExactLimit = 1100;

}  // namespace dc
