#pragma once
// Growth of large std::vectors that are filled one element at a time (an explorer's edge
// arrays, a reader's distributions): each new buffer is marked for transparent huge pages
// before anything is written to it, so that filling it costs one page fault per 2 MiB rather
// than one per 4 KiB. At 10^7 explored states those 4 KiB faults (not the zeroing of the
// pages, which stays) were about a sixth of exploration's time. The vectors stay
// std::vector, the type the matrices hold; the advice is only advice, which a kernel without
// transparent huge pages ignores.

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <vector>

#include <sys/mman.h>

namespace oasis {

// Marks the whole 2 MiB pages within [data, data + bytes) for transparent huge pages.
inline void advise_huge_pages(void* data, std::size_t bytes) {
  constexpr std::uintptr_t kHugePage = std::uintptr_t{2} << 20;
  const auto first = reinterpret_cast<std::uintptr_t>(data);
  const std::uintptr_t begin = (first + kHugePage - 1) & ~(kHugePage - 1);
  const std::uintptr_t end = (first + bytes) & ~(kHugePage - 1);
  // NOLINTNEXTLINE(performance-no-int-to-ptr): the page-aligned address within the buffer
  if (end > begin) ::madvise(reinterpret_cast<void*>(begin), end - begin, MADV_HUGEPAGE);
}

// Room for at least `capacity` elements in `values`, in a buffer advised as above when it is
// new and large (from 4 MiB up: below that no whole huge page is sure to fit).
template <typename T>
void reserve_huge(std::vector<T>& values, std::size_t capacity) {
  if (capacity <= values.capacity()) return;
  if (capacity * sizeof(T) < (std::size_t{4} << 20)) {
    values.reserve(capacity);
    return;
  }
  std::vector<T> bigger;
  bigger.reserve(capacity);
  advise_huge_pages(bigger.data(), capacity * sizeof(T));
  bigger.insert(bigger.end(), values.begin(), values.end());
  values.swap(bigger);
}

// Room for at least `size` elements, doubling the capacity through reserve_huge() when it
// is used up. (Growing faster would copy less, but the memory budget, RLIMIT_DATA, counts
// the capacity reserved and not only the pages written.)
template <typename T>
void grow_huge(std::vector<T>& values, std::size_t size) {
  if (size <= values.capacity()) return;
  reserve_huge(values, std::max({size, values.capacity() * 2, std::size_t{16}}));
}

// push_back, growing through grow_huge() when the capacity is used up.
template <typename T>
void push_back_huge(std::vector<T>& values, const T& value) {
  if (values.size() == values.capacity()) grow_huge(values, values.size() + 1);
  values.push_back(value);
}

}  // namespace oasis
