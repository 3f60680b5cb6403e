#include "model/transition_stream.hpp"

#include <algorithm>
#include <stdexcept>
#include <utility>

namespace oasis::model {
namespace {

// Rows up to this length are sorted by insertion (most have one to four edges); longer ones
// by std::stable_sort. Both are stable, so the result is the same.
constexpr std::size_t kInsertionSortLimit = 32;

}  // namespace

void TransitionStream::throw_too_many_edges() {
  throw std::length_error("more than 2^32 transitions");
}

void TransitionStream::begin(ChoiceIndex choice) {
  close_row();
  std::vector<EdgeIndex>& begins = matrix_.choice_begin;
  if (choice < begins.size()) throw std::logic_error("TransitionStream: choices out of order");
  // Choices skipped since the last one have no edges: they begin (and end) here.
  if (choice >= begins.capacity())
    reserve_huge(begins, std::max<std::size_t>(begins.capacity() * 2, std::size_t{choice} + 1));
  begins.resize(std::size_t{choice} + 1, static_cast<EdgeIndex>(matrix_.edge_target.size()));
  row_begin_ = matrix_.edge_target.size();
}

TransitionMatrix TransitionStream::finish(std::uint32_t num_states, RationalPool& values) {
  close_row();
  const std::size_t num_choices = std::size_t{num_states} * num_actions_;
  if (matrix_.choice_begin.size() > num_choices) {
    throw std::logic_error("TransitionStream: a choice beyond the last state");
  }
  matrix_.num_states = num_states;
  matrix_.num_actions = num_actions_;
  reserve_huge(matrix_.choice_begin, num_choices + 1);
  matrix_.choice_begin.resize(num_choices + 1, static_cast<EdgeIndex>(matrix_.edge_target.size()));
  for (const Merge& merge : merges_)
    matrix_.edge_probability[merge.edge] = values.intern(merge.sum);
  merges_.clear();
  row_begin_ = 0;
  return std::exchange(matrix_, TransitionMatrix{});
}

void TransitionStream::close_row() {
  const std::size_t end = matrix_.edge_target.size();
  if (end - row_begin_ < 2) return;
  const auto* targets = matrix_.edge_target.data();
  bool sorted = true;
  bool distinct = true;
  for (std::size_t e = row_begin_ + 1; e < end; ++e) {
    sorted = sorted && targets[e - 1] <= targets[e];
    distinct = distinct && targets[e - 1] != targets[e];
  }
  if (sorted && distinct) return;
  if (!sorted) {
    sort_row(row_begin_, end);
    distinct = true;
    for (std::size_t e = row_begin_ + 1; e < end; ++e)
      distinct = distinct && targets[e - 1] != targets[e];
  }
  if (!distinct) merge_row(row_begin_, end);
}

void TransitionStream::sort_row(std::size_t begin, std::size_t end) {
  StateIndex* targets = matrix_.edge_target.data();
  ValueId* probabilities = matrix_.edge_probability.data();
  if (end - begin > kInsertionSortLimit) {
    std::vector<std::pair<StateIndex, ValueId>> row;
    row.reserve(end - begin);
    for (std::size_t e = begin; e < end; ++e)
      row.emplace_back(targets[e], probabilities[e]);
    std::stable_sort(row.begin(), row.end(),
                     [](const auto& x, const auto& y) { return x.first < y.first; });
    for (std::size_t e = begin; e < end; ++e)
      std::tie(targets[e], probabilities[e]) = row[e - begin];
    return;
  }
  for (std::size_t e = begin + 1; e < end; ++e) {
    const StateIndex target = targets[e];
    const ValueId probability = probabilities[e];
    std::size_t i = e;
    for (; i > begin && targets[i - 1] > target; --i) {
      targets[i] = targets[i - 1];
      probabilities[i] = probabilities[i - 1];
    }
    targets[i] = target;
    probabilities[i] = probability;
  }
}

// Adds the probabilities of each run of equal targets into the run's first edge; the sums
// are interned in finish(). The row only shrinks, and it is the last one.
void TransitionStream::merge_row(std::size_t begin, std::size_t end) {
  StateIndex* targets = matrix_.edge_target.data();
  ValueId* probabilities = matrix_.edge_probability.data();
  std::size_t kept = begin;
  for (std::size_t i = begin; i < end;) {
    std::size_t j = i + 1;
    targets[kept] = targets[i];
    probabilities[kept] = probabilities[i];
    if (j < end && targets[j] == targets[i]) {
      Rational sum = (*values_)[probabilities[i]];
      for (; j < end && targets[j] == targets[i]; ++j)
        sum += (*values_)[probabilities[j]];
      merges_.push_back({static_cast<EdgeIndex>(kept), std::move(sum)});
    }
    ++kept;
    i = j;
  }
  matrix_.edge_target.resize(kept);
  matrix_.edge_probability.resize(kept);
}

}  // namespace oasis::model
