#pragma once
// The ranks of an MPI job for run_distributed (table_ranks.hpp): rank 0 hands out the next unit
// to whichever rank asks and receives every result. In the library dyncontact_table_mpi, which
// only the command line links (built with DYNCONTACT_WITH_MPI): the other users of
// dyncontact_table spread their units over their threads alone.

namespace dc::table {

/// Installs MPI as run_distributed's transport between ranks (once, at start-up, before any
/// run_distributed).
void use_mpi_ranks();

}  // namespace dc::table
