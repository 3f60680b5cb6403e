#pragma once
// The reverse of a TransitionMatrix, for refinement: for every state t, the (choice,
// probability) of each edge into t, grouped by t.
//
// It is the largest structure refinement builds (one record per edge), so a record is packed
// into 32 bits whenever the choice index and the probability id fit there together: 10^7
// choices take 24 bits and leave 8 for up to 256 distinct probabilities, which covers the
// models this tool meets. Otherwise a record takes 64 bits. The choice in this packing costs
// one shift; the refinement that reads the records is bound by cache misses, not by that.

#include <cstdint>
#include <vector>

#include "model/explicit_model.hpp"
#include "support/huge_page_allocator.hpp"

namespace oasis::bisim {

class IncomingEdges {
 public:
  // The offsets and the records. `allow_packed` false keeps 64-bit records even where 32
  // would do (for tests).
  explicit IncomingEdges(const model::TransitionMatrix& matrix, bool allow_packed = true);
  // The offsets alone (begin, end, size): the records are the larger part by far, and a
  // refinement done wholly by forward passes never reads them. build_records() adds them.
  static IncomingEdges offsets_only(const model::TransitionMatrix& matrix);
  // For a `matrix` these offsets were built from; once (later calls do nothing).
  void build_records(const model::TransitionMatrix& matrix, bool allow_packed = true);
  [[nodiscard]] bool has_records() const { return has_records_; }

  // The edges into t are [begin(t), end(t)).
  [[nodiscard]] model::EdgeIndex begin(model::StateIndex t) const { return begin_[t]; }
  [[nodiscard]] model::EdgeIndex end(model::StateIndex t) const { return begin_[t + 1]; }
  // Asks for t's range to be brought into the cache, for a walk about to reach t.
  void prefetch(model::StateIndex t) const { __builtin_prefetch(&begin_[t]); }
  [[nodiscard]] std::size_t size() const { return size_; }
  [[nodiscard]] bool packed() const { return packed_; }

  [[nodiscard]] model::ChoiceIndex choice(model::EdgeIndex e) const {
    return packed_ ? packed_records_[e] >> value_bits_ : wide_records_[e].choice;
  }
  [[nodiscard]] ValueId probability(model::EdgeIndex e) const {
    return packed_ ? packed_records_[e] & value_mask_ : wide_records_[e].probability;
  }

 private:
  struct WideRecord {
    model::ChoiceIndex choice;
    ValueId probability;
  };

  IncomingEdges() = default;
  void count(const model::TransitionMatrix& matrix);
  template <typename Store>
  void fill(const model::TransitionMatrix& matrix, Store store);

  // On huge pages: building the records scatters every edge over all of them, and refinement
  // reads them at random; with 4 KiB pages most of those accesses also miss the TLB.
  template <typename T>
  using HugeArray = std::vector<T, HugePageAllocator<T>>;

  HugeArray<model::EdgeIndex> begin_;  // num_states + 1 offsets
  std::size_t size_ = 0;
  bool has_records_ = false;
  bool packed_ = false;
  std::uint32_t value_bits_ = 0;
  std::uint32_t value_mask_ = 0;
  HugeArray<std::uint32_t> packed_records_;  // choice << value_bits_ | probability
  HugeArray<WideRecord> wide_records_;
};

}  // namespace oasis::bisim
