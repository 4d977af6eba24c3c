#pragma once
// Solver settings the validation tests run with.
#include "case_model.hpp"

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

}  // namespace dc::test
