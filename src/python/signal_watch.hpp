// Long calls from Python (a run, a factor of safety, a cut) run without the GIL, so that
// other Python threads go on meanwhile, and stop when Ctrl-C arrives: Python's own signal
// handler only marks the signal, and the interpreter acts on it when C++ gives it the chance
// (PyErr_CheckSignals). These helpers give it that chance every kSignalPollInterval and turn
// a raised exception (KeyboardInterrupt) into a stop the solver's hooks understand, then
// raise it once the call has returned with what it had done complete.
#pragma once

#include <chrono>
#include <functional>

namespace dda::python {

// Asked by the work after each of its steps or trials: true means stop now.
using StopQuery = std::function<bool()>;

// Often enough that Ctrl-C answers at once to a person, seldom enough that taking the GIL
// back costs nothing next to a step.
inline constexpr std::chrono::milliseconds kSignalPollInterval{50};

// Runs `work` on the calling thread with the GIL released. Its stop query, asked from this
// thread only, takes the GIL back at most every kSignalPollInterval to run Python's signal
// handlers; once one raises, the query answers true, and the exception is raised when
// `work` has returned. An exception `work` throws passes through.
void call_on_this_thread(const std::function<void(const StopQuery&)>& work);

// Runs `work` on a thread of its own, for work whose stop query is asked from threads of its
// own (the factor of safety's trials) or that asks none (a cut): the calling thread waits
// without the GIL and runs the signal handlers every kSignalPollInterval; once one raises, the
// query answers true, and the exception is raised when `work` has returned. An exception
// `work` throws is thrown again here.
void call_on_worker(const std::function<void(const StopQuery&)>& work);

}  // namespace dda::python
