// State elimination over rationals, component by component (state_elimination.hpp).

#include "modelcheck/state_elimination.hpp"

#include <algorithm>
#include <functional>
#include <queue>
#include <string>
#include <utility>

#include "modelcheck/number_limits.hpp"
#include "modelcheck/strongly_connected.hpp"

namespace oasis::modelcheck {
namespace {

Digraph digraph_of(const LinearEquations& equations) {
  Digraph graph;
  graph.first.push_back(0);
  for (const SparseRow& row : equations.rows) {
    for (const Entry& entry : row)
      graph.next.push_back(entry.column);
    graph.first.push_back(static_cast<std::uint32_t>(graph.next.size()));
  }
  return graph;
}

// One strongly connected component, its columns renumbered 0..n-1, eliminated in minimum
// degree order.
class ComponentEliminator {
 public:
  ComponentEliminator(std::vector<SparseRow> rows, std::vector<Rational> constant,
                      const Options& options)
      : rows_(std::move(rows)),
        constant_(std::move(constant)),
        options_(options),
        eliminated_(rows_.size(), false),
        in_count_(rows_.size(), 0),
        users_(rows_.size()) {
    for (std::uint32_t i = 0; i < rows_.size(); ++i) {
      entries_ += rows_[i].size();
      for (const Entry& entry : rows_[i]) {
        ++in_count_[entry.column];
        users_[entry.column].push_back(i);
      }
    }
    check_entries();
  }

  std::vector<Rational> solve() {
    for (std::uint32_t k = 0; k < rows_.size(); ++k)
      queue_.emplace(cost(k), k);
    while (!queue_.empty()) {
      const auto [queued_cost, k] = queue_.top();
      queue_.pop();
      if (eliminated_[k] || queued_cost != cost(k)) continue;
      eliminate(k);
    }
    return back_substitute();
  }

 private:
  using Queued = std::pair<std::uint64_t, std::uint32_t>;

  [[nodiscard]] std::uint64_t cost(std::uint32_t k) const {
    return std::uint64_t{in_count_[k]} * rows_[k].size();
  }

  void check_entries() const {
    if (entries_ > kMaxEliminationEntries) {
      throw ExactLimitExceeded(suggest_sound_mode(
          "the exact solve of a strongly connected part of " + std::to_string(rows_.size()) +
          " states needs more than " + std::to_string(kMaxEliminationEntries) +
          " matrix entries (fill-in of the elimination)"));
    }
  }

  // x_k = b_k + sum a_kj x_j without its own term: divides by 1 - a_kk.
  void remove_self_loop(std::uint32_t k) {
    SparseRow& row = rows_[k];
    const auto self = std::lower_bound(
        row.begin(), row.end(), k, [](const Entry& e, std::uint32_t c) { return e.column < c; });
    if (self == row.end() || self->column != k) return;
    const Rational scale = 1 / (1 - self->value);
    row.erase(self);
    --entries_;
    for (Entry& entry : row) {
      entry.value *= scale;
      check_number_size(entry.value, options_.max_number_bits);
    }
    constant_[k] *= scale;
    check_number_size(constant_[k], options_.max_number_bits);
  }

  // Row i := row i without column k + factor * row k; new columns are registered.
  void substitute(std::uint32_t i, std::uint32_t k) {
    SparseRow& target = rows_[i];
    const auto at = std::lower_bound(target.begin(), target.end(), k,
                                     [](const Entry& e, std::uint32_t c) { return e.column < c; });
    if (at == target.end() || at->column != k) return;
    const Rational factor = at->value;
    target.erase(at);
    const SparseRow& source = rows_[k];
    SparseRow merged;
    merged.reserve(target.size() + source.size());
    std::size_t a = 0;
    std::size_t b = 0;
    while (a < target.size() || b < source.size()) {
      if (b == source.size() || (a < target.size() && target[a].column < source[b].column)) {
        merged.push_back(std::move(target[a++]));
        continue;
      }
      Rational product = factor * source[b].value;
      if (a < target.size() && target[a].column == source[b].column) {
        product += target[a++].value;
      } else {
        ++in_count_[source[b].column];
        users_[source[b].column].push_back(i);
        touched_.push_back(source[b].column);
      }
      check_number_size(product, options_.max_number_bits);
      merged.push_back({source[b++].column, std::move(product)});
    }
    entries_ = entries_ - target.size() - 1 + merged.size();
    target = std::move(merged);
    constant_[i] += factor * constant_[k];
    check_number_size(constant_[i], options_.max_number_bits);
    touched_.push_back(i);
    check_entries();
  }

