#include "progress.hpp"

#include <unistd.h>

#include <cstdio>
#include <iostream>

namespace dc::cli {

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
    std::lock_guard<std::mutex> lock(mutex_);
    info_ = info;
    have_info_ = true;
  };
}

void Progress::count(std::size_t done, std::size_t total, const char* what) {
  std::lock_guard<std::mutex> lock(mutex_);
  done_ = done;
  total_ = total;
  what_ = what;
}

std::string Progress::line(double elapsed) const {
  char buf[256];
  if (total_ > 0) {
    if (done_ == 0)
      std::snprintf(buf, sizeof buf, "%s: %.1f s, 0 of %zu %s done", label_.c_str(), elapsed, total_, what_);
    else
      std::snprintf(buf, sizeof buf, "%s: %.1f s, %zu of %zu %s done, about %.0f s left", label_.c_str(), elapsed,
                    done_, total_, what_, elapsed * static_cast<double>(total_ - done_) / static_cast<double>(done_));
    return buf;
  }
  // Not every solver reports its objective while it runs (0 then): shown only when it does.
  if (have_info_ && info_.objective != 0.0)
    std::snprintf(buf, sizeof buf, "%s: %.1f s, iteration %d, objective %.6g, residual %.2e", label_.c_str(), elapsed,
                  info_.iteration, info_.objective, info_.residual);
  else if (have_info_)
    std::snprintf(buf, sizeof buf, "%s: %.1f s, iteration %d, residual %.2e", label_.c_str(), elapsed,
                  info_.iteration, info_.residual);
  else
    std::snprintf(buf, sizeof buf, "%s: %.1f s", label_.c_str(), elapsed);
  return buf;
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

}  // namespace dc::cli
