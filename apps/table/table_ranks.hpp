#pragma once
// Many independent work units (the lines of a creep-force table, the runs of a sweep) spread
// over the threads of this process and, when started by `mpirun`, over the ranks of the job.
// Dynamic assignment: rank 0 hands out the next unit to whichever rank asks (uneven units
// balance themselves); every result is gathered to rank 0 in unit order. A unit's result is a
// JSON value whose numbers survive the transport exactly, so rank 0 sees the same values
// whichever rank or thread computed them (a serial run writes the same files).
//
// Threads: DYNCONTACT_THREADS (default: the hardware's cores) per process without MPI; one
// worker per rank under MPI (start one rank per core).
#include <cstddef>
#include <functional>
#include <memory>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

namespace dc::table {

/// This process's place in an MPI job started by a launcher (mpirun, srun), read from the
/// launcher's environment without starting MPI: {rank, size}; {0, 1} when not launched so.
struct LaunchRank {
  int rank = 0;
  int size = 1;
  bool root() const { return rank == 0; }
};
LaunchRank launch_rank();

/// Whether this program can run across MPI ranks: an MPI transport is installed
/// (install_rank_transport; the command line's, table_ranks_mpi.hpp).
bool built_with_mpi();

/// Runs work(u) for every u in [0, units). Returns, on rank 0, the results in unit order; on
/// other ranks an empty vector. `done(finished, units)` is called on rank 0 (from this thread)
/// as results arrive. `work` must not throw (a unit reports its own failure in its result);
/// if it does, the message becomes the unit's result {"error": message}. Once an interrupt is
/// requested (core/interrupt.hpp) no further unit starts: a unit that was interrupted
/// (dc::Interrupted) or never started has a null result.
/// Under a launcher with several ranks, a program without an MPI transport throws InputError
/// (every rank would run the whole job alone).
std::vector<nlohmann::json> run_distributed(std::size_t units, const std::function<nlohmann::json(std::size_t)>& work,
                                            const std::function<void(std::size_t, std::size_t)>& done);

/// How the ranks of a job started by a launcher exchange units and results for run_distributed:
/// MPI in the command line (table_ranks_mpi.hpp, the library dyncontact_table_mpi), so that the
/// other users of this library (the Python module, the tests) need no MPI.
class RankTransport {
 public:
  virtual ~RankTransport() = default;
  /// Joins the job (the launcher started several ranks): this process's rank and the job's size.
  virtual LaunchRank start() = 0;
  /// Rank 0: answers the requests waiting, without blocking: stores the result a request carries
  /// (`store(unit, result as JSON text)`) and hands out `next_unit()` (-1: stop). Returns the
  /// number of ranks told to stop.
  virtual int serve(const std::function<long long()>& next_unit,
                    const std::function<void(std::size_t, const std::string&)>& store) = 0;
  /// Other ranks: asks rank 0 for a unit, runs it (`result(unit)`), sends its result with the
  /// next request, until told to stop.
  virtual void work(const std::function<nlohmann::json(std::size_t)>& result) = 0;
  /// Leaves the job (every rank, at the end of a run_distributed that started it).
  virtual void finish() = 0;
};

/// The transport every later run_distributed uses under a launcher; installed once, at start-up,
/// before any run_distributed.
void install_rank_transport(std::unique_ptr<RankTransport> transport);

}  // namespace dc::table
