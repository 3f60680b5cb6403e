#include "verify/coarsest_check.hpp"

#include <map>
#include <optional>
#include <tuple>
#include <vector>

#include "verify/block_distribution.hpp"

namespace oasis::verify {
namespace {

using model::ActionIndex;
using model::StateIndex;

using Distribution = std::vector<std::pair<std::uint32_t, Rational>>;

// One block of the quotient: for each action, nothing when it is disabled, else its reward
// and its distribution over blocks.
struct QuotientState {
  std::vector<std::optional<std::pair<Rational, Distribution>>> choices;
};

// (current class, [(action, reward, distribution over classes)] for the enabled actions).
using Signature =
    std::pair<std::uint32_t, std::vector<std::tuple<ActionIndex, Rational, Distribution>>>;

std::vector<QuotientState> build_quotient(const model::ExplicitModel& model, std::size_t context,
                                          const bisim::Partition& partition) {
  const model::TransitionMatrix& matrix = *model.contexts[context].transitions;
  std::vector<std::optional<StateIndex>> first_member(partition.num_blocks);
  for (StateIndex s = 0; s < partition.num_states(); ++s) {
    if (!first_member[partition.block_of[s]]) first_member[partition.block_of[s]] = s;
  }
  std::vector<QuotientState> quotient(partition.num_blocks);
  for (bisim::BlockIndex b = 0; b < partition.num_blocks; ++b) {
    const StateIndex r = *first_member[b];
    quotient[b].choices.resize(model.num_actions());
    for (ActionIndex a = 0; a < model.num_actions(); ++a) {
      if (!matrix.enabled(r, a)) continue;
      quotient[b].choices[a].emplace(model.reward(context, r, a),
                                     block_distribution(model, context, partition.block_of, r, a));
    }
  }
  return quotient;
}

// The distribution over blocks `d` as a distribution over classes.
Distribution over_classes(const Distribution& d, const std::vector<std::uint32_t>& class_of) {
  std::map<std::uint32_t, Rational> sums;
  for (const auto& [block, p] : d)
    sums[class_of[block]] += p;
  return {sums.begin(), sums.end()};
}

}  // namespace

VerificationResult check_coarsest(const model::ExplicitModel& model, std::size_t context,
                                  const bisim::Partition& partition) {
  const std::vector<QuotientState> quotient = build_quotient(model, context, partition);
  const std::size_t n = quotient.size();
  std::vector<std::uint32_t> class_of(n, 0);
  std::size_t num_classes = n == 0 ? 0 : 1;
  while (true) {
    std::map<Signature, std::uint32_t> numbering;
    std::vector<std::uint32_t> next(n);
    for (std::size_t b = 0; b < n; ++b) {
      Signature signature{class_of[b], {}};
      for (ActionIndex a = 0; a < quotient[b].choices.size(); ++a) {
        const auto& choice = quotient[b].choices[a];
        if (!choice) continue;
        signature.second.emplace_back(a, choice->first, over_classes(choice->second, class_of));
      }
      const auto [it, inserted] =
          numbering.try_emplace(std::move(signature), static_cast<std::uint32_t>(numbering.size()));
      next[b] = it->second;
    }
    class_of = std::move(next);
    // Each round only splits classes (the old class is part of the signature), so an
    // unchanged count means an unchanged partition: the fixpoint.
    if (numbering.size() == num_classes) break;
    num_classes = numbering.size();
  }
  if (num_classes == n) return {};

  // The first block that shares its class with an earlier one.
  std::vector<std::optional<bisim::BlockIndex>> first_of_class(num_classes);
  for (bisim::BlockIndex b = 0; b < n; ++b) {
    auto& first = first_of_class[class_of[b]];
    if (!first) {
      first = b;
      continue;
    }
    Violation v;
    v.kind = ViolationKind::BlocksCouldMerge;
    v.block = *first;
    v.other_block = b;
    for (StateIndex s = 0; s < partition.num_states(); ++s) {
      if (partition.block_of[s] == *first && !v.state) v.state = s;
      if (partition.block_of[s] == b && !v.other_state) v.other_state = s;
    }
    v.message = "the partition is a bisimulation but not the coarsest: " +
                describe_block(model, partition, *first) + " and " +
                describe_block(model, partition, b) +
                " are bisimilar, so the coarsest bisimulation puts them together (" +
                std::to_string(num_classes) + " blocks instead of " + std::to_string(n) + ")";
    return {std::move(v)};
  }
  return {};  // not reached: fewer classes than blocks means some class has two
}

}  // namespace oasis::verify
