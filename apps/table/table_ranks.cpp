#include "table_ranks.hpp"

#include <algorithm>
#include <chrono>
#include <condition_variable>
#include <cstdlib>
#include <exception>
#include <memory>
#include <mutex>
#include <string>
#include <thread>
#include <utility>

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

/// The transport between ranks that run_distributed uses under a launcher (none: threads only).
std::unique_ptr<RankTransport>& installed_transport() {
  static std::unique_ptr<RankTransport> transport;
  return transport;
}

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

void install_rank_transport(std::unique_ptr<RankTransport> transport) { installed_transport() = std::move(transport); }

bool built_with_mpi() { return installed_transport() != nullptr; }

std::vector<nlohmann::json> run_distributed(std::size_t units, const std::function<nlohmann::json(std::size_t)>& work,
                                            const std::function<void(std::size_t, std::size_t)>& done) {
  const LaunchRank launched = launch_rank();
  RankTransport* const transport = installed_transport().get();
  int rank = 0, size = 1;
  if (launched.size > 1) {
    if (transport == nullptr)
      throw InputError("mpirun", "this dyncontact was built without MPI (DYNCONTACT_WITH_MPI off): run it without "
                                 "mpirun (it uses the cores of this machine with threads), or rebuild with Open MPI");
    const LaunchRank joined = transport->start();
    rank = joined.rank;
    size = joined.size;
  }
  if (rank != 0) {
    transport->work([&](std::size_t unit) { return run_unit(work, unit); });
    transport->finish();
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
  const std::function<long long()> next_unit = [&] { return queue.take(); };
  const std::function<void(std::size_t, const std::string&)> store = [&](std::size_t unit, const std::string& text) {
    gathered.put(unit, text);
  };
  while (!all_finished() || remote_active > 0) {
    if (size > 1) remote_active -= transport->serve(next_unit, store);
    finished = gathered.wait(std::chrono::milliseconds(size > 1 ? 2 : 200), finished);
    if (finished != reported && done) done(finished, units);
    reported = finished;
  }
  for (auto& t : pool) t.join();
  if (size > 1) transport->finish();
  return gathered.take();
}

}  // namespace dc::table
