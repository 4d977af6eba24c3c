#include "solver_options.hpp"

#include <cstddef>
#include <utility>

#include "number_text.hpp"

namespace dc {
namespace {

// The user-facing names: one table per enum, read both ways.
template <class Enum>
using Name = std::pair<Enum, const char*>;
constexpr Name<Backend> kBackendNames[] = {
    {Backend::automatic, "auto"}, {Backend::ipopt, "ipopt"}, {Backend::nlopt, "nlopt"}, {Backend::native, "native"}};
constexpr Name<Hessian> kHessianNames[] = {
    {Hessian::automatic, "auto"}, {Hessian::exact, "exact"}, {Hessian::limited_memory, "limited-memory"}};
constexpr Name<OperatorKind> kOperatorKindNames[] = {
    {OperatorKind::automatic, "auto"}, {OperatorKind::dense, "dense"}, {OperatorKind::fft, "fft"}};

template <class Enum, std::size_t N>
const char* name_of(Enum value, const Name<Enum> (&names)[N]) {
  for (const auto& [v, name] : names)
    if (v == value) return name;
  return "unknown";
}

template <class Enum, std::size_t N>
std::optional<Enum> value_of(const std::string& name, const Name<Enum> (&names)[N]) {
  for (const auto& [v, n] : names)
    if (name == n) return v;
  return std::nullopt;
}

/// "" when `value` is in [lo, hi], else the case reader's message (JsonBlock::bounded).
std::string outside(const char* field, double value, double lo, double hi) {
  if (value >= lo && value <= hi) return "";
  return std::string(field) + ": must be from " + six_digits(lo) + " to " + six_digits(hi) + " (relative), got " + six_digits(value);
}

}  // namespace

std::string SolverOptions::validate() const {
  if (std::string why = outside("tol", tol, kMinTol, kMaxTol); !why.empty()) return why;
  if (std::string why = outside("certificate_tol", certificate_tol, kMinTol, kMaxTol); !why.empty()) return why;
  if (max_iter < 1) return "max_iter: must be at least 1, got " + std::to_string(max_iter);
  return "";
}

const char* to_string(Backend backend) { return name_of(backend, kBackendNames); }
const char* to_string(Hessian hessian) { return name_of(hessian, kHessianNames); }
const char* to_string(OperatorKind kind) { return name_of(kind, kOperatorKindNames); }

std::optional<Backend> backend_from_string(const std::string& name) { return value_of(name, kBackendNames); }
std::optional<Hessian> hessian_from_string(const std::string& name) { return value_of(name, kHessianNames); }
std::optional<OperatorKind> operator_kind_from_string(const std::string& name) {
  return value_of(name, kOperatorKindNames);
}

}  // namespace dc
