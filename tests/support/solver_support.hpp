#pragma once
// Solver settings the validation tests run with.
#include "material.hpp"
#include "solver_options.hpp"

namespace dc::test {

/// The native backend alone (no fallback), tol 1e-10, at most `max_iter` iterations.
inline SolverOptions native_solver_spec(int max_iter) {
  SolverOptions s;
  s.backend = Backend::native;
  s.fallback = false;
  s.tol = 1e-10;
  s.max_iter = max_iter;
  return s;
}

/// Steel (E 210 GPa, nu 0.3) on aluminium (E 70 GPa, nu 0.33): kappa != 0.
inline MaterialPair steel_on_aluminium() {
  return {Elastic::from_E_nu(2.1e11, 0.3), Elastic::from_E_nu(7.0e10, 0.33)};
}

}  // namespace dc::test
