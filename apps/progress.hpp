#pragma once
// A progress line on stderr for solves that take longer than about a second.
// On a terminal the line is rewritten in place; otherwise a line is printed every few
// seconds. Backends feed iteration/objective/residual through callback(); the elapsed
// time is shown even when a backend reports nothing.
#include <chrono>
#include <condition_variable>
#include <cstddef>
#include <mutex>
#include <string>
#include <thread>

#include "quadratic_program.hpp"

namespace dc::cli {

class Progress {
 public:
  explicit Progress(std::string label, bool enabled = true);
  ~Progress();
  Progress(const Progress&) = delete;
  Progress& operator=(const Progress&) = delete;

  /// The callback to hand to the solver (valid while this object lives).
  ProgressCallback callback();
  /// Runs of many points (table, sweep): `done` of `total` finished; the line then shows the
  /// count of `what` ("points", "runs") and the time left (estimated from the time per finished one).
  void count(std::size_t done, std::size_t total, const char* what = "points");
  /// Stops the reporter; prints the final time if a progress line was shown.
  void finish();

 private:
  void run();
  std::string line(double elapsed) const;

  std::string label_;
  bool enabled_;
  bool tty_;
  std::chrono::steady_clock::time_point start_;
  mutable std::mutex mutex_;
  std::condition_variable cv_;
  bool stop_ = false;
  bool shown_ = false;
  bool have_info_ = false;
  ProgressInfo info_;
  std::size_t done_ = 0, total_ = 0;
  const char* what_ = "points";
  std::thread thread_;
};

}  // namespace dc::cli
