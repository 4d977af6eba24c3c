#pragma once
// What the shakedown analysis returns (nlp/shakedown_problem.hpp): the shakedown load factor,
// the elastic limit, the verdict at the load as given, the residual stress and our own
// certificate.
#include <string>
#include <vector>

#include "voigt_stress.hpp"

namespace dc {

enum class ShakedownStatus {
  optimal,        ///< "optimal": the certificate holds (gap and yield violation within certificate_tol)
  not_converged,  ///< "not_converged": Ipopt gave a point, the certificate does not hold
  unbounded,      ///< "unbounded": no depth limits the load factor (the residual can absorb every sample)
  failed,         ///< "failed": no usable point (Ipopt's failure, non-finite values)
};
// No "infeasible": lambda = 0, rho = 0 satisfies every yield condition strictly (f(0) = 0 < 1),
// so the program always has a feasible point.

/// The load as given (load factor 1) against the two limits.
enum class ShakedownVerdict {
  elastic,            ///< "elastic": lambda_e >= 1, no yield at all
  elastic_shakedown,  ///< "shakedown": lambda_e < 1 <= lambda (certified lower bound >= 1)
  beyond_shakedown,   ///< "beyond": lambda < 1 (certified upper bound < 1): cyclic plasticity or ratchetting
  undetermined,       ///< "undetermined": the certified bracket contains 1, or the solve failed
};

const char* to_string(ShakedownStatus status);
const char* to_string(ShakedownVerdict verdict);

/// Measured by us from Ipopt's point and multipliers (never Ipopt's own claim).
struct ShakedownCertificate {
  double yield_violation = 0.0;  ///< max over samples of f(lambda sigma + rho) - 1, clipped at 0
  /// A feasible load factor: lambda / max f (Ipopt's point scaled onto the yield surface).
  double lower_bound = 0.0;
  double upper_bound = 0.0;      ///< the Lagrangian dual bound sqrt(S / Q) from the multipliers (+inf: none)
  double duality_gap = 0.0;      ///< (upper_bound - lower_bound) / upper_bound
};

struct ShakedownResult {
  ShakedownStatus status = ShakedownStatus::failed;
  std::string message;          ///< Ipopt's status, or why it was not run
  double load_factor = 0.0;     ///< the shakedown limit lambda (Ipopt's point; +inf when unbounded)
  double elastic_limit = 0.0;   ///< lambda_e = 1 / max f(sigma^e) (+inf when no sample is stressed)
  int elastic_limit_depth = -1, elastic_limit_position = -1;  ///< where first yield occurs
  /// The depth index carrying the largest multiplier mass: where the yield conditions bind.
  int critical_depth = -1;
  std::vector<Voigt> residual;  ///< rho(z_j) at Ipopt's point, one per depth (components not free are 0)
  ShakedownVerdict verdict = ShakedownVerdict::undetermined;
  ShakedownCertificate certificate;
  int iterations = 0;           ///< Ipopt's iterations, summed over the rounds
  int rounds = 0;               ///< Ipopt solves (constraint generation's rounds)
  int constraints = 0;          ///< yield conditions in the last program solved (of depths x positions)
  double time_s = 0.0;          ///< wall time of the whole analysis
};

}  // namespace dc
