#include "mumps_ordering_hook.hpp"

#if defined(DYNCONTACT_WITH_MUMPS_ORDERING)

#include "dense_last_ordering.hpp"

#include <dlfcn.h>
#include <dmumps_c.h>

#include <atomic>
#include <cstdio>
#include <cstdlib>

namespace dc {
namespace {
thread_local int ordering_scopes_open = 0;
std::atomic<long> ordered_analyses{0};

using DmumpsEntry = void (*)(DMUMPS_STRUC_C*);

DmumpsEntry real_dmumps() {
  static const DmumpsEntry real = [] {
    auto* found = reinterpret_cast<DmumpsEntry>(dlsym(RTLD_NEXT, "dmumps_c"));
    if (found == nullptr) {
      // Only reached when something called dmumps_c, so libdmumps is loaded after us.
      std::fprintf(stderr, "internal error: MUMPS's dmumps_c not found behind the ordering hook\n");
      std::abort();
    }
    return found;
  }();
  return real;
}

// MUMPS's analysis jobs (analysis alone, with the factorisation, with the solve too).
bool is_analysis(int job) { return job == 1 || job == 4 || job == 6; }

// MUMPS's controls are 1-based in its manual.
constexpr int kOrdering = 7 - 1;        // ICNTL(7): 1 = the user's PERM_IN
constexpr int kFormat = 5 - 1;          // ICNTL(5): 0 = assembled
constexpr int kDistribution = 18 - 1;   // ICNTL(18): 0 = centralised on the host
constexpr int kOrderingUsed = 7 - 1;    // INFOG(7)
constexpr int kUserOrdering = 1;

void analyse_with_our_ordering(DMUMPS_STRUC_C* mumps) {
  // MUMPS 5 reads NNZ, or NZ when NNZ is 0 (Ipopt 3.11 sets NZ only).
  const long long entries = mumps->nnz > 0 ? mumps->nnz : mumps->nz;
  DenseLastOrdering order = dense_last_ordering(mumps->n, entries, mumps->irn, mumps->jcn);
  if (order.position.empty()) {  // METIS failed: MUMPS's own ordering
    real_dmumps()(mumps);
    return;
  }
  const int asked = mumps->icntl[kOrdering];
  MUMPS_INT* const asked_permutation = mumps->perm_in;
  mumps->icntl[kOrdering] = kUserOrdering;
  mumps->perm_in = order.position.data();
  real_dmumps()(mumps);
  const bool ours = mumps->info[0] >= 0 && mumps->infog[kOrderingUsed] == kUserOrdering;
  mumps->icntl[kOrdering] = asked;  // PERM_IN is read by the analysis only
  mumps->perm_in = asked_permutation;
  if (ours)
    ++ordered_analyses;
  else if (mumps->info[0] < 0)
    real_dmumps()(mumps);  // MUMPS refused it: the analysis again with its own ordering
}
}  // namespace

MumpsOrderedByUs::MumpsOrderedByUs() { ++ordering_scopes_open; }
MumpsOrderedByUs::~MumpsOrderedByUs() { --ordering_scopes_open; }
long mumps_analyses_ordered_by_us() { return ordered_analyses.load(); }
bool mumps_ordering_hook_built() { return true; }

}  // namespace dc

// Exported even from a program built with hidden visibility, so that libipopt's call resolves
// to it.
extern "C" __attribute__((visibility("default"))) void dmumps_c(DMUMPS_STRUC_C* mumps) {
  if (dc::ordering_scopes_open > 0 && dc::is_analysis(mumps->job) && mumps->sym != 0 && mumps->icntl[dc::kFormat] == 0 &&
      mumps->icntl[dc::kDistribution] == 0 && mumps->irn != nullptr && mumps->jcn != nullptr)
    dc::analyse_with_our_ordering(mumps);
  else
    dc::real_dmumps()(mumps);
}

#else

namespace dc {
MumpsOrderedByUs::MumpsOrderedByUs() = default;
MumpsOrderedByUs::~MumpsOrderedByUs() = default;
long mumps_analyses_ordered_by_us() { return 0; }
bool mumps_ordering_hook_built() { return false; }
}  // namespace dc

#endif
