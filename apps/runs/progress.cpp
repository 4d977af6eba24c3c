#include "progress.hpp"

#include <unistd.h>

#include <cmath>
#include <cstdio>
#include <iostream>

namespace dc::runs {

Progress::Progress(std::string label, bool enabled)
    : label_(std::move(label)),
      enabled_(enabled),
      tty_(isatty(STDERR_FILENO) != 0),
      start_(std::chrono::steady_clock::now()) {
  if (enabled_) thread_ = std::thread([this] { run(); });
}

Progress::~Progress() { finish(); }

ProgressCallback Progress::callback() {
  return [this](const ProgressInfo& info) {
    const double now = std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
    std::lock_guard<std::mutex> lock(mutex_);
    // A new solve (the iteration count starts again, another target) or a larger residual
    // restarts the rate's reference.
    const bool new_solve = !have_info_ || info.iteration < info_.iteration || info.target != info_.target ||
                           info.step != info_.step;
    if (new_solve || info.residual >= rate_residual_) {
      rate_from_ = now;
      rate_residual_ = info.residual;
    }
    info_ = info;
    info_at_ = now;
    have_info_ = true;
    if (info.steps > 0) {  // a history: step `step` of `steps` under way
      share_ = Share::count;
      done_ = info.step;
      total_ = info.steps;
      what_ = "steps";
    }
  };
}

void Progress::count(std::size_t done, std::size_t total, const char* what) {
  std::lock_guard<std::mutex> lock(mutex_);
  share_ = Share::count;
  done_ = static_cast<double>(done);
  total_ = static_cast<double>(total);
  what_ = what;
}

void Progress::time(double t, double t_end) {
  std::lock_guard<std::mutex> lock(mutex_);
  share_ = Share::time;
  done_ = t;
  total_ = t_end;
}

double Progress::solve_time_left() const {
  const double r = info_.residual, target = info_.target;
  if (!have_info_ || !(target > 0.0) || !(r > target) || !(rate_residual_ > r) || !(info_at_ > rate_from_))
    return -1.0;
  // log-linear convergence: the decades still to go at the decades per second so far.
  return (info_at_ - rate_from_) * std::log(r / target) / std::log(rate_residual_ / r);
}

std::string Progress::line(double elapsed) const {
  char buf[320];
  std::string text = label_;
  auto add = [&](const char* format, auto... values) {
    std::snprintf(buf, sizeof buf, format, values...);
    text += buf;
  };
  add(": %.1f s", elapsed);
  double left = -1.0;
  if (share_ == Share::time && total_ > 0.0) {
    add(", t = %.4g of %.4g s", done_, total_);
    if (done_ > 0.0) left = elapsed * (total_ - done_) / done_;
  } else if (share_ == Share::count && total_ > 0.0) {
    add(", %.0f of %.0f %s done", done_, total_, what_);
    if (done_ > 0.0) left = elapsed * (total_ - done_) / done_;
  }
  // A single solve, or the step of a history under way: its iteration and residual. Not every
  // solver reports its objective while it runs (0 then): shown only when it does.
  if (have_info_ && share_ != Share::time && (share_ == Share::none || info_.steps > 0)) {
    add(", iteration %d", info_.iteration);
    if (info_.objective != 0.0) add(", objective %.6g", info_.objective);
    add(", residual %.2e", info_.residual);
    if (share_ == Share::none) left = solve_time_left();
  }
  if (left >= 0.0) add(", about %.0f s left", left);
  return text;
}

void Progress::run() {
  using namespace std::chrono;
  std::unique_lock<std::mutex> lock(mutex_);
  double last_print = -1e9;
  while (!stop_) {
    cv_.wait_for(lock, milliseconds(tty_ ? 200 : 500));
    if (stop_) break;
    const double elapsed = duration<double>(steady_clock::now() - start_).count();
    if (elapsed < 1.0) continue;
    if (tty_) {
      std::cerr << "\r\033[K" << line(elapsed) << std::flush;
      shown_ = true;
    } else if (elapsed - last_print >= 5.0 || !shown_) {
      std::cerr << line(elapsed) << '\n' << std::flush;
      last_print = elapsed;
      shown_ = true;
    }
  }
}

void Progress::finish() {
  if (!enabled_) return;
  {
    std::lock_guard<std::mutex> lock(mutex_);
    if (stop_) return;
    stop_ = true;
  }
  cv_.notify_all();
  if (thread_.joinable()) thread_.join();
  if (shown_) {
    const double elapsed = std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
    if (tty_) std::cerr << "\r\033[K";
    std::cerr << label_ << ": done in " << (static_cast<double>(static_cast<long>(elapsed * 10.0)) / 10.0) << " s\n"
              << std::flush;
  }
}

}  // namespace dc::runs
