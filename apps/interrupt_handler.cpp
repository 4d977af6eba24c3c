#include "interrupt_handler.hpp"

#include <csignal>

#include "interrupt.hpp"

namespace dc::cli {
namespace {

extern "C" void on_interrupt_signal(int signal) {
  dc::request_interrupt(signal);
  std::signal(signal, SIG_DFL);  // a second Ctrl-C ends the program without waiting
}

}  // namespace

void install_interrupt_handlers() {
  struct sigaction action {};
  action.sa_handler = on_interrupt_signal;
  sigemptyset(&action.sa_mask);
  action.sa_flags = SA_RESTART;  // reads and writes in progress complete
  sigaction(SIGINT, &action, nullptr);
  sigaction(SIGTERM, &action, nullptr);
}

int interrupted_exit_code() {
  const int signal = dc::interrupt_signal();
  return 128 + (signal > 0 ? signal : SIGINT);
}

}  // namespace dc::cli
