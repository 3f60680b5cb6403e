#include "bisim/initial_partition.hpp"

#include <algorithm>
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
    // Most states repeat the last pair (a reward is mostly 0): no lookup for them.
    if (key == last_key_) return last_id_;
    auto [it, inserted] = cache_.try_emplace(key, 0);
    if (inserted) {
      Rational value = model_.values[state_part] + model_.values[choice_part];
      if (rounding_step_)
        value = Rational(static_cast<long>(std::llround(to_double(value) / *rounding_step_)));
      it->second = numbers_.intern(value);
    }
    last_key_ = key;
    last_id_ = it->second;
    return it->second;
  }

  const model::ExplicitModel& model_;
  const model::RewardTable& rewards_;
  std::optional<double> rounding_step_;
  std::unordered_map<std::uint64_t, std::uint32_t> cache_;
  RationalPool numbers_;
  std::uint64_t last_key_ = UINT64_MAX;  // no pair of value ids: both would be kDisabled
  std::uint32_t last_id_ = 0;
};

// Numbers signatures of one width: each new signature gets the next block, 0, 1, ... Open
// addressing over a flat array of block numbers, the signatures kept one after another, so
// that finding a known signature (nearly every state: blocks are few) costs a probe and a
// comparison, and allocates nothing.
class SignatureBlocks {
 public:
  explicit SignatureBlocks(std::size_t width) : width_(width), slots_(kInitialSlots, kDisabled) {}

  std::uint32_t block(const std::vector<std::uint32_t>& signature, std::uint64_t hash) {
    const std::size_t mask = slots_.size() - 1;
    for (std::size_t i = hash & mask;; i = (i + 1) & mask) {
      const std::uint32_t block = slots_[i];
      if (block == kDisabled) return add(signature, hash, i);
      if (hashes_[block] == hash &&
          std::equal(signature.begin(), signature.end(),
                     signatures_.begin() + static_cast<std::ptrdiff_t>(block * width_)))
        return block;
    }
  }

  [[nodiscard]] std::uint32_t count() const { return static_cast<std::uint32_t>(hashes_.size()); }

 private:
  static constexpr std::size_t kInitialSlots = 64;  // a power of two

  std::uint32_t add(const std::vector<std::uint32_t>& signature, std::uint64_t hash,
                    std::size_t slot) {
    const std::uint32_t block = count();
    slots_[slot] = block;
    hashes_.push_back(hash);
    signatures_.insert(signatures_.end(), signature.begin(), signature.end());
    if (hashes_.size() * 2 > slots_.size()) grow();
    return block;
  }

  // Twice the slots, every block placed again by its hash (the table stays at most half full).
  void grow() {
    slots_.assign(slots_.size() * 2, kDisabled);
    const std::size_t mask = slots_.size() - 1;
    for (std::uint32_t block = 0; block < hashes_.size(); ++block) {
      std::size_t i = hashes_[block] & mask;
      while (slots_[i] != kDisabled)
        i = (i + 1) & mask;
      slots_[i] = block;
    }
  }

  std::size_t width_;
  std::vector<std::uint32_t> slots_;       // a block, or kDisabled for an empty slot
  std::vector<std::uint64_t> hashes_;      // by block
  std::vector<std::uint32_t> signatures_;  // by block, width_ each
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
  SignatureBlocks blocks(signature.size());
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
    result.block_of[s] = blocks.block(signature, hash);
  }
  result.count = blocks.count();
  return result;
}

}  // namespace oasis::bisim
