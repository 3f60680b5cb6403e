#include "support/gmp_allocation.hpp"

#include <cstdlib>
#include <new>

#include <gmp.h>

namespace oasis {
namespace {

void* allocate_or_throw(std::size_t size) {
  void* memory = std::malloc(size);
  if (memory == nullptr) throw std::bad_alloc();
  return memory;
}

void* reallocate_or_throw(void* memory, std::size_t /*old_size*/, std::size_t new_size) {
  void* moved = std::realloc(memory, new_size);
  if (moved == nullptr) throw std::bad_alloc();  // `memory` is still GMP's, and still valid
  return moved;
}

void release(void* memory, std::size_t /*size*/) {
  std::free(memory);
}

}  // namespace

void make_gmp_throw_on_allocation_failure() {
  mp_set_memory_functions(allocate_or_throw, reallocate_or_throw, release);
}

}  // namespace oasis
