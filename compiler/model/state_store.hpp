#pragma once
// The set of states found during exploration, each a valuation of bounded integer variables
// packed into 64-bit words, numbered in the order they were found. A flat open-addressing
// table maps packed keys to indices: no per-state heap node. Each slot holds the key's first
// word beside the index, so that a lookup touches one cache line of the table and, when the
// variables fit in one word (most models), nothing else: lookups are most of exploration's
// time, and each one that misses the cache costs the same as a dozen guard evaluations.

#include <cstdint>
#include <span>
#include <utility>
#include <vector>

#include "model/model_ir.hpp"
#include "support/huge_page_allocator.hpp"

namespace oasis::model {

class StateStore {
 public:
  explicit StateStore(const std::vector<DiscreteVariable>& variables);

  [[nodiscard]] std::uint32_t size() const { return count_; }
  [[nodiscard]] std::size_t words_per_state() const { return words_; }

  // The packed key of a state found earlier.
  [[nodiscard]] std::span<const std::uint64_t> key_of(std::uint32_t state) const {
    return {keys_.data() + std::size_t{state} * words_, words_};
  }

  // Packs `valuation` (every value within its variable's bounds) into `key`.
  void pack(Valuation valuation, std::span<std::uint64_t> key) const;
  void unpack(std::uint32_t state, std::span<std::int64_t> valuation) const;
  // Sets variable `v` to `value` (within its bounds) in a packed key: a successor is its
  // source's key with the updated variables changed, with no valuation packed whole.
  void set(std::span<std::uint64_t> key, std::size_t v, std::int64_t value) const {
    const Field& f = fields_[v];
    key[f.word] = (key[f.word] & ~(f.mask << f.shift)) |
                  ((static_cast<std::uint64_t>(value - f.low) & f.mask) << f.shift);
  }
  // Whether `key` is that of `state` (a self-loop needs no lookup).
  [[nodiscard]] bool is_key_of(std::uint32_t state, std::span<const std::uint64_t> key) const {
    const std::uint64_t* stored = keys_.data() + std::size_t{state} * words_;
    for (std::size_t i = 0; i < words_; ++i) {
      if (stored[i] != key[i]) return false;
    }
    return true;
  }

  // Starts fetching the table slot where `key` would be, for an insert() soon after: a
  // caller with several keys at hand prefetches them all so that their cache misses overlap.
  // A key among the recent states needs no slot.
  void prefetch(std::span<const std::uint64_t> key) const {
    const std::uint64_t h = hash(key);
    if (recent_match(h, key)) return;
    __builtin_prefetch(&slots_[h & (slots_.size() - 1)]);
  }

  // The index of the state with this key, adding it when new: {index, inserted}.
  std::pair<std::uint32_t, bool> insert(std::span<const std::uint64_t> key);

 private:
  struct Field {
    std::size_t word;
    unsigned shift;
    std::uint64_t mask;
    std::int64_t low;
  };

  [[nodiscard]] std::uint64_t hash(std::span<const std::uint64_t> key) const;
  [[nodiscard]] bool key_equals(std::uint32_t state, std::span<const std::uint64_t> key) const;
  void grow();

  struct Slot {
    std::uint64_t first_word = 0;  // key[0] of the state
    std::uint32_t state = 0;       // its index + 1; 0 marks an empty slot
  };

  // Where `key` is, or the empty slot where it belongs.
  [[nodiscard]] std::size_t find_slot(std::uint64_t hash, std::span<const std::uint64_t> key) const;

  // Whether `key` (of hash `h`) is the state remembered in recent_.
  [[nodiscard]] bool recent_match(std::uint64_t h, std::span<const std::uint64_t> key) const {
    const Slot& slot = recent_[h & (kRecentSlots - 1)];
    return slot.state != 0 && slot.first_word == key[0] &&
           (words_ == 1 || key_equals(slot.state - 1, key));
  }

  // Recently found or looked-up states, direct-mapped by hash: a breadth-first search looks
  // a state up mostly soon after finding it (its neighbours are explored a few layers
  // later), and a hit here is in the cache where a slot of the table, at random in a large
  // array, is a miss to memory. It is a copy: the table alone decides what is stored.
  // 2^15 slots are 512 KiB, half of a core's L2 on the machine this was tuned on.
  static constexpr std::size_t kRecentSlots = std::size_t{1} << 15;

  std::vector<Field> fields_;
  std::size_t words_ = 1;
  std::uint32_t count_ = 0;
  std::vector<std::uint64_t> keys_;                   // count_ * words_
  std::vector<Slot, HugePageAllocator<Slot>> slots_;  // a power of two, at most half full
  std::vector<Slot> recent_;                          // kRecentSlots
};

}  // namespace oasis::model
