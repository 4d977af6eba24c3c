#include "sparse_factorisation_hooks.hpp"

#include <atomic>

namespace dc {
namespace {
std::atomic<void (*)()> installed_enter{nullptr};
std::atomic<void (*)()> installed_leave{nullptr};
}  // namespace

void set_sparse_factorisation_hooks(const SparseFactorisationHooks& hooks) {
  installed_enter.store(hooks.enter);
  installed_leave.store(hooks.leave);
}

SparseFactorisationScope::SparseFactorisationScope() : leave_(installed_leave.load()) {
  if (void (*enter)() = installed_enter.load()) enter();
}

SparseFactorisationScope::~SparseFactorisationScope() {
  if (leave_ != nullptr) leave_();
}

}  // namespace dc
