#pragma once
// The process's peak resident memory so far, as the kernel counts it (getrusage's
// ru_maxrss): what `quotient` reports and the benchmarks record.

#include <cstdint>

#include <sys/resource.h>

namespace oasis {

inline std::uint64_t peak_memory_kib() {
  rusage usage{};
  ::getrusage(RUSAGE_SELF, &usage);
  return static_cast<std::uint64_t>(usage.ru_maxrss);
}

inline double peak_memory_mib() {
  return static_cast<double>(peak_memory_kib()) / 1024.0;
}

}  // namespace oasis
