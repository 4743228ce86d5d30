#include "app/interrupt.hpp"

#include <atomic>
#include <csignal>

namespace dda {
namespace {

// Lock-free, so safe to set in the handler, and read by every thread (dda fos polls it from
// its trials' threads).
std::atomic<int> received{0};
static_assert(std::atomic<int>::is_always_lock_free);

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
