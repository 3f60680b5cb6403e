#pragma once
// The set of states found during exploration, each a valuation of bounded integer variables
// packed into 64-bit words, numbered in the order they were found. A flat open-addressing
// table maps packed keys to indices: no per-state heap node. A slot is 8 bytes, the index
// beside 32 bits of the key's hash, so that a lookup touches one cache line of the table and
// a key is read only when its hash matches. At 10^7 states a quarter of exploration's time
// was the kernel zeroing this table's fresh pages as it doubled: slots of 8 bytes and a table
// up to 3/4 full need a quarter of the memory that 16-byte slots half full did.

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
  // Whether `key` is that of `state` (a self-loop needs no lookup, nor a slot whose hash
  // matches another).
  [[nodiscard]] bool is_key_of(std::uint32_t state, std::span<const std::uint64_t> key) const {
    const std::uint64_t* stored = keys_.data() + std::size_t{state} * words_;
    for (std::size_t i = 0; i < words_; ++i) {
      if (stored[i] != key[i]) return false;
    }
    return true;
  }

  // Starts fetching the table slot where `key` would be, for an insert() soon after: a
  // caller with several keys at hand prefetches them all so that their cache misses overlap.
  // Its entry among the recent states is fetched too, not read: reading it here would wait
  // for it, itself often a miss. (The slot of a key found among them is fetched for nothing,
  // which costs no waiting.)
  void prefetch(std::span<const std::uint64_t> key) const {
    const std::uint64_t h = hash(key);
    __builtin_prefetch(&recent_[h & (kRecentSlots - 1)]);
    __builtin_prefetch(&slots_[h & (slots_.size() - 1)]);
  }

  // The index of the state with this key, adding it when new: {index, inserted}.
  std::pair<std::uint32_t, bool> insert(std::span<const std::uint64_t> key);

  // Frees the lookup table once exploration is over: the keys stay (key_of(), unpack()), and
  // the memory is reused for the model being built (at 10^7 states, 128 MiB fewer fresh
  // pages). No insert() or prefetch() may follow.
  void end_lookups();

 private:
  struct Field {
    std::size_t word;
    unsigned shift;
    std::uint64_t mask;
    std::int64_t low;
  };

  [[nodiscard]] std::uint64_t hash(std::span<const std::uint64_t> key) const;
  void grow();

  // A slot of the table. Its position comes from the hash's low bits and `hash_high` holds
  // the high ones, so that a key is compared only where they match.
  struct Slot {
    std::uint32_t hash_high = 0;
    std::uint32_t state = 0;  // its index + 1; 0 marks an empty slot
  };
  [[nodiscard]] static std::uint32_t hash_high(std::uint64_t h) {
    return static_cast<std::uint32_t>(h >> 32);
  }

  // Where `key` (of hash `h`) is, or the empty slot where it belongs.
  [[nodiscard]] std::size_t find_slot(std::uint64_t h, std::span<const std::uint64_t> key) const;
  // Puts state `state` (of hash `h`), not in the table, into its empty slot.
  void place(std::uint64_t h, std::uint32_t state);

  // A state remembered in recent_, with its key's first word (in the cache already).
  struct Recent {
    std::uint64_t first_word = 0;
    std::uint32_t state = 0;  // its index + 1; 0 marks an empty entry
  };

  // Whether `key` (of hash `h`) is the state remembered in recent_.
  [[nodiscard]] bool recent_match(std::uint64_t h, std::span<const std::uint64_t> key) const {
    const Recent& entry = recent_[h & (kRecentSlots - 1)];
    return entry.state != 0 && entry.first_word == key[0] &&
           (words_ == 1 || is_key_of(entry.state - 1, key));
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
  std::vector<Slot, HugePageAllocator<Slot>> slots_;  // a power of two, at most 3/4 full
  std::vector<Recent> recent_;                        // kRecentSlots
};

}  // namespace oasis::model
