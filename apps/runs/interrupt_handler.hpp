#pragma once
// SIGINT/SIGTERM for the command line: a watchdog thread takes them (sigwait) and raises dc's
// interrupt flag (core/interrupt.hpp); a second signal ends the program at once. The signals and
// their unblocking in a child process: output/interrupt_signals.hpp.
#include <string>

namespace dc::runs {

/// How long an interrupt may go unnoticed inside a non-polling section (core/interrupt.hpp:
/// meshing, a sparse factorisation) before the watchdog ends the process (exit 128 + signal).
inline constexpr double kInterruptGraceSeconds = 0.5;

/// Blocks SIGINT and SIGTERM in the calling thread (and so in every thread it starts) and starts
/// the watchdog that takes them (once, at start-up, before any other thread).
void install_interrupt_handlers();

/// A file the watchdog writes (whole: a temporary renamed into place) before it ends the process,
/// e.g. an "interrupted" summary.json; an empty path clears it. Set before the work it covers.
void set_interrupt_last_file(const std::string& path, const std::string& text);

/// The exit code of an interrupted run: 128 + the signal (130 SIGINT, 143 SIGTERM).
int interrupted_exit_code();

}  // namespace dc::runs
