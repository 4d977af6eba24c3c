#include "interrupt_handler.hpp"

#include <pthread.h>
#include <unistd.h>

#include <chrono>
#include <csignal>
#include <ctime>
#include <cstdio>
#include <exception>
#include <mutex>
#include <thread>

#include "interrupt.hpp"
#include "interrupt_signals.hpp"
#include "output_files.hpp"

namespace dc::runs {
namespace {

std::mutex g_last_file_mutex;
std::string g_last_path, g_last_text;

/// For a signal delivered to a thread started before main (a library's, with every signal open):
/// the flag only (async-signal-safe); the watchdog sees it.
extern "C" void on_interrupt_signal(int signal) { dc::request_interrupt(signal); }

/// Writes the last file whole (output/output_files.hpp); nothing on failure.
void write_last_file() {
  std::lock_guard<std::mutex> lock(g_last_file_mutex);
  if (g_last_path.empty()) return;
  try {
    output::write_file_whole(g_last_path, g_last_text);
  } catch (const std::exception&) {  // the process ends now either way
  }
}

/// Waits for a signal and raises the interrupt flag: the main thread polls it and unwinds on its
/// own, unless it sits in a non-polling section (meshing, a factorisation) past the grace period;
/// then the process ends here, with the last file written. A second signal ends it at once.
void watchdog() {
  const sigset_t set = output::interrupt_signals();
  const timespec poll{0, 50'000'000};
  while (!interrupt_requested()) {
    const int signal = sigtimedwait(&set, nullptr, &poll);
    if (signal > 0) dc::request_interrupt(signal);
  }
  using clock = std::chrono::steady_clock;
  const auto grace = std::chrono::duration<double>(kInterruptGraceSeconds);
  const char* section = nullptr;
  auto since = clock::now();
  for (;;) {
    const int again = sigtimedwait(&set, nullptr, &poll);
    if (again > 0) {
      std::fprintf(stderr, "interrupted again: stopped at once\n");
      _exit(128 + again);
    }
    const char* now = open_non_polling_section();
    if (now == nullptr || section == nullptr) {  // polling, or a section just opened: the grace starts
      section = now;
      since = clock::now();
      continue;
    }
    section = now;  // the innermost of nested sections, for the message
    if (clock::now() - since < grace) continue;
    write_last_file();
    std::fprintf(stderr, "interrupted while %s (which cannot stop midway): stopped there\n", section);
    std::fflush(stderr);
    _exit(interrupted_exit_code());
  }
}

}  // namespace

void install_interrupt_handlers() {
  static std::once_flag once;
  std::call_once(once, [] {
    const sigset_t set = output::interrupt_signals();
    pthread_sigmask(SIG_BLOCK, &set, nullptr);  // this thread and every thread started from it
    struct sigaction action {};
    action.sa_handler = on_interrupt_signal;
    sigemptyset(&action.sa_mask);
    action.sa_flags = SA_RESTART;
    sigaction(SIGINT, &action, nullptr);
    sigaction(SIGTERM, &action, nullptr);
    std::thread(watchdog).detach();
  });
}

void set_interrupt_last_file(const std::string& path, const std::string& text) {
  std::lock_guard<std::mutex> lock(g_last_file_mutex);
  g_last_path = path;
  g_last_text = text;
}

int interrupted_exit_code() {
  const int signal = dc::interrupt_signal();
  return 128 + (signal > 0 ? signal : SIGINT);
}

}  // namespace dc::runs
