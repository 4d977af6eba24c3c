#include "table_ranks.hpp"

#include <algorithm>
#include <chrono>
#include <condition_variable>
#include <cstdlib>
#include <exception>
#include <mutex>
#include <string>
#include <thread>

#ifdef DYNCONTACT_WITH_MPI
#include <mpi.h>
#endif

#include "errors.hpp"
#include "interrupt.hpp"

namespace dc::table {
namespace {

/// The integer in environment variable `name`, or `fallback` when unset or not a number.
int env_int(const char* name, int fallback) {
  const char* v = std::getenv(name);
  if (!v || !*v) return fallback;
  char* end = nullptr;
  const long n = std::strtol(v, &end, 10);
  return *end == '\0' ? static_cast<int>(n) : fallback;
}

/// Worker threads of this process: DYNCONTACT_THREADS, else the hardware's cores; at most
/// one per unit.
int local_threads(std::size_t units) {
  int n = env_int("DYNCONTACT_THREADS", static_cast<int>(std::thread::hardware_concurrency()));
  n = std::max(1, n);
  return static_cast<int>(std::min<std::size_t>(static_cast<std::size_t>(n), std::max<std::size_t>(units, 1)));
}

nlohmann::json run_unit(const std::function<nlohmann::json(std::size_t)>& work, std::size_t unit) {
  try {
    return work(unit);
  } catch (const Interrupted&) {  // not finished: no result
    return nlohmann::json();
  } catch (const std::exception& e) {
    return {{"error", e.what()}};
  } catch (...) {
    return {{"error", "unknown exception"}};
  }
}

/// The next unit to hand out (local threads and remote ranks alike), -1 when none is left or
/// an interrupt was requested.
class UnitQueue {
 public:
  explicit UnitQueue(std::size_t units) : units_(units) {}
  long long take() {
    std::lock_guard<std::mutex> lock(mutex_);
    return next_ < units_ && !interrupt_requested() ? static_cast<long long>(next_++) : -1;
  }
  /// Units handed out so far (fixed once an interrupt is requested).
  std::size_t handed_out() {
    std::lock_guard<std::mutex> lock(mutex_);
    return next_;
  }

 private:
  std::mutex mutex_;
  std::size_t next_ = 0;
  const std::size_t units_;
};

/// Results gathered on rank 0, in unit order. Every value passes through its JSON text (as a
/// remote one does), so a result does not depend on where it was computed.
class Gathered {
 public:
  explicit Gathered(std::size_t units) : values_(units) {}
  void put(std::size_t unit, const std::string& text) {
    nlohmann::json value = nlohmann::json::parse(text);
    {
      std::lock_guard<std::mutex> lock(mutex_);
      values_[unit] = std::move(value);
      ++finished_;
    }
    cv_.notify_all();
  }
  /// Waits up to `timeout` for a change; returns the number finished.
  std::size_t wait(std::chrono::milliseconds timeout, std::size_t seen) {
    std::unique_lock<std::mutex> lock(mutex_);
    cv_.wait_for(lock, timeout, [&] { return finished_ != seen; });
    return finished_;
  }
  std::vector<nlohmann::json> take() { return std::move(values_); }

