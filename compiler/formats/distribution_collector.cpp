#include "formats/distribution_collector.hpp"

#include <algorithm>

namespace oasis::formats {

void DistributionCollector::reserve(std::size_t distributions, std::size_t edges) {
  sources_.reserve(distributions);
  actions_.reserve(distributions);
  if (kept_ == Kept::OffsetsAndPayloads) offsets_.reserve(distributions);
  if (kept_ != Kept::Nothing) payloads_.reserve(distributions);
  edge_begin_.reserve(distributions);
  targets_.reserve(edges);
  probabilities_.reserve(edges);
}

void DistributionCollector::begin(model::StateIndex source, model::ActionIndex action,
                                  SourceOffset offset, std::uint32_t payload) {
  begin(source, action);
  if (kept_ == Kept::OffsetsAndPayloads) offsets_.push_back(offset);
  if (kept_ != Kept::Nothing) payloads_.push_back(payload);
}

void DistributionCollector::begin(model::StateIndex source, model::ActionIndex action) {
  push_back_huge(sources_, source);
  push_back_huge(actions_, action);
  push_back_huge(edge_begin_, static_cast<model::EdgeIndex>(targets_.size()));
}

std::optional<model::TransitionMatrix> DistributionCollector::finish(
    std::uint32_t num_states, std::uint32_t num_actions, RationalPool& values,
    std::vector<Duplicate>& duplicates) {
  const std::size_t num_choices = std::size_t{num_states} * num_actions;
  model::TransitionMatrix matrix;
  matrix.num_states = num_states;
  matrix.num_actions = num_actions;
  // First the distribution of each choice, in the array that becomes choice_begin.
  std::vector<model::EdgeIndex>& owner = matrix.choice_begin;
  reserve_huge(owner, num_choices + 1);
  owner.assign(num_choices + 1, kNone);
  bool in_order = true;  // distributions in choice order
  std::size_t previous = 0;
  for (std::uint32_t d = 0; d < size(); ++d) {
    const std::size_t c = std::size_t{sources_[d]} * num_actions + actions_[d];
    if (owner[c] != kNone) {
      duplicates.push_back({owner[c], d});
      continue;
    }
    owner[c] = d;
    if (d > 0 && c < previous) in_order = false;
    previous = c;
  }
  if (!duplicates.empty()) return std::nullopt;
  if (in_order) {
    if (!sorted_) normalize_in_place(values);
    build_in_place(matrix);
  } else {
    build_copying(matrix, values);
  }
  // The edges' starts are in choice_begin now: freed before the caller builds more beside it.
  std::vector<model::EdgeIndex>().swap(edge_begin_);
  return matrix;
}

void DistributionCollector::release() {
  std::vector<model::StateIndex>().swap(sources_);
  std::vector<model::ActionIndex>().swap(actions_);
  std::vector<SourceOffset>().swap(offsets_);
  std::vector<std::uint32_t>().swap(payloads_);
  std::vector<model::EdgeIndex>().swap(edge_begin_);
}

// Distributions already in choice order with sorted targets: the collected edge arrays are
// the CSR arrays; only the choice offsets need filling in.
void DistributionCollector::build_in_place(model::TransitionMatrix& matrix) {
  std::vector<model::EdgeIndex>& begin = matrix.choice_begin;
  model::EdgeIndex next = static_cast<model::EdgeIndex>(targets_.size());
  begin.back() = next;
  for (std::size_t c = begin.size() - 1; c-- > 0;) {
    if (begin[c] != kNone) next = edge_begin_[begin[c]];
    begin[c] = next;
  }
  matrix.edge_target = std::move(targets_);
  matrix.edge_probability = std::move(probabilities_);
  targets_.clear();
  probabilities_.clear();
}

// The (target, probability) edges of distribution d, as collected.
void DistributionCollector::copy_distribution(
    std::uint32_t d, std::vector<std::pair<model::StateIndex, ValueId>>& row) const {
  const std::size_t last = d + 1 < size() ? edge_begin_[d + 1] : targets_.size();
  row.clear();
  for (std::size_t e = edge_begin_[d]; e < last; ++e)
    row.emplace_back(targets_[e], probabilities_[e]);
}

// Distributions in choice order, some with unsorted or repeated targets: each is sorted and
// merged where it lies. Merging only shrinks a distribution, so edges move towards the front
// and the arrays become the CSR arrays without a second copy of them (which, for a large
// file, would be the reader's peak).
void DistributionCollector::normalize_in_place(RationalPool& values) {
  std::vector<std::pair<model::StateIndex, ValueId>> row;
  std::size_t kept = 0;
  for (std::uint32_t d = 0; d < size(); ++d) {
    const std::size_t first = edge_begin_[d];
    const std::size_t last = d + 1 < size() ? edge_begin_[d + 1] : targets_.size();
    edge_begin_[d] = static_cast<model::EdgeIndex>(kept);
    // Most distributions are in order already: they only move towards the front.
    if (strictly_increasing(first, last)) {
      for (std::size_t e = first; e < last; ++e, ++kept) {
        targets_[kept] = targets_[e];
        probabilities_[kept] = probabilities_[e];
      }
      continue;
    }
    row.clear();
    for (std::size_t e = first; e < last; ++e)
      row.emplace_back(targets_[e], probabilities_[e]);
    model::normalize_distribution(row, values);
    for (const auto& [target, probability] : row) {
      targets_[kept] = target;
      probabilities_[kept] = probability;
      ++kept;
    }
  }
  targets_.resize(kept);
  probabilities_.resize(kept);
  sorted_ = true;
}

bool DistributionCollector::strictly_increasing(std::size_t first, std::size_t last) const {
  for (std::size_t e = first + 1; e < last; ++e) {
    if (targets_[e - 1] >= targets_[e]) return false;
  }
  return true;
}

void DistributionCollector::build_copying(model::TransitionMatrix& matrix, RationalPool& values) {
  std::vector<model::EdgeIndex>& begin = matrix.choice_begin;
  matrix.edge_target.reserve(targets_.size());
  matrix.edge_probability.reserve(targets_.size());
  std::vector<std::pair<model::StateIndex, ValueId>> row;
  for (std::size_t c = 0; c + 1 < begin.size(); ++c) {
    const std::uint32_t d = begin[c];
    begin[c] = static_cast<model::EdgeIndex>(matrix.edge_target.size());
    if (d == kNone) continue;
    copy_distribution(d, row);
    model::append_distribution(row, values, matrix);
  }
  begin.back() = static_cast<model::EdgeIndex>(matrix.edge_target.size());
  std::vector<model::StateIndex>().swap(targets_);
  std::vector<ValueId>().swap(probabilities_);
}

}  // namespace oasis::formats
