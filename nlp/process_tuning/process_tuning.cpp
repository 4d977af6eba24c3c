#include "process_tuning.hpp"

#include <optional>

#include "freed_memory_kept.hpp"
#include "mumps_ordering_hook.hpp"
#include "sparse_factorisation_hooks.hpp"

namespace dc {
namespace {
// One scope per thread (the library runs one Ipopt application at a time per thread): the
// memory kept first, MUMPS's ordering inside it, left in the reverse order.
thread_local std::optional<FreedMemoryKept> kept;
thread_local std::optional<MumpsOrderedByUs> ordered;

void enter_sparse_factorisation() {
  kept.emplace();
  ordered.emplace();
}

void leave_sparse_factorisation() {
  ordered.reset();
  kept.reset();
}
}  // namespace

void install_process_tuning() {
  SparseFactorisationHooks hooks;
  hooks.enter = &enter_sparse_factorisation;
  hooks.leave = &leave_sparse_factorisation;
  set_sparse_factorisation_hooks(hooks);
}

}  // namespace dc
