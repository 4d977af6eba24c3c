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
  beyond_shakedown,   ///< "beyond": lambda < 1 (limit_upper_bound < 1): cyclic plasticity or ratchetting
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
  int elastic_limit_line = -1;  ///< 3-D: its y index (nlp/shakedown_3d.hpp); -1 in 2-D
  /// The depth index carrying the largest multiplier mass: where the yield conditions bind.
  int critical_depth = -1;
  int critical_line = -1;       ///< 3-D: the y index of that station; -1 in 2-D
  /// rho at Ipopt's point: 2-D one per depth (components not free are 0); 3-D one per station
  /// (depth k, line j) at k * lines + j.
  std::vector<Voigt> residual;
  /// A certified upper bound of the criterion's own limit: certificate.upper_bound times the
  /// criterion's outer_factor() (core/yield_criterion.hpp: 2/sqrt 3 when the program's cone is
  /// Tresca's inscribed von Mises cylinder, else 1). The verdict "beyond" needs it below 1.
  double limit_upper_bound = 0.0;
  ShakedownVerdict verdict = ShakedownVerdict::undetermined;
  ShakedownCertificate certificate;
  int iterations = 0;           ///< Ipopt's iterations, summed over the rounds
  int rounds = 0;               ///< Ipopt solves (constraint generation's rounds)
  int constraints = 0;          ///< yield conditions in the last program solved (of depths x positions)
  double time_s = 0.0;          ///< wall time of the whole analysis
};

}  // namespace dc
