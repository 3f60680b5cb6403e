#include "bisim/initial_partition.hpp"

#include <cmath>
#include <limits>
#include <unordered_map>

#include "support/hash.hpp"

namespace oasis::bisim {
namespace {

constexpr std::uint32_t kDisabled = std::numeric_limits<std::uint32_t>::max();

// Numbers R(s, a) = state reward + choice reward. Rewards are few distinct values, so the
// sum is computed once per pair of value ids rather than once per (state, action).
class RewardNumbering {
 public:
  RewardNumbering(const model::ExplicitModel& model, std::size_t context,
                  std::optional<double> rounding_step)
      : model_(model), rewards_(model.contexts[context].rewards), rounding_step_(rounding_step) {}

  std::uint32_t id(model::StateIndex s, model::ActionIndex a) {
    const ValueId choice_part = rewards_.choice.empty()
                                    ? RationalPool::kZero
                                    : rewards_.choice[std::size_t{s} * model_.num_actions() + a];
    return number(rewards_.state[s], choice_part);
  }

  // The state reward alone: what separates states that have no enabled action.
  std::uint32_t state_only(model::StateIndex s) {
    return number(rewards_.state[s], RationalPool::kZero);
  }

 private:
  std::uint32_t number(ValueId state_part, ValueId choice_part) {
    const std::uint64_t key = (std::uint64_t{state_part} << 32U) | choice_part;
    auto [it, inserted] = cache_.try_emplace(key, 0);
    if (inserted) {
      Rational value = model_.values[state_part] + model_.values[choice_part];
      if (rounding_step_)
        value = Rational(static_cast<long>(std::llround(to_double(value) / *rounding_step_)));
      it->second = numbers_.intern(value);
    }
    return it->second;
  }

  const model::ExplicitModel& model_;
  const model::RewardTable& rewards_;
  std::optional<double> rounding_step_;
  std::unordered_map<std::uint64_t, std::uint32_t> cache_;
  RationalPool numbers_;
};

}  // namespace

InitialBlocks blocks_by_rewards(const model::ExplicitModel& model, std::size_t context,
                                std::optional<double> rounding_step,
                                const std::vector<std::uint32_t>& label_class) {
  const model::TransitionMatrix& matrix = *model.contexts[context].transitions;
  const std::uint32_t num_actions = model.num_actions();
  RewardNumbering rewards(model, context, rounding_step);
  InitialBlocks result;
  result.block_of.resize(model.num_states());
  // One entry per action (its reward, or disabled), one that holds the state reward of a state
  // with no enabled action (R(s) is the reward for being in s, and with no action there is no
  // R(s, a) to carry it), and a last one for the state's class of labels.
  std::vector<std::uint32_t> signature(num_actions + 2);
  // Signature hash -> the blocks whose signature has that hash, with the signature.
  std::unordered_map<std::uint64_t,
                     std::vector<std::pair<std::vector<std::uint32_t>, std::uint32_t>>>
      seen;
  for (model::StateIndex s = 0; s < model.num_states(); ++s) {
    std::uint64_t hash = 0x9e3779b97f4a7c15ULL;
    bool any_enabled = false;
    for (model::ActionIndex a = 0; a < num_actions; ++a) {
      const bool enabled = matrix.enabled(s, a);
      any_enabled |= enabled;
      signature[a] = enabled ? rewards.id(s, a) : kDisabled;
      hash = mix_bits(hash ^ signature[a]);
    }
    signature[num_actions] = any_enabled ? kDisabled : rewards.state_only(s);
    hash = mix_bits(hash ^ signature[num_actions]);
    signature[num_actions + 1] = label_class.empty() ? 0 : label_class[s];
    hash = mix_bits(hash ^ signature[num_actions + 1]);
    auto& candidates = seen[hash];
    std::uint32_t block = kDisabled;
    for (const auto& [other, index] : candidates) {
      if (other == signature) block = index;
    }
    if (block == kDisabled) {
      block = result.count++;
      candidates.emplace_back(signature, block);
    }
    result.block_of[s] = block;
  }
  return result;
}

}  // namespace oasis::bisim
