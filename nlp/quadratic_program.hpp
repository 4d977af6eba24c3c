#pragma once
// The one program interface every backend sees: a convex quadratic program
//   minimise  1/2 x'Qx + c'x
//   subject to lower <= x <= upper,  a_k'x = b_k,  x_i^2 + x_j^2 <= r^2 (cones).
// Q is applied matrix-free (LinearOperator); small problems may also expose it densely.
#include <cmath>
#include <functional>
#include <limits>
#include <string>
#include <vector>

#include "iteration_record.hpp"
#include "linear_operator.hpp"
#include "solver_options.hpp"

namespace dc {

struct LinearEquality {
  std::vector<double> a;  ///< dense row, size n
  double b = 0.0;
};

/// Second-order cone in two variables: x[ix]^2 + x[iy]^2 <= radius^2 (a friction disk).
struct DiskConstraint {
  int ix = 0, iy = 0;
  double radius = 0.0;
};

struct SparseBlock;  // sparse_block.hpp

struct QuadraticProgram {
  const LinearOperator* Q = nullptr;  ///< symmetric positive semi-definite, n x n
  std::vector<double> c;              ///< size n
  std::vector<double> lower, upper;   ///< size n (or empty: unbounded); +-infinity allowed
  std::vector<LinearEquality> equalities;
  std::vector<DiskConstraint> disks;
  std::vector<double> x0;  ///< starting point (or empty: zeros projected on the bounds)
  /// Further unknowns kept as sparse rows (sparse_block.hpp): Ipopt only.
  const SparseBlock* block = nullptr;
  /// An approximate inverse of Q (symmetric positive definite; e.g. core/tangential_preconditioner):
  /// the native tangential solver's conjugate gradients use it on their face. Optional.
  const LinearOperator* preconditioner = nullptr;

  int n() const { return static_cast<int>(c.size()); }
  /// Why the program is malformed (sizes, indices, missing operator), or empty when it is fine.
  std::string invalid_reason() const;
  double objective(const double* x) const;
  /// g = Qx + c; returns the objective as a by-product.
  double gradient(const double* x, double* g) const;
};

inline constexpr double kInf = std::numeric_limits<double>::infinity();

/// The Euclidean projection of (x, y) onto the disk of radius r >= 0 (a friction disk):
/// unchanged inside, scaled onto the circle outside.
inline void project_onto_disk(double& x, double& y, double r) {
  const double norm2 = x * x + y * y;
  if (norm2 <= r * r) return;
  const double s = norm2 > 0.0 ? r / std::sqrt(norm2) : 0.0;
  x *= s;
  y *= s;
}

struct ProgressInfo {
  int iteration = 0;
  double objective = 0.0;
  double residual = 0.0;
  double target = 0.0;  ///< the residual at which the solver stops (0: not known); the time left follows
  int step = 0;         ///< a history: the step being solved (0-based) of `steps` (0: not a history)
  int steps = 0;
};
using ProgressCallback = std::function<void(const ProgressInfo&)>;

struct SolveOptions {
  double tol = 1e-9;        ///< relative tolerance handed to the backend
  int max_iter = 1000;      ///< iteration limit of the backend
  /// Ipopt Hessian: exact, limited-memory or automatic (exact while n <= exact_hessian_limit).
  Hessian hessian = Hessian::automatic;
  int exact_hessian_limit = 500;  // measured: L-BFGS is faster from ~30^2 unknowns (dense MUMPS)
  bool verbose = false;
  ProgressCallback progress;  ///< called now and then by backends that support it
};

/// What a backend returns. Multipliers follow  Qx + c = sum_k lambda_k a_k + z_l - z_u - sum disks.
struct SolveOutcome {
  std::vector<double> x;
  std::vector<double> equality_multipliers;
  bool success = false;       ///< the backend's own verdict (the certificate decides)
  std::string message;        ///< backend status text
  int iterations = 0;
  double objective = 0.0;
  bool polished = false;      ///< finished by the active-set polish (active_set_polish.hpp)
  std::vector<double> block_x;  ///< the program's sparse block's unknowns y (when it has one)
  std::vector<IterationRecord> history;  ///< native solvers: a bounded iteration history
};

SolveOutcome solve_with_ipopt(const QuadraticProgram& qp, const SolveOptions& options);
SolveOutcome solve_with_nlopt(const QuadraticProgram& qp, const SolveOptions& options);

}  // namespace dc
