#pragma once
// The solver's options (as Ceres' Solver::Options): a public struct whose fields hold their
// documented defaults, and one validity check. The case file's `solver` block is read into it
// (apps/case/read_solver.cpp), the solvers in nlp/ and dynamics/ take it.
#include <optional>
#include <string>

#include "operator_kind.hpp"

namespace dc {

/// Which backend solves the quadratic programs.
enum class Backend {
  automatic,  ///< "auto": by problem size (nlp/backend_choice.hpp), the others as fallbacks
  ipopt,      ///< "ipopt": Ipopt (interior point)
  nlopt,      ///< "nlopt": NLopt
  native,     ///< "native": the problem's own specialist solver
};

/// Ipopt's Hessian of the quadratic programs.
enum class Hessian {
  automatic,       ///< "auto": exact up to a problem-size limit (SolveOptions::exact_hessian_limit)
  exact,           ///< "exact": the exact (dense) Hessian
  limited_memory,  ///< "limited-memory": the L-BFGS approximation
};

struct SolverOptions {
  /// Relative tolerance handed to the backend. Default 1e-9; valid from 1e-16 to 0.1.
  double tol = 1e-9;
  /// Largest accepted certificate residual (relative). Default 1e-6; valid from 1e-16 to 0.1.
  double certificate_tol = 1e-6;
  /// Iteration limit of a backend. Default 1000; at least 1.
  int max_iter = 1000;
  /// With `backend` automatic: try the next backend when one fails. Default true.
  bool fallback = true;
  /// Write the results (exit 0) even when the certificate fails. Default false.
  bool accept_unconverged = false;
  /// The backend. Default automatic; a named backend is never replaced by another.
  Backend backend = Backend::automatic;
  /// Ipopt's Hessian. Default automatic.
  Hessian hessian = Hessian::automatic;
  /// The compliance operator. Default automatic.
  OperatorKind operator_kind = OperatorKind::automatic;

  static constexpr double kMinTol = 1e-16;  ///< smallest valid tol and certificate_tol
  static constexpr double kMaxTol = 0.1;    ///< largest valid tol and certificate_tol

  /// "" when the options are valid, else "<field>: <reason>", the field named as in the case
  /// file's `solver` block (e.g. "max_iter: must be at least 1, got 0"). The case reader reports
  /// it as InputError("solver.<field>", reason).
  std::string validate() const;
};

/// The user-facing names: "auto", "ipopt", "nlopt", "native"; "auto", "exact", "limited-memory";
/// "auto", "dense", "fft" (summary.json, stdout, reports).
const char* to_string(Backend backend);
const char* to_string(Hessian hessian);
const char* to_string(OperatorKind kind);

/// The value of a user-facing name (nullopt for an unknown one). For the layers where text comes
/// in only (the case reader, the command line, the Python binding): the solvers take the enums.
std::optional<Backend> backend_from_string(const std::string& name);
std::optional<Hessian> hessian_from_string(const std::string& name);
std::optional<OperatorKind> operator_kind_from_string(const std::string& name);

}  // namespace dc
