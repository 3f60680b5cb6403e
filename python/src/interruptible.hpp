#pragma once
// Long calls release the GIL and stop on Ctrl-C. The work runs on a thread of its own while
// the calling thread, without the GIL, waits for it and every 50 ms asks Python whether a
// signal came (PyErr_CheckSignals runs Python's handlers, which raise KeyboardInterrupt on
// SIGINT). When one did, the work is asked to stop: the compiler calls its progress callbacks
// now and then (exploration, refinement, the model checker's iterations), and the callbacks
// the module gives it throw `Interrupted` once asked. The work unwinds (a staged output
// directory is removed by its destructor: nothing half written), and the call raises the
// Python exception. Work between two callbacks finishes first, so small calls simply end.
//
// The work must not touch Python objects: it gets C++ values only.

#include <atomic>
#include <chrono>
#include <condition_variable>
#include <exception>
#include <mutex>
#include <optional>
#include <thread>
#include <utility>

#include <pybind11/pybind11.h>

namespace oasis::python {

// Thrown by a progress callback once the call was asked to stop.
struct Interrupted {};

class Cancellation {
 public:
  void request() { requested_.store(true, std::memory_order_relaxed); }
  // For progress callbacks: throws Interrupted once asked to stop.
  void check() const {
    if (requested_.load(std::memory_order_relaxed)) throw Interrupted{};
  }

 private:
  std::atomic<bool> requested_{false};
};

// Runs work(cancellation) on its own thread, the GIL released; returns its result or rethrows
// its exception here. Raises the pending Python exception (KeyboardInterrupt) when a signal
// handler raised one meanwhile.
template <typename Work>
auto run_interruptible(Work&& work) -> decltype(work(std::declval<const Cancellation&>())) {
  using Result = decltype(work(std::declval<const Cancellation&>()));
  Cancellation cancellation;
  std::optional<Result> result;
  std::exception_ptr failure;
  std::mutex lock;
  std::condition_variable finished;
  bool done = false;
  bool interrupted = false;
  {
    const pybind11::gil_scoped_release release;
    std::thread worker([&] {
      try {
        result.emplace(work(cancellation));
      } catch (...) {
        failure = std::current_exception();
      }
      const std::lock_guard guard(lock);
      done = true;
      finished.notify_one();
    });
    std::unique_lock waiting(lock);
    while (!finished.wait_for(waiting, std::chrono::milliseconds(50), [&] { return done; })) {
      if (interrupted) continue;  // asked already: wait for the work to unwind
      waiting.unlock();
      {
        const pybind11::gil_scoped_acquire acquire;
        if (PyErr_CheckSignals() != 0) interrupted = true;  // the exception stays pending
      }
      if (interrupted) cancellation.request();
      waiting.lock();
    }
    waiting.unlock();
    worker.join();
  }
  if (interrupted) throw pybind11::error_already_set();
  if (failure) std::rethrow_exception(failure);
  return std::move(*result);
}

}  // namespace oasis::python
