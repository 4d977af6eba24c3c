#pragma once
// Restarted GMRES for matrix-free non-symmetric systems A x = b (right preconditioned:
// A M^-1 y = b, x = M^-1 y), used by the steady rolling Newton solver, the contact sensitivity and
// the pointwise heat partition (flash_temperature.hpp).
#include <functional>
#include <vector>

namespace dc {

struct GmresResult {
  int iterations = 0;       ///< applies of A
  double relative_residual = 0.0;
  bool converged = false;
};

using VectorMap = std::function<void(const std::vector<double>& in, std::vector<double>& out)>;

/// The Krylov basis and the small least-squares arrays of a solve, kept between solves (a
/// caller solving many systems of one size allocates them once: a basis of 60 vectors of 3000
/// doubles is glibc-mmap'ed memory, page faults at every fresh allocation).
struct GmresWorkspace {
  std::vector<std::vector<double>> V, H;
  std::vector<double> cs, sn, g, z, w, y;
};

/// Solves A x = b from x (in/out) to |b - A x| <= rtol |b| with restarts every `restart`
/// iterations, at most `max_iter` applies. `precondition` (may be empty) applies M^-1.
GmresResult gmres(const VectorMap& apply, const VectorMap& precondition, const std::vector<double>& b,
                  std::vector<double>& x, double rtol, int restart, int max_iter);
/// The same with the caller's workspace.
GmresResult gmres(const VectorMap& apply, const VectorMap& precondition, const std::vector<double>& b,
                  std::vector<double>& x, double rtol, int restart, int max_iter, GmresWorkspace& work);

}  // namespace dc
