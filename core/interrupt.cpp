#include "interrupt.hpp"

namespace dc {
namespace {

// -1: no request; otherwise the signal number (0 for a request not from a signal).
std::atomic<int> g_request{-1};
static_assert(std::atomic<int>::is_always_lock_free, "the signal handler needs a lock-free flag");
std::atomic<const char*> g_section{nullptr};

}  // namespace

void request_interrupt(int signal) noexcept { g_request.store(signal < 0 ? 0 : signal, std::memory_order_relaxed); }

bool interrupt_requested() noexcept { return g_request.load(std::memory_order_relaxed) >= 0; }

int interrupt_signal() noexcept {
  const int s = g_request.load(std::memory_order_relaxed);
  return s > 0 ? s : 0;
}

void clear_interrupt() noexcept { g_request.store(-1, std::memory_order_relaxed); }

void throw_if_interrupted() {
  if (interrupt_requested()) throw Interrupted{interrupt_signal()};
}

NonPollingSection::NonPollingSection(const char* what) : previous_(nullptr) {
  throw_if_interrupted();
  previous_ = g_section.exchange(what);
}

NonPollingSection::~NonPollingSection() { g_section.store(previous_); }

const char* open_non_polling_section() noexcept { return g_section.load(); }

}  // namespace dc
