#pragma once
// SIGINT/SIGTERM for the command line: the handlers only raise dc's interrupt flag
// (core/interrupt.hpp); a second signal of the same kind ends the program at once.
namespace dc::cli {

/// Installs the handlers (once, at start-up).
void install_interrupt_handlers();

/// The exit code of an interrupted run: 128 + the signal (130 SIGINT, 143 SIGTERM).
int interrupted_exit_code();

}  // namespace dc::cli
