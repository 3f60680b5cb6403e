#include "model/state_store.hpp"

#include <algorithm>
#include <bit>
#include <stdexcept>

#include "support/hash.hpp"
#include "support/huge_page_growth.hpp"

namespace oasis::model {

StateStore::StateStore(const std::vector<DiscreteVariable>& variables) {
  std::size_t word = 0;
  unsigned used = 0;
  for (const DiscreteVariable& var : variables) {
    const auto span = static_cast<std::uint64_t>(var.high - var.low);
    const auto bits = static_cast<unsigned>(std::bit_width(span));
    if (used + bits > 64) {
      ++word;
      used = 0;
    }
    const std::uint64_t mask = bits == 64 ? ~std::uint64_t{0} : (std::uint64_t{1} << bits) - 1;
    fields_.push_back({word, used, mask, var.low});
    used += bits;
  }
  words_ = word + 1;
  slots_.resize(1024);
  recent_.resize(kRecentSlots);
}

void StateStore::pack(Valuation valuation, std::span<std::uint64_t> key) const {
  for (std::uint64_t& w : key)
    w = 0;
  for (std::size_t v = 0; v < fields_.size(); ++v) {
    const Field& f = fields_[v];
    key[f.word] |= (static_cast<std::uint64_t>(valuation[v] - f.low) & f.mask) << f.shift;
  }
}

void StateStore::unpack(std::uint32_t state, std::span<std::int64_t> valuation) const {
  const std::uint64_t* key = keys_.data() + std::size_t{state} * words_;
  for (std::size_t v = 0; v < fields_.size(); ++v) {
    const Field& f = fields_[v];
    valuation[v] = f.low + static_cast<std::int64_t>((key[f.word] >> f.shift) & f.mask);
  }
}

std::uint64_t StateStore::hash(std::span<const std::uint64_t> key) const {
  std::uint64_t h = 0x9e3779b97f4a7c15ULL;
  for (std::uint64_t w : key)
    h = mix_bits(h ^ w);
  return h;
}

std::size_t StateStore::find_slot(std::uint64_t h, std::span<const std::uint64_t> key) const {
  const std::size_t mask = slots_.size() - 1;
  const std::uint32_t high = hash_high(h);
  for (std::size_t i = h & mask;; i = (i + 1) & mask) {
    const Slot& slot = slots_[i];
    if (slot.state == 0) return i;
    if (slot.hash_high == high && is_key_of(slot.state - 1, key)) return i;
  }
}

void StateStore::place(std::uint64_t h, std::uint32_t state) {
  const std::size_t mask = slots_.size() - 1;
  std::size_t i = h & mask;
  while (slots_[i].state != 0)
    i = (i + 1) & mask;
  slots_[i] = {hash_high(h), state + 1};
}

std::pair<std::uint32_t, bool> StateStore::insert(std::span<const std::uint64_t> key) {
  const std::uint64_t h = hash(key);
  Recent& recent = recent_[h & (kRecentSlots - 1)];
  if (recent_match(h, key)) return {recent.state - 1, false};
  // Linear probing stays short up to 3/4 full: 8-byte slots, 8 to a cache line.
  if ((std::size_t{count_} + 1) * 4 > slots_.size() * 3) grow();
  Slot& slot = slots_[find_slot(h, key)];
  if (slot.state != 0) {
    recent = {key[0], slot.state};
    return {slot.state - 1, false};
  }
  if (count_ == UINT32_MAX - 1) throw std::length_error("more than 2^32 states");
  slot = {hash_high(h), count_ + 1};
  recent = {key[0], count_ + 1};
  grow_huge(keys_, keys_.size() + words_);
  keys_.insert(keys_.end(), key.begin(), key.end());
  return {count_++, true};
}

void StateStore::end_lookups() {
  slots_ = std::vector<Slot, HugePageAllocator<Slot>>();
  recent_ = std::vector<Recent>();
}

// The slots hold no keys: the keys, read in order, are hashed again into a table twice the
// size (a sequential read rather than a random one over the old table, which is freed first
// so that the two are never held together). Each slot written is at random in a table larger
// than the caches: the slots of a block of keys are fetched together, so that their misses
// overlap.
void StateStore::grow() {
  const std::size_t size = slots_.size() * 2;
  slots_ = std::vector<Slot, HugePageAllocator<Slot>>();
  slots_.resize(size);
  constexpr std::uint32_t kBlock = 16;
  std::uint64_t hashes[kBlock];
  for (std::uint32_t first = 0; first < count_; first += kBlock) {
    const std::uint32_t last = std::min(count_, first + kBlock);
    for (std::uint32_t s = first; s < last; ++s) {
      hashes[s - first] = hash(key_of(s));
      __builtin_prefetch(&slots_[hashes[s - first] & (size - 1)], 1);
    }
    for (std::uint32_t s = first; s < last; ++s)
      place(hashes[s - first], s);
  }
}

}  // namespace oasis::model
