#pragma once
// Independent work items on a few threads: the contexts of a model are abstracted this way,
// each reading the shared model and writing only its own result slot.

#include <algorithm>
#include <atomic>
#include <cstddef>
#include <exception>
#include <mutex>
#include <thread>
#include <vector>

namespace oasis {

// The threads to use for `items` items when the user asked for `jobs` (0: one per hardware
// thread): never more than there are items, never fewer than one.
inline std::size_t thread_count(unsigned jobs, std::size_t items) {
  const unsigned hardware = std::max(1U, std::thread::hardware_concurrency());
  return std::max<std::size_t>(1, std::min<std::size_t>(jobs == 0 ? hardware : jobs, items));
}

// Calls work(i) once for every i in [0, items), on up to thread_count(jobs, items) threads,
// the calling one included; returns when all are done. If work(i) throws (std::bad_alloc when
// the memory budget runs out, common/command_line/memory_budget.hpp), no further item is started
// and the first exception is rethrown here once every thread has stopped; an exception escaping a
// std::thread would std::terminate the process instead. A thread that cannot be started
// leaves its share to the others.
template <class Work>
void parallel_for(std::size_t items, unsigned jobs, Work&& work) {
  std::atomic<std::size_t> next{0};
  std::mutex failure_lock;
  std::exception_ptr failure;
  auto worker = [&] {
    try {
      for (std::size_t i = next++; i < items; i = next++)
        work(i);
    } catch (...) {
      next = items;  // start nothing more
      const std::lock_guard lock(failure_lock);
      if (!failure) failure = std::current_exception();
    }
  };
  std::vector<std::thread> threads;
  try {
    threads.reserve(thread_count(jobs, items));
    for (std::size_t t = 1; t < thread_count(jobs, items); ++t)
      threads.emplace_back(worker);
  } catch (const std::exception&) {
    // Out of memory or of threads: the ones running (and this one) do all the work.
  }
  worker();
  for (std::thread& thread : threads)
    thread.join();
  if (failure) std::rethrow_exception(failure);
}

}  // namespace oasis
