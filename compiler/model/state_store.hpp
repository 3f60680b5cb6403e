#pragma once
// The set of states found during exploration, each a valuation of bounded integer variables
// packed into 64-bit words, numbered in the order they were found. A flat open-addressing
// table maps packed keys to indices: no per-state heap node, about 12 bytes per state for
// models whose variables fit in one word.

#include <cstdint>
#include <span>
#include <utility>
#include <vector>

#include "model/model_ir.hpp"

namespace oasis::model {

class StateStore {
 public:
  explicit StateStore(const std::vector<DiscreteVariable>& variables);

  [[nodiscard]] std::uint32_t size() const { return count_; }
  [[nodiscard]] std::size_t words_per_state() const { return words_; }

  // Packs `valuation` (every value within its variable's bounds) into `key`.
  void pack(Valuation valuation, std::span<std::uint64_t> key) const;
  void unpack(std::uint32_t state, std::span<std::int64_t> valuation) const;

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

  std::vector<Field> fields_;
  std::size_t words_ = 1;
  std::uint32_t count_ = 0;
  std::vector<std::uint64_t> keys_;   // count_ * words_
  std::vector<std::uint32_t> slots_;  // state index + 1; 0 marks an empty slot
};

}  // namespace oasis::model
