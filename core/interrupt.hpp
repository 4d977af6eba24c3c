#pragma once
// Interrupting a long run (SIGINT/SIGTERM): the signal handler only raises a flag; the solver
// loops, marching steps and sweeps poll it and unwind with dc::Interrupted, so the command line
// can write what was finished and exit 128 + signal.
#include <atomic>

namespace dc {

/// Thrown where a run notices the interrupt. Deliberately not a std::exception: the
/// `catch (const std::exception&)` of a backend or its fallback must not swallow it.
struct Interrupted {
  int signal = 0;  ///< the signal that asked for it (0: requested otherwise, e.g. a test)
};

/// Raises the flag (async-signal-safe: one lock-free atomic store).
void request_interrupt(int signal) noexcept;
/// Whether an interrupt was requested.
bool interrupt_requested() noexcept;
/// The signal of the request (0 if none or not from a signal).
int interrupt_signal() noexcept;
/// Clears the flag (tests).
void clear_interrupt() noexcept;
/// Throws Interrupted when the flag is raised; cheap enough for every solver iteration.
void throw_if_interrupted();

/// A single call that cannot poll the flag (a mesher's, a sparse factorisation's): while one is
/// open, the command line's watchdog (apps/runs/interrupt_handler.hpp) ends the process when an
/// interrupt is not noticed within its grace period. Opening one throws Interrupted when the
/// flag is already raised. Not nested across threads: the innermost description is kept.
class NonPollingSection {
 public:
  explicit NonPollingSection(const char* what);
  ~NonPollingSection();
  NonPollingSection(const NonPollingSection&) = delete;
  NonPollingSection& operator=(const NonPollingSection&) = delete;

 private:
  const char* previous_;
};

/// The description of the open non-polling section ("meshing the body", ...), null when none.
const char* open_non_polling_section() noexcept;

}  // namespace dc
