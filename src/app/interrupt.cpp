#include "app/interrupt.hpp"

#include <csignal>

namespace dda {
namespace {

volatile std::sig_atomic_t received = 0;

void on_interrupt(int signal) {
  received = signal;
  std::signal(signal, SIG_DFL);  // a second one ends the program at once
}

}  // namespace

void watch_for_interrupts() {
  std::signal(SIGINT, on_interrupt);
  std::signal(SIGTERM, on_interrupt);
}

int interrupt_signal() { return received; }

int interrupted_exit_code() { return 128 + received; }

}  // namespace dda
