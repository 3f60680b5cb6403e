#include "verify/block_distribution.hpp"

#include <algorithm>

namespace oasis::verify {

std::vector<std::pair<model::BlockIndex, Rational>> block_distribution(
    const model::ExplicitModel& model, std::size_t context,
    const std::vector<model::BlockIndex>& block_of, model::StateIndex s, model::ActionIndex a) {
  const model::TransitionMatrix& matrix = *model.contexts[context].transitions;
  std::vector<std::pair<model::BlockIndex, Rational>> edges;
  for (model::EdgeIndex e = matrix.edges_begin(s, a); e < matrix.edges_end(s, a); ++e) {
    edges.emplace_back(block_of[matrix.edge_target[e]], model.values[matrix.edge_probability[e]]);
  }
  std::sort(edges.begin(), edges.end(),
            [](const auto& x, const auto& y) { return x.first < y.first; });
  std::vector<std::pair<model::BlockIndex, Rational>> result;
  for (auto& [block, probability] : edges) {
    if (!result.empty() && result.back().first == block) {
      result.back().second += probability;
    } else {
      result.emplace_back(block, std::move(probability));
    }
  }
  return result;
}

}  // namespace oasis::verify
