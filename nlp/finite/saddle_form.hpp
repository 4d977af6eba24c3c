#pragma once
// The sparse saddle form (a) of finite normal contact, handed to Ipopt. The body's equilibrium
// stays as sparse equality rows instead of being condensed (DESIGN.md "Finite contact"):
//   minimise   1/2 p'(A C_hs)p + 1/2 v'Ks v + A (h - delta)'p
//   subject to Ks v = B p - M R a     (the body's equilibrium, six supported dofs held, (3.12))
//              R'M R a = R'B p        (the rigid modes: inertia relief of the resultant)
//              sum A p = P            (force control; delta is then its multiplier)
//              p >= 0                 ((2.2)-(2.3))
// over (p, v, a). On the equality set v'Ks v = A p'(B'G B / A)p, so the program is the
// condensed one of body_compliance.hpp with the same minimiser: the saddle point gives the
// condensed program's pressure, and its certificate is measured with the condensed operator.
// The half-space block A C_hs is dense: the exact Hessian (dense block + sparse Ks) while it
// fits, Ipopt's limited-memory Hessian beyond.
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
  std::vector<double> displacement;    ///< w = C_hs p + B'u / A at the grid (m), the body's u from v
  Eigen::VectorXd body_displacement;   ///< u = v less its mean rigid motion (R'M u = 0)
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
