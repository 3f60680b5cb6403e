#pragma once
// Independent work items on a few threads: the contexts of a model are abstracted this way,
// each reading the shared model and writing only its own result slot.

#include <algorithm>
#include <atomic>
#include <cstddef>
#include <thread>
#include <vector>

namespace oasis {

// The threads to use for `items` items when the user asked for `jobs` (0: one per hardware
// thread): never more than there are items, never fewer than one.
inline std::size_t thread_count(unsigned jobs, std::size_t items) {
  const unsigned hardware = std::max(1U, std::thread::hardware_concurrency());
  return std::max<std::size_t>(1, std::min<std::size_t>(jobs == 0 ? hardware : jobs, items));
}

// Calls work(i) once for every i in [0, items), on thread_count(jobs, items) threads, the
// calling one included; returns when all are done. `work` must not throw.
template <class Work>
void parallel_for(std::size_t items, unsigned jobs, Work&& work) {
  std::atomic<std::size_t> next{0};
  auto worker = [&] {
    for (std::size_t i = next++; i < items; i = next++)
      work(i);
  };
  std::vector<std::thread> threads;
  for (std::size_t t = 1; t < thread_count(jobs, items); ++t)
    threads.emplace_back(worker);
  worker();
  for (std::thread& thread : threads)
    thread.join();
}

}  // namespace oasis
