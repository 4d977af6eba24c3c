#pragma once
// The BLAS under Ipopt's MUMPS and CHOLMOD: one thread. A threaded BLAS (Debian's OpenBLAS
// when installed) splits its products by the cores it may use, so the last digits of a result
// would depend on the machine and on the process's binding (`mpirun` binds each rank to a core):
// a table or sweep over ranks would no longer write the bytes the same run writes alone. The
// parallelism of a run is its own (FFT threads, table and sweep points over threads and ranks).
// OPENBLAS_NUM_THREADS or OMP_NUM_THREADS, when set, are left to the BLAS.
namespace dc {

/// Sets the BLAS (OpenBLAS when loaded) to one thread unless the user chose a count; a no-op
/// for a BLAS without threads. Call once at start-up, before any solve.
void use_one_blas_thread();

}  // namespace dc
