#pragma once
// A progress line on stderr for solves that take longer than about a second.
// On a terminal the line is rewritten in place; otherwise a line is printed every few
// seconds. Backends feed iteration/objective/residual through callback(); the elapsed
// time is shown even when a backend reports nothing. The time left: from the finished share
// of a run of many points, steps or simulated time; for one solve, from the rate at which its
// residual falls towards the residual it stops at (when the backend reports that target).
#include <chrono>
#include <condition_variable>
#include <cstddef>
#include <mutex>
#include <string>
#include <thread>

#include "quadratic_program.hpp"

namespace dc::runs {

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
  /// Runs in time: simulated time `t` of `t_end` (s) reached.
  void time(double t, double t_end);
  /// Stops the reporter; prints the final time if a progress line was shown.
  void finish();
  /// The progress line as shown `elapsed` seconds after the start.
  std::string line(double elapsed) const;

 private:
  void run();
  /// One solve: the seconds left at its residual's rate of decrease, or < 0 when not known.
  double solve_time_left() const;

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
  double info_at_ = 0.0;  ///< when info_ came (s since start)
  double rate_from_ = 0.0, rate_residual_ = 0.0;  ///< the current solve's largest residual, and when
  enum class Share { none, count, time } share_ = Share::none;
  double done_ = 0.0, total_ = 0.0;
  const char* what_ = "points";
  std::thread thread_;
};

}  // namespace dc::runs
