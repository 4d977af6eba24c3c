// The "solver" block (CASES.md) into SolverOptions (nlp/solver_options.hpp), each value checked by
// SolverOptions::validate() as it is read.
#include "case_readers.hpp"

#include <string>

#include "errors.hpp"
#include "json_block.hpp"

namespace dc {

using namespace case_json;

namespace {

/// SolverOptions::validate()'s "<field>: <reason>" as InputError("solver.<field>", reason).
void check_solver(const SolverOptions& s) {
  const std::string why = s.validate();
  if (why.empty()) return;
  const std::size_t colon = why.find(": ");
  throw InputError("solver." + why.substr(0, colon), why.substr(colon + 2));
}

}  // namespace

SolverOptions read_solver(const json& j) {
  JsonBlock o(j, "solver");
  o.allow({"backend", "tol", "certificate_tol", "max_iter", "fallback", "accept_unconverged", "hessian",
           "operator"});
  SolverOptions s;
  s.backend = *backend_from_string(o.choice("backend", to_string(s.backend), {"auto", "ipopt", "nlopt", "native"}));
  // Each value checked as it is read (the first bad key is the one reported).
  s.tol = o.number_or("tol", s.tol);
  check_solver(s);
  s.certificate_tol = o.number_or("certificate_tol", s.certificate_tol);
  check_solver(s);
  s.max_iter = o.integer_or("max_iter", s.max_iter);
  check_solver(s);
  s.fallback = o.boolean_or("fallback", s.fallback);
  s.accept_unconverged = o.boolean_or("accept_unconverged", s.accept_unconverged);
  s.hessian = *hessian_from_string(o.choice("hessian", to_string(s.hessian), {"auto", "exact", "limited-memory"}));
  s.operator_kind =
      *operator_kind_from_string(o.choice("operator", to_string(s.operator_kind), {"auto", "dense", "fft"}));
  return s;
}

}  // namespace dc
