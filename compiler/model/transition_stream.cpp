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

void TransitionStream::grow_edges() {
  grow_huge(matrix_.edge_target, matrix_.edge_target.size() + 1);
  grow_huge(matrix_.edge_probability, matrix_.edge_target.capacity());
}

void TransitionStream::set_num_actions(std::uint32_t num_actions) {
  std::vector<EdgeIndex>& begins = matrix_.choice_begin;
  const std::size_t old_count = num_actions_;
  const std::size_t new_count = num_actions;
  if (begins.empty() || new_count == old_count) {
    num_actions_ = num_actions;
    return;
  }
  // Every state before the last one begun has all its old_count choices in `begins`; the
  // last one those up to the choice begun last (the next begin() or finish() adds the rest).
  const std::size_t last_state = (begins.size() - 1) / old_count;
  const std::size_t last_action = (begins.size() - 1) % old_count;
  const std::size_t size = last_state * new_count + last_action + 1;
  if (last_action >= new_count) throw_action_beyond_count();
  if (new_count < old_count) {
    // Choices move towards the front: in increasing order, none is overwritten unread. The
    // dropped actions of a state must have no edges: they begin where its next state does.
    for (std::size_t state = 0; state <= last_state; ++state) {
      if (state < last_state &&
          begins[state * old_count + new_count] != begins[(state + 1) * old_count])
        throw_action_beyond_count();
      const std::size_t count = state < last_state ? new_count : last_action + 1;
      for (std::size_t action = 0; action < count; ++action)
        begins[state * new_count + action] = begins[state * old_count + action];
    }
    begins.resize(size);
  } else {
    // Choices move towards the back: in decreasing order, none is overwritten unread. A
    // state's new actions have no edges: they begin where its next state's edges begin.
    grow_huge(begins, size);
    begins.resize(size);
    for (std::size_t c = size; c-- > 0;) {
      const std::size_t state = c / new_count;
      const std::size_t action = c % new_count;
      begins[c] =
          action < old_count ? begins[state * old_count + action] : begins[(state + 1) * new_count];
    }
  }
  num_actions_ = num_actions;
}

void TransitionStream::throw_action_beyond_count() {
  throw std::logic_error("TransitionStream: a choice of an action beyond the new count");
}

void TransitionStream::begin(ChoiceIndex choice) {
  close_row();
  std::vector<EdgeIndex>& begins = matrix_.choice_begin;
  if (choice < begins.size()) throw std::logic_error("TransitionStream: choices out of order");
  // Choices skipped since the last one have no edges: they begin (and end) here.
  grow_huge(begins, std::size_t{choice} + 1);
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