  void eliminate(std::uint32_t k) {
    remove_self_loop(k);
    eliminated_[k] = true;
    order_.push_back(k);
    for (const Entry& entry : rows_[k]) {
      --in_count_[entry.column];
      touched_.push_back(entry.column);
    }
    std::vector<std::uint32_t> users = std::move(users_[k]);
    users_[k] = {};
    for (const std::uint32_t i : users) {
      if (!eliminated_[i]) substitute(i, k);
    }
    for (const std::uint32_t t : touched_) {
      if (!eliminated_[t]) queue_.emplace(cost(t), t);
    }
    touched_.clear();
    report_progress();
  }

  void report_progress() const {
    if (!options_.progress || order_.size() % 20000 != 0) return;
    options_.progress("exact: " + std::to_string(order_.size()) + " of " +
                      std::to_string(rows_.size()) + " states of a component eliminated, " +
                      std::to_string(entries_) + " entries");
  }

  std::vector<Rational> back_substitute() {
    std::vector<Rational> x(rows_.size());
    for (auto k = order_.rbegin(); k != order_.rend(); ++k) {
      Rational value = constant_[*k];
      for (const Entry& entry : rows_[*k])
        value += entry.value * x[entry.column];
      check_number_size(value, options_.max_number_bits);
      x[*k] = std::move(value);
    }
    return x;
  }

  std::vector<SparseRow> rows_;
  std::vector<Rational> constant_;
  const Options& options_;
  std::vector<bool> eliminated_;
  std::vector<std::uint32_t> in_count_;
  std::vector<std::vector<std::uint32_t>> users_;  // rows that mention each column
  std::vector<std::uint32_t> touched_;             // whose cost changed
  std::vector<std::uint32_t> order_;
  std::size_t entries_ = 0;
  std::priority_queue<Queued, std::vector<Queued>, std::greater<>> queue_;
};

// A component of one state: x = (b + sum of known terms) / (1 - a_ii).
Rational solve_single(const SparseRow& row, Rational constant, std::uint32_t self,
                      const std::vector<Rational>& x, const Options& options) {
  Rational loop = 0;
  for (const Entry& entry : row) {
    if (entry.column == self) {
      loop = entry.value;
    } else {
      constant += entry.value * x[entry.column];
    }
  }
  if (sgn(loop) != 0) constant /= 1 - loop;
  check_number_size(constant, options.max_number_bits);
  return constant;
}

}  // namespace

std::vector<Rational> solve_by_elimination(LinearEquations equations, const Options& options) {
  const Components components = strongly_connected_components(digraph_of(equations));
  const ComponentMembers members = group_by_component(components);
  std::vector<Rational> x(equations.rows.size());
  std::vector<std::uint32_t> local(equations.rows.size(), 0);
  for (std::uint32_t c = 0; c < components.count; ++c) {
    const std::uint32_t begin = members.first[c];
    const std::uint32_t end = members.first[c + 1];
    if (end - begin == 1) {
      const std::uint32_t v = members.nodes[begin];
      x[v] = solve_single(equations.rows[v], std::move(equations.constant[v]), v, x, options);
      continue;
    }
    for (std::uint32_t i = begin; i < end; ++i)
      local[members.nodes[i]] = i - begin;
    std::vector<SparseRow> rows(end - begin);
    std::vector<Rational> constant(end - begin);
    for (std::uint32_t i = begin; i < end; ++i) {
      const std::uint32_t v = members.nodes[i];
      constant[i - begin] = std::move(equations.constant[v]);
      for (Entry& entry : equations.rows[v]) {
        if (components.of_node[entry.column] == c) {
          rows[i - begin].push_back({local[entry.column], std::move(entry.value)});
        } else {
          constant[i - begin] += entry.value * x[entry.column];
        }
      }
      std::sort(rows[i - begin].begin(), rows[i - begin].end(),
                [](const Entry& a, const Entry& b) { return a.column < b.column; });
      equations.rows[v] = {};
    }
    const std::vector<Rational> solved =
        ComponentEliminator(std::move(rows), std::move(constant), options).solve();
    for (std::uint32_t i = begin; i < end; ++i)
      x[members.nodes[i]] = solved[i - begin];
  }
  return x;
}

}  // namespace oasis::modelcheck
