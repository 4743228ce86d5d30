// SIGINT (Ctrl-C) and SIGTERM for the long commands: the first one sets a flag that the
// command polls, so it stops at the end of its current step or increment and keeps and
// indexes what it wrote; a second one ends the program at once (the default action).
#pragma once

namespace dda {

// Installs the handlers (once).
void watch_for_interrupts();

// While a message is set, SIGINT or SIGTERM ends the program at once instead: the message
// is written to standard error and the exit code is 128 + the signal. For work that cannot
// stop at a step of its own (dda cut inside CGAL's arrangement, seconds to minutes) and that
// has nothing half-written (its files go to a temporary name first: the mode is off while
// they are written). nullptr: back to the flag.
void exit_at_once_on_interrupt(const char* message);

// The signal received (SIGINT or SIGTERM), or 0.
int interrupt_signal();

// The exit code of a command stopped by that signal: 128 + its number, as a shell reports
// a program killed by it (130 for SIGINT, 143 for SIGTERM).
int interrupted_exit_code();

}  // namespace dda
