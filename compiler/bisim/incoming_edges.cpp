#include "bisim/incoming_edges.hpp"

#include <algorithm>
#include <bit>

namespace oasis::bisim {

using model::ChoiceIndex;
using model::EdgeIndex;
using model::StateIndex;

IncomingEdges::IncomingEdges(const model::TransitionMatrix& matrix, bool allow_packed) {
  count(matrix);
  build_records(matrix, allow_packed);
}

IncomingEdges IncomingEdges::offsets_only(const model::TransitionMatrix& matrix) {
  IncomingEdges incoming;
  incoming.count(matrix);
  return incoming;
}

void IncomingEdges::count(const model::TransitionMatrix& matrix) {
  size_ = matrix.num_edges();
  begin_.assign(std::size_t{matrix.num_states} + 1, 0);
  for (StateIndex t : matrix.edge_target)
    ++begin_[t + 1];
  for (std::size_t t = 0; t < matrix.num_states; ++t)
    begin_[t + 1] += begin_[t];
}

void IncomingEdges::build_records(const model::TransitionMatrix& matrix, bool allow_packed) {
  if (has_records_) return;
  has_records_ = true;
  const std::size_t num_choices = std::size_t{matrix.num_states} * matrix.num_actions;
  const ValueId largest_value =
      matrix.edge_probability.empty()
          ? 0
          : *std::max_element(matrix.edge_probability.begin(), matrix.edge_probability.end());
  value_bits_ = static_cast<std::uint32_t>(std::bit_width(largest_value));
  const auto choice_bits =
      static_cast<std::uint32_t>(std::bit_width(std::max<std::size_t>(num_choices, 1) - 1));
  packed_ = allow_packed && value_bits_ + choice_bits <= 32 && value_bits_ < 32;
  if (packed_) {
    value_mask_ = (std::uint32_t{1} << value_bits_) - 1;
    packed_records_.resize(size_);
    fill(matrix, [this](EdgeIndex at, ChoiceIndex c, ValueId p) {
      packed_records_[at] = (c << value_bits_) | p;
    });
  } else {
    wide_records_.resize(size_);
    fill(matrix, [this](EdgeIndex at, ChoiceIndex c, ValueId p) { wide_records_[at] = {c, p}; });
  }
}

// Places every edge of `matrix` at the next free slot of its target, in choice order.
template <typename Store>
void IncomingEdges::fill(const model::TransitionMatrix& matrix, Store store) {
  HugeArray<EdgeIndex> cursor(begin_.begin(), begin_.end() - 1);
  const std::size_t num_choices = std::size_t{matrix.num_states} * matrix.num_actions;
  for (ChoiceIndex c = 0; c < num_choices; ++c) {
    for (EdgeIndex e = matrix.choice_begin[c]; e < matrix.choice_begin[c + 1]; ++e) {
      store(cursor[matrix.edge_target[e]]++, c, matrix.edge_probability[e]);
    }
  }
}

}  // namespace oasis::bisim
