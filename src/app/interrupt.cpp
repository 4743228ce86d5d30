#include "app/interrupt.hpp"

#include <unistd.h>

#include <atomic>
#include <cstddef>
#include <csignal>

namespace dda {
namespace {

// Lock-free, so safe to set in the handler, and read by every thread (dda fos polls it from
// its trials' threads).
std::atomic<int> received{0};
static_assert(std::atomic<int>::is_always_lock_free);

std::atomic<const char*> at_once{nullptr};
static_assert(std::atomic<const char*>::is_always_lock_free);

void on_interrupt(int signal) {
  if (const char* message = at_once.load()) {
    // write and _exit are async-signal-safe; the length is counted here, without strlen.
    std::size_t n = 0;
    while (message[n] != '\0') ++n;
    const ssize_t ignored = ::write(STDERR_FILENO, message, n);
    (void)ignored;
    ::_exit(128 + signal);
  }
  received = signal;
  std::signal(signal, SIG_DFL);  // a second one ends the program at once
}

}  // namespace

void watch_for_interrupts() {
  std::signal(SIGINT, on_interrupt);
  std::signal(SIGTERM, on_interrupt);
}

void exit_at_once_on_interrupt(const char* message) { at_once = message; }

int interrupt_signal() { return received; }

int interrupted_exit_code() { return 128 + received; }

}  // namespace dda
