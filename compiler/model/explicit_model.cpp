#include "model/explicit_model.hpp"

#include <algorithm>
#include <numeric>
#include <stdexcept>

namespace oasis::model {

std::size_t TransitionMatrix::num_enabled_choices() const {
  std::size_t count = 0;
  for (std::size_t c = 0; c + 1 < choice_begin.size(); ++c) {
    if (choice_begin[c] != choice_begin[c + 1]) ++count;
  }
  return count;
}

std::string StateSpace::name(StateIndex s) const {
  if (!names.empty()) return names[s];
  if (variables.empty()) return std::to_string(s);
  std::string text = "(";
  for (std::size_t v = 0; v < variables.size(); ++v) {
    if (v > 0) text += ',';
    text += variables[v] + '=' + std::to_string(valuations[s * variables.size() + v]);
  }
  return text + ')';
}

Rational ExplicitModel::reward(std::size_t context, StateIndex s, ActionIndex a) const {
  const RewardTable& table = contexts[context].rewards;
  Rational total = values[table.state[s]];
  if (!table.choice.empty()) total += values[table.choice[s * num_actions() + a]];
  return total;
}

TransitionBuilder::TransitionBuilder(std::uint32_t num_states, std::uint32_t num_actions)
    : num_states_(0), num_actions_(num_actions) {
  set_num_states(num_states);
}

void TransitionBuilder::set_num_states(std::uint32_t num_states) {
  if (static_cast<std::uint64_t>(num_states) * num_actions_ >= UINT32_MAX) {
    throw std::length_error("more than 2^32 state-action pairs");
  }
  num_states_ = num_states;
}

void TransitionBuilder::reserve(std::size_t edges) {
  choices_.reserve(edges);
  targets_.reserve(edges);
  probabilities_.reserve(edges);
}

void TransitionBuilder::add(StateIndex source, ActionIndex action, StateIndex target,
                            ValueId probability) {
  if (targets_.size() >= UINT32_MAX) throw std::length_error("more than 2^32 transitions");
  choices_.push_back(source * num_actions_ + action);
  targets_.push_back(target);
  probabilities_.push_back(probability);
}

TransitionMatrix TransitionBuilder::finish(RationalPool& values) {
  TransitionMatrix matrix;
  matrix.num_states = num_states_;
  matrix.num_actions = num_actions_;
  const std::size_t num_choices = static_cast<std::size_t>(num_states_) * num_actions_;

  // Counting sort by choice: O(m + choices), stable, no comparison sort over all edges.
  matrix.choice_begin.assign(num_choices + 1, 0);
  for (ChoiceIndex c : choices_)
    ++matrix.choice_begin[c + 1];
  std::partial_sum(matrix.choice_begin.begin(), matrix.choice_begin.end(),
                   matrix.choice_begin.begin());
  std::vector<EdgeIndex> cursor(matrix.choice_begin.begin(), matrix.choice_begin.end() - 1);
  std::vector<StateIndex> sorted_target(targets_.size());
  std::vector<ValueId> sorted_probability(targets_.size());
  for (std::size_t e = 0; e < targets_.size(); ++e) {
    const EdgeIndex slot = cursor[choices_[e]]++;
    sorted_target[slot] = targets_[e];
    sorted_probability[slot] = probabilities_[e];
  }
  std::vector<ChoiceIndex>().swap(choices_);
  std::vector<StateIndex>().swap(targets_);
  std::vector<ValueId>().swap(probabilities_);

  // Sort each distribution by target and merge repeated targets.
  matrix.edge_target.reserve(sorted_target.size());
  matrix.edge_probability.reserve(sorted_target.size());
  std::vector<std::pair<StateIndex, ValueId>> row;
  EdgeIndex row_begin = 0;
  for (std::size_t c = 0; c < num_choices; ++c) {
    const EdgeIndex begin = matrix.choice_begin[c];
    const EdgeIndex end = matrix.choice_begin[c + 1];
    matrix.choice_begin[c] = row_begin;
    row.clear();
    for (EdgeIndex e = begin; e < end; ++e)
      row.emplace_back(sorted_target[e], sorted_probability[e]);
    append_distribution(row, values, matrix);
    row_begin = static_cast<EdgeIndex>(matrix.edge_target.size());
  }
  matrix.choice_begin[num_choices] = row_begin;
  return matrix;
}

void sort_by_target(std::span<std::pair<StateIndex, ValueId>> row) {
  // Insertion sort for the short rows most models have: stable like std::stable_sort, and
  // it needs no temporary buffer (an allocation per row).
  constexpr std::size_t kInsertionSortLimit = 32;
  if (row.size() <= kInsertionSortLimit) {
    for (std::size_t i = 1; i < row.size(); ++i) {
      const std::pair<StateIndex, ValueId> edge = row[i];
      std::size_t j = i;
      for (; j > 0 && row[j - 1].first > edge.first; --j)
        row[j] = row[j - 1];
      row[j] = edge;
    }
    return;
  }
  const auto by_target = [](const auto& x, const auto& y) { return x.first < y.first; };
  constexpr std::size_t kShortRow = 16;
  if (row.size() <= kShortRow) {
    // Rows are mostly a few targets: an insertion sort (stable) allocates nothing, where
    // std::stable_sort asks for a buffer every time.
    for (std::size_t i = 1; i < row.size(); ++i) {
      const std::pair<StateIndex, ValueId> edge = row[i];
      std::size_t j = i;
      for (; j > 0 && edge.first < row[j - 1].first; --j)
        row[j] = row[j - 1];
      row[j] = edge;
    }
  } else if (!std::is_sorted(row.begin(), row.end(), by_target)) {
    std::stable_sort(row.begin(), row.end(), by_target);
  }
}

void normalize_distribution(std::vector<std::pair<StateIndex, ValueId>>& row,
                            RationalPool& values) {
  sort_by_target(row);
  std::size_t kept = 0;
  for (std::size_t i = 0; i < row.size();) {
    std::size_t j = i + 1;
    ValueId probability = row[i].second;
    if (j < row.size() && row[j].first == row[i].first) {
      Rational sum = values[probability];
      for (; j < row.size() && row[j].first == row[i].first; ++j)
        sum += values[row[j].second];
      probability = values.intern(sum);
    }
    row[kept++] = {row[i].first, probability};
    i = j;
  }
  row.resize(kept);
}

void append_distribution(std::vector<std::pair<StateIndex, ValueId>>& row, RationalPool& values,
                         TransitionMatrix& matrix) {
  normalize_distribution(row, values);
  for (const auto& [target, probability] : row) {
    matrix.edge_target.push_back(target);
    matrix.edge_probability.push_back(probability);
  }
}

std::optional<std::string> find_structural_problem(const ExplicitModel& model) {
  const std::uint32_t n = model.num_states();
  const std::uint32_t k = model.num_actions();
  if (!model.states.names.empty() && model.states.names.size() != n) {
    return "state name table has the wrong size";
  }
  for (StateIndex s : model.states.initial) {
    if (s >= n) return "initial state " + std::to_string(s) + " is out of range";
  }
  for (const Context& context : model.contexts) {
    const std::string where = "context '" + context.name + "': ";
    if (!context.transitions) return where + "no transition matrix";
    const TransitionMatrix& matrix = *context.transitions;
    if (matrix.num_states != n || matrix.num_actions != k ||
        matrix.choice_begin.size() != static_cast<std::size_t>(n) * k + 1) {
      return where + "transition matrix has the wrong shape";
    }
    if (context.rewards.state.size() != n ||
        (!context.rewards.choice.empty() && context.rewards.choice.size() != std::size_t{n} * k)) {
      return where + "reward table has the wrong size";
    }
    for (StateIndex s = 0; s < n; ++s) {
      for (ActionIndex a = 0; a < k; ++a) {
        if (!matrix.enabled(s, a)) continue;
        Rational sum = 0;
        for (EdgeIndex e = matrix.edges_begin(s, a); e < matrix.edges_end(s, a); ++e) {
          if (matrix.edge_target[e] >= n) return where + "edge target out of range";
          if (e > matrix.edges_begin(s, a) && matrix.edge_target[e - 1] >= matrix.edge_target[e]) {
            return where + "edges of a choice are not sorted and distinct";
          }
          const Rational& p = model.values[matrix.edge_probability[e]];
          if (p <= 0) return where + "non-positive probability";
          sum += p;
        }
        if (sum != 1) {
          return where + "distribution of state " + model.states.name(s) + ", action " +
                 model.actions[a] + " sums to " + describe(sum);
        }
      }
    }
  }
  return std::nullopt;
}

}  // namespace oasis::model
