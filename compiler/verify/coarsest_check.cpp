#include "verify/coarsest_check.hpp"

#include <algorithm>
#include <optional>
#include <unordered_map>
#include <vector>

#include "verify/block_distribution.hpp"

namespace oasis::verify {
namespace {

using model::ActionIndex;
using model::StateIndex;

// An enabled choice of a quotient state. Rewards and probabilities are ids in a pool local
// to the check, so that signatures are vectors of integers: equal ids, equal rationals.
struct QuotientChoice {
  ActionIndex action = 0;
  ValueId reward = 0;
  std::vector<std::pair<model::BlockIndex, ValueId>> distribution;
};

// The quotient: block b behaves as its first member does (all members agree, since the
// partition is a bisimulation).
std::vector<std::vector<QuotientChoice>> build_quotient(const model::ExplicitModel& model,
                                                        std::size_t context,
                                                        const model::Partition& partition,
                                                        RationalPool& pool) {
  const model::TransitionMatrix& matrix = *model.contexts[context].transitions;
  std::vector<std::optional<StateIndex>> first_member(partition.num_blocks);
  for (StateIndex s = 0; s < partition.num_states(); ++s) {
    if (!first_member[partition.block_of[s]]) first_member[partition.block_of[s]] = s;
  }
  std::vector<std::vector<QuotientChoice>> quotient(partition.num_blocks);
  for (model::BlockIndex b = 0; b < partition.num_blocks; ++b) {
    const StateIndex r = *first_member[b];
    for (ActionIndex a = 0; a < model.num_actions(); ++a) {
      if (!matrix.enabled(r, a)) continue;
      QuotientChoice choice{a, pool.intern(model.reward(context, r, a)), {}};
      for (const auto& [block, p] : block_distribution(model, context, partition.block_of, r, a)) {
        choice.distribution.emplace_back(block, pool.intern(p));
      }
      quotient[b].push_back(std::move(choice));
    }
    // A block with no enabled action is told apart by its state reward R(s); it gets one
    // pseudo-choice, with the action number one past the last and no successors.
    if (quotient[b].empty()) {
      const ValueId state_reward = model.contexts[context].rewards.state[r];
      quotient[b].push_back({model.num_actions(), pool.intern(model.values[state_reward]), {}});
    }
  }
  return quotient;
}

// Exact addition of pooled values, remembered: the same few sums recur in every round (a
// class holding both targets of a choice), and GMP arithmetic would dominate the check.
class PooledSums {
 public:
  explicit PooledSums(RationalPool& pool) : pool_(pool) {}

  ValueId add(ValueId x, ValueId y) {
    if (x > y) std::swap(x, y);
    const std::uint64_t key = (std::uint64_t{x} << 32) | y;
    const auto it = sums_.find(key);
    if (it != sums_.end()) return it->second;
    const ValueId sum = pool_.intern(pool_[x] + pool_[y]);
    sums_.emplace(key, sum);
    return sum;
  }

 private:
  RationalPool& pool_;
  std::unordered_map<std::uint64_t, ValueId> sums_;
};

struct SignatureHash {
  std::size_t operator()(const std::vector<std::uint32_t>& signature) const {
    std::uint64_t hash = signature.size();
    for (std::uint32_t x : signature)
      hash = (hash ^ x) * 0x9e3779b97f4a7c15ULL;
    return hash ^ (hash >> 29);
  }
};

// One round of naive refinement: the new class of every quotient state is its signature
//   (class, [action, reward, k, (class, probability) * k] for each enabled action),
// where the probabilities of reaching each class are summed exactly. Returns the number of
// classes.
std::size_t refine(const std::vector<std::vector<QuotientChoice>>& quotient, PooledSums& sums,
                   std::vector<std::uint32_t>& class_of) {
  std::unordered_map<std::vector<std::uint32_t>, std::uint32_t, SignatureHash> numbering;
  std::vector<std::uint32_t> next(quotient.size());
  std::vector<std::uint32_t> signature;
  std::vector<std::pair<std::uint32_t, ValueId>> by_class;
  for (std::size_t b = 0; b < quotient.size(); ++b) {
    signature.assign(1, class_of[b]);
    for (const QuotientChoice& choice : quotient[b]) {
      by_class.clear();
      for (const auto& [block, p] : choice.distribution)
        by_class.emplace_back(class_of[block], p);
      std::sort(by_class.begin(), by_class.end());
      signature.push_back(choice.action);
      signature.push_back(choice.reward);
      const std::size_t count_at = signature.size();
      signature.push_back(0);
      for (std::size_t i = 0; i < by_class.size();) {
        std::size_t j = i + 1;
        ValueId probability = by_class[i].second;
        for (; j < by_class.size() && by_class[j].first == by_class[i].first; ++j) {
          probability = sums.add(probability, by_class[j].second);
        }
        signature.push_back(by_class[i].first);
        signature.push_back(probability);
        ++signature[count_at];
        i = j;
      }
    }
    next[b] = numbering.try_emplace(signature, static_cast<std::uint32_t>(numbering.size()))
                  .first->second;
  }
  class_of = std::move(next);
  return numbering.size();
}

}  // namespace

VerificationResult check_coarsest(const model::ExplicitModel& model, std::size_t context,
                                  const model::Partition& partition,
                                  const std::vector<std::uint32_t>& label_class) {
  RationalPool pool;
  const auto quotient = build_quotient(model, context, partition, pool);
  PooledSums sums(pool);
  const std::size_t n = quotient.size();
  // The first classes: one, or the blocks' classes of labels (every member of a block has its
  // block's class, check_bisimulation made sure), renumbered densely.
  std::vector<std::uint32_t> class_of(n, 0);
  std::size_t num_classes = n == 0 ? 0 : 1;
  if (!label_class.empty()) {
    std::unordered_map<std::uint32_t, std::uint32_t> dense;
    for (StateIndex s = 0; s < partition.num_states(); ++s)
      class_of[partition.block_of[s]] =
          dense.try_emplace(label_class[s], static_cast<std::uint32_t>(dense.size())).first->second;
    num_classes = dense.size();
  }
  while (true) {
    const std::size_t count = refine(quotient, sums, class_of);
    // Each round only splits classes (the old class is part of the signature), so an
    // unchanged count means an unchanged partition: the fixpoint.
    if (count == num_classes) break;
    num_classes = count;
  }
  if (num_classes == n) return {};

  // The first block that shares its class with an earlier one.
  std::vector<std::optional<model::BlockIndex>> first_of_class(num_classes);
  for (model::BlockIndex b = 0; b < n; ++b) {
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
