#pragma once
// MUMPS orders the KKT matrix of the finite body's sparse saddle form with our ordering
// (dense_last_ordering.hpp: METIS's nested dissection, the dense inertia-relief columns
// last) instead of its own (SCOTCH: slower, and its result varied from run to run), within a
// scope.
//
// Ipopt 3.11 takes MUMPS's ordering as a number (mumps_pivot_order) and offers no way to hand it
// a permutation, and its linear-solver classes are not installed. So this target
// (dyncontact_process_tuning, linked by programs only: process_tuning.hpp) defines dmumps_c,
// the one MUMPS entry Ipopt calls: the executable's definition comes before libdmumps_seq's in
// the dynamic linker's search, and it forwards every call to
// the real one (dlsym RTLD_NEXT). Within a MumpsOrderedByUs scope, on this thread, an analysis
// (JOB 1, 4, 6) of an assembled matrix is given ICNTL(7) = 1 and PERM_IN; outside, and where
// our definition is not the one taken, MUMPS orders as Ipopt asked (the solve is the same, only
// its ordering differs). Built only with METIS (libmetis-dev) and MUMPS's C header.

namespace dc {

class MumpsOrderedByUs {
 public:
  MumpsOrderedByUs();
  ~MumpsOrderedByUs();
  MumpsOrderedByUs(const MumpsOrderedByUs&) = delete;
  MumpsOrderedByUs& operator=(const MumpsOrderedByUs&) = delete;
};

/// Analyses MUMPS ran with our ordering in this process (INFOG(7) = 1 after them): tests check
/// that the hook is really taken.
long mumps_analyses_ordered_by_us();

/// Whether this build has the hook (METIS and MUMPS's header found).
bool mumps_ordering_hook_built();

}  // namespace dc