 private:
  std::mutex mutex_;
  std::condition_variable cv_;
  std::vector<nlohmann::json> values_;
  std::size_t finished_ = 0;
};

#ifdef DYNCONTACT_WITH_MPI
constexpr int kTagResult = 1;  // rank -> 0: {"unit": u, "result": r} (u = -1: first request)
constexpr int kTagAssign = 2;  // 0 -> rank: the next unit, -1: stop

/// Rank 0: answers pending requests (storing the results they carry) without blocking.
/// Returns the number of ranks that were told to stop.
int serve_requests(UnitQueue& queue, Gathered& gathered) {
  int stopped = 0;
  for (;;) {
    int flag = 0;
    MPI_Status status;
    MPI_Iprobe(MPI_ANY_SOURCE, kTagResult, MPI_COMM_WORLD, &flag, &status);
    if (!flag) return stopped;
    int size = 0;
    MPI_Get_count(&status, MPI_CHAR, &size);
    std::string text(static_cast<std::size_t>(size), '\0');
    MPI_Recv(text.data(), size, MPI_CHAR, status.MPI_SOURCE, kTagResult, MPI_COMM_WORLD, MPI_STATUS_IGNORE);
    const nlohmann::json message = nlohmann::json::parse(text);
    const long long unit = message.at("unit").get<long long>();
    if (unit >= 0) gathered.put(static_cast<std::size_t>(unit), message.at("result").dump());
    long long next = queue.take();
    MPI_Send(&next, 1, MPI_LONG_LONG, status.MPI_SOURCE, kTagAssign, MPI_COMM_WORLD);
    if (next < 0) ++stopped;
  }
}

/// Ranks other than 0: ask for a unit, solve it, send its result with the next request.
void remote_worker(const std::function<nlohmann::json(std::size_t)>& work) {
  nlohmann::json message = {{"unit", -1}};
  for (;;) {
    const std::string text = message.dump();
    MPI_Send(text.data(), static_cast<int>(text.size()), MPI_CHAR, 0, kTagResult, MPI_COMM_WORLD);
    long long unit = -1;
    MPI_Recv(&unit, 1, MPI_LONG_LONG, 0, kTagAssign, MPI_COMM_WORLD, MPI_STATUS_IGNORE);
    if (unit < 0) return;
    message = {{"unit", unit}, {"result", run_unit(work, static_cast<std::size_t>(unit))}};
  }
}
#endif

}  // namespace

LaunchRank launch_rank() {
  LaunchRank r;
  // Open MPI's mpirun, then MPICH/Hydra and PMI launchers.
  for (auto [rank, size] : {std::pair{"OMPI_COMM_WORLD_RANK", "OMPI_COMM_WORLD_SIZE"}, std::pair{"PMI_RANK", "PMI_SIZE"}}) {
    const int n = env_int(size, 0);
    if (n > 0) {
      r.rank = env_int(rank, 0);
      r.size = n;
      return r;
    }
  }
  return r;
}

bool built_with_mpi() {
#ifdef DYNCONTACT_WITH_MPI
  return true;
#else
  return false;
#endif
}

std::vector<nlohmann::json> run_distributed(std::size_t units, const std::function<nlohmann::json(std::size_t)>& work,
                                            const std::function<void(std::size_t, std::size_t)>& done) {
  const LaunchRank launched = launch_rank();
  int rank = 0, size = 1;
#ifdef DYNCONTACT_WITH_MPI
  if (launched.size > 1) {
    int provided = 0;
    MPI_Init_thread(nullptr, nullptr, MPI_THREAD_FUNNELED, &provided);
    MPI_Comm_rank(MPI_COMM_WORLD, &rank);
    MPI_Comm_size(MPI_COMM_WORLD, &size);
  }
#else
  if (launched.size > 1)
    throw InputError("mpirun", "this dyncontact was built without MPI (DYNCONTACT_WITH_MPI off): run it without "
                               "mpirun (it uses the cores of this machine with threads), or rebuild with Open MPI");
#endif
  if (rank != 0) {
#ifdef DYNCONTACT_WITH_MPI
    remote_worker(work);
    MPI_Finalize();
#endif
    return {};
  }

  UnitQueue queue(units);
  Gathered gathered(units);
  // Under MPI rank 0's main thread serves the other ranks, and one thread of it works.
  const int threads = size > 1 ? 1 : local_threads(units);
  std::vector<std::thread> pool;
  for (int t = 0; t < threads; ++t)
    pool.emplace_back([&] {
      for (long long u; (u = queue.take()) >= 0;)
        gathered.put(static_cast<std::size_t>(u), run_unit(work, static_cast<std::size_t>(u)).dump());
    });
  int remote_active = size - 1;
  std::size_t finished = 0, reported = 0;
  if (done) done(0, units);
  // Until every unit is finished, or after an interrupt every unit handed out.
  const auto all_finished = [&] {
    return finished == units || (interrupt_requested() && finished == queue.handed_out());
  };
  while (!all_finished() || remote_active > 0) {
#ifdef DYNCONTACT_WITH_MPI
    if (size > 1) remote_active -= serve_requests(queue, gathered);
#endif
    finished = gathered.wait(std::chrono::milliseconds(size > 1 ? 2 : 200), finished);
    if (finished != reported && done) done(finished, units);
    reported = finished;
  }
  for (auto& t : pool) t.join();
#ifdef DYNCONTACT_WITH_MPI
  if (size > 1) MPI_Finalize();
#endif
  return gathered.take();
}

}  // namespace dc::table
