#include "interrupt_handler.hpp"

#include <fcntl.h>
#include <semaphore.h>
#include <unistd.h>

#include <cerrno>
#include <chrono>
#include <csignal>
#include <cstdio>
#include <mutex>
#include <thread>

#include "interrupt.hpp"

namespace dc::cli {
namespace {

sem_t g_signalled;  // posted by the handler (sem_post is async-signal-safe)
std::mutex g_last_file_mutex;
std::string g_last_path, g_last_text;

extern "C" void on_interrupt_signal(int signal) {
  dc::request_interrupt(signal);
  std::signal(signal, SIG_DFL);  // a second Ctrl-C ends the program without waiting
  sem_post(&g_signalled);
}

/// Writes the last file whole (temporary + rename); nothing on failure.
void write_last_file() {
  std::lock_guard<std::mutex> lock(g_last_file_mutex);
  if (g_last_path.empty()) return;
  const std::string temporary = g_last_path + ".partial-watchdog";
  const int fd = ::open(temporary.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
  if (fd < 0) return;
  std::size_t done = 0;
  while (done < g_last_text.size()) {
    const ssize_t n = ::write(fd, g_last_text.data() + done, g_last_text.size() - done);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) break;
    done += static_cast<std::size_t>(n);
  }
  const bool whole = ::close(fd) == 0 && done == g_last_text.size();
  if (!whole || std::rename(temporary.c_str(), g_last_path.c_str()) != 0) ::unlink(temporary.c_str());
}

/// After a signal: the main thread polls the flag and unwinds on its own, unless it sits in a
/// non-polling section (meshing, a factorisation) past the grace period; then the process ends
/// here, with the last file written.
void watchdog() {
  while (sem_wait(&g_signalled) != 0) {
  }
  using clock = std::chrono::steady_clock;
  const auto grace = std::chrono::duration<double>(kInterruptGraceSeconds);
  const char* section = nullptr;
  auto since = clock::now();
  for (;;) {
    std::this_thread::sleep_for(std::chrono::milliseconds(50));
    const char* now = open_non_polling_section();
    if (now == nullptr || now != section) {  // polling, or another section: the grace starts again
      section = now;
      since = clock::now();
      continue;
    }
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
    sem_init(&g_signalled, 0, 0);
    std::thread(watchdog).detach();
    struct sigaction action {};
    action.sa_handler = on_interrupt_signal;
    sigemptyset(&action.sa_mask);
    action.sa_flags = SA_RESTART;  // reads and writes in progress complete
    sigaction(SIGINT, &action, nullptr);
    sigaction(SIGTERM, &action, nullptr);
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

}  // namespace dc::cli
