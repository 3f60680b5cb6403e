#pragma once
// An allocator for large arrays read at random (hash tables): from 2 MiB up, the memory is
// aligned to 2 MiB and marked for transparent huge pages (madvise), so that a random access
// is rarely also a TLB miss. Smaller arrays come from the ordinary allocator. Where the kernel
// does not give huge pages the advice is ignored, and the array works as any other.

#include <cstddef>
#include <cstdlib>
#include <new>

#include <sys/mman.h>

namespace oasis {

template <typename T>
class HugePageAllocator {
 public:
  using value_type = T;  // NOLINT(readability-identifier-naming): the allocator interface
  static constexpr std::size_t kHugePage = std::size_t{2} << 20;

  HugePageAllocator() = default;
  template <typename U>
  explicit HugePageAllocator(const HugePageAllocator<U>& /*other*/) {}

  T* allocate(std::size_t n) {
    const std::size_t bytes = n * sizeof(T);
    if (bytes < kHugePage) return std::allocator<T>().allocate(n);
    const std::size_t rounded = (bytes + kHugePage - 1) / kHugePage * kHugePage;
    void* memory = std::aligned_alloc(kHugePage, rounded);
    if (memory == nullptr) throw std::bad_alloc();
    ::madvise(memory, rounded, MADV_HUGEPAGE);  // advice only: failure changes nothing
    return static_cast<T*>(memory);
  }

  void deallocate(T* memory, std::size_t n) {
    if (n * sizeof(T) < kHugePage) {
      std::allocator<T>().deallocate(memory, n);
    } else {
      std::free(memory);
    }
  }

  template <typename U>
  bool operator==(const HugePageAllocator<U>& /*other*/) const {
    return true;
  }
};

}  // namespace oasis
