#include "python/signal_watch.hpp"

#include <pybind11/pybind11.h>

#include <atomic>
#include <condition_variable>
#include <exception>
#include <mutex>
#include <optional>
#include <thread>

namespace py = pybind11;

namespace dda::python {
namespace {

// Under the GIL: runs the pending signal handlers; the exception one raised, if any.
std::optional<py::error_already_set> raised_by_signal_handlers() {
  py::gil_scoped_acquire acquire;
  if (PyErr_CheckSignals() == 0) return std::nullopt;
  return py::error_already_set();
}

}  // namespace

void call_on_this_thread(const std::function<void(const StopQuery&)>& work) {
  std::optional<py::error_already_set> raised;
  {
    py::gil_scoped_release release;
    auto last = std::chrono::steady_clock::now();
    const StopQuery stop = [&] {
      if (raised) return true;
      const auto now = std::chrono::steady_clock::now();
      if (now - last < kSignalPollInterval) return false;
      last = now;
      raised = raised_by_signal_handlers();
      return raised.has_value();
    };
    work(stop);
  }
  if (raised) throw *raised;
}

void call_on_worker(const std::function<void(const StopQuery&)>& work) {
  std::optional<py::error_already_set> raised;
  std::exception_ptr failure;
  {
    py::gil_scoped_release release;
    std::atomic<bool> stop_asked{false};
    std::mutex mutex;
    std::condition_variable finished;
    bool done = false;
    std::thread worker([&] {
      try {
        work([&] { return stop_asked.load(); });
      } catch (...) {
        failure = std::current_exception();
      }
      const std::lock_guard<std::mutex> lock(mutex);
      done = true;
      finished.notify_one();
    });
    std::unique_lock<std::mutex> lock(mutex);
    while (!finished.wait_for(lock, kSignalPollInterval, [&] { return done; })) {
      if (raised) continue;  // asked to stop already: wait for the work to end
      lock.unlock();
      raised = raised_by_signal_handlers();
      if (raised) stop_asked = true;
      lock.lock();
    }
    lock.unlock();
    worker.join();
  }
  if (raised) throw *raised;
  if (failure) std::rethrow_exception(failure);
}

}  // namespace dda::python
