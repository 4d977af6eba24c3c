#pragma once
// One BLAS thread per process. An optimised BLAS (OpenBLAS, which scripts/setup.sh installs for
// CHOLMOD's and MUMPS's factorisations) splits some reductions over its threads, so a result
// would depend on how many threads it had: a table run over threads and one over MPI ranks would
// differ in the last digits. dyncontact parallelises over points and ranks itself, so the BLAS
// runs one thread, and every run writes the same bytes.
namespace dc::cli {

/// Sets the BLAS to one thread when it is OpenBLAS (found at run time; a no-op for any other BLAS).
void use_one_blas_thread();

}  // namespace dc::cli
