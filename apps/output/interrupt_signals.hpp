#pragma once
// The signals that interrupt a run: SIGINT and SIGTERM. The command line blocks them in its main
// thread and every thread it starts, and its watchdog takes them (runs/interrupt_handler.hpp);
// a child process (gnuplot, gnuplot_figures.cpp) gets them back before exec.
#include <signal.h>

namespace dc::output {

/// SIGINT and SIGTERM: blocked in the main thread and every thread it starts, and taken by the
/// watchdog with sigtimedwait, so no library's handler (Gmsh's, METIS's: GKlib takes SIGTERM for
/// its own errors) can swallow them.
sigset_t interrupt_signals();

/// For a child process between fork and exec: SIGINT and SIGTERM delivered again (async-signal-safe).
void unblock_interrupt_signals();

}  // namespace dc::output
