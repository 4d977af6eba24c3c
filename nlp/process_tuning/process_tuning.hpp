#pragma once
// Process-wide tuning of the finite body's sparse solves, for programs only: the library
// (dyncontact_nlp) changes nothing in the process. `dyncontact` and the Python module link
// dyncontact_process_tuning (an object library: its definition of dmumps_c must be linked
// in) and call install_process_tuning() once; the tests that check the tuning do too. Within
// every Ipopt application on a sparse block (nlp/sparse_factorisation_hooks.hpp):
//  - MUMPS orders the KKT matrix with METIS's nested dissection, the dense columns last
//    (mumps_ordering_hook.hpp; built with METIS and MUMPS's C header): 50k dofs 49.7 -> 41.3 s
//    per sparse solve, the same order in every run (SCOTCH's varied; docs/finite.md);
//  - freed memory stays in the heap (freed_memory_kept.hpp, glibc's mallopt): 50k dofs 2.3 M ->
//    0.47 M page faults, system time 11 -> 1.7 s (docs/finite.md, "Performance").
// Without it the solves are the same, only slower.

namespace dc {

/// Installs the tuning's hooks for the process (idempotent).
void install_process_tuning();

}  // namespace dc
