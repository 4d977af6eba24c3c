#pragma once
// The shakedown program's options (nlp/shakedown_problem.hpp): a struct whose fields hold their
// documented defaults, and one validity check (as solver_options.hpp).
#include <string>

namespace dc {

struct ShakedownOptions {
  /// Ipopt's relative tolerance. Default 1e-10; valid from 1e-16 to 0.1.
  double tol = 1e-10;
  /// Largest accepted certificate residual: the relative duality gap (upper - lower) / upper and
  /// the yield violation max f - 1 of Ipopt's point. Default 1e-7; valid from 1e-16 to 0.1.
  double certificate_tol = 1e-7;
  /// Ipopt's iteration limit, per Ipopt solve (constraint generation's round). Default 500; at least 1.
  int max_iter = 500;
  /// Constraint generation: Ipopt solves the program on a working set of samples (per depth the
  /// first-yield sample and the extremes along and across the residual's directions), the samples
  /// its answer violates by more than certificate_tol / 10 are added and the program solved again,
  /// until none is; the certificate is measured on every sample either way (the multipliers of
  /// the samples left out are zero, which keeps the dual bound valid). Default true: 64 depths x
  /// 256 positions in tens of milliseconds instead of a second. False: every sample at once.
  bool constraint_generation = true;
  /// Constraint generation's largest number of rounds (Ipopt solves) before every sample is
  /// taken at once. Default 30; at least 1.
  int max_rounds = 30;
  /// Ipopt prints its iterations and timing statistics (print_level 5). Default false.
  bool verbose = false;

  static constexpr double kMinTol = 1e-16;
  static constexpr double kMaxTol = 0.1;

  /// "" when valid, else "<field>: <reason>".
  std::string validate() const;
};

}  // namespace dc
