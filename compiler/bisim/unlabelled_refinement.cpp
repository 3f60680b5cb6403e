#include "bisim/unlabelled_refinement.hpp"

#include <algorithm>
#include <chrono>
#include <unordered_map>
#include <utility>
#include <vector>

#include "support/hash.hpp"

namespace oasis::bisim {
namespace {

struct SignatureHash {
  std::size_t operator()(const std::vector<std::uint32_t>& signature) const {
    std::uint64_t h = signature.size();
    for (const std::uint32_t word : signature)
      h = mix_bits(h ^ word) + 0x9e3779b97f4a7c15ULL;
    return static_cast<std::size_t>(h);
  }
};

// Numbers signatures in the order they are first seen.
class SignatureTable {
 public:
  std::uint32_t id(const std::vector<std::uint32_t>& signature) {
    return ids_.try_emplace(signature, static_cast<std::uint32_t>(ids_.size())).first->second;
  }
  [[nodiscard]] std::size_t size() const { return ids_.size(); }
  void clear() { ids_.clear(); }

 private:
  std::unordered_map<std::vector<std::uint32_t>, std::uint32_t, SignatureHash> ids_;
};

class UnlabelledRefiner {
 public:
  UnlabelledRefiner(const model::ExplicitModel& model, std::size_t context,
                    const RefinementOptions& options)
      : model_(model),
        matrix_(*model.contexts.at(context).transitions),
        rewards_(model.contexts.at(context).rewards),
        options_(options),
        model_to_local_(model.values.size(), kUnseen) {
    // R(s, a) of every enabled choice, once, as ids of local_.
    reward_.assign(std::size_t{matrix_.num_states} * matrix_.num_actions, 0);
    for (model::StateIndex s = 0; s < matrix_.num_states; ++s) {
      for (model::ActionIndex a = 0; a < matrix_.num_actions; ++a) {
        if (matrix_.enabled(s, a))
          reward_[matrix_.choice(s, a)] = local_.intern(model.reward(context, s, a));
      }
    }
  }

  Partition run(RefinementStatistics* statistics) {
    const auto start = std::chrono::steady_clock::now();
    std::vector<std::uint32_t> block = initial_blocks();
    std::size_t num_blocks = count(block);
    const std::uint32_t initial_blocks = static_cast<std::uint32_t>(num_blocks);
    std::uint64_t rounds = 0;
    for (;;) {
      ++rounds;
      std::vector<std::uint32_t> next = refine(block);
      const std::size_t next_blocks = count(next);
      if (options_.progress) {
        options_.progress({rounds, 0, static_cast<std::uint32_t>(next_blocks)});
      }
      // Signatures include the block, so a round only splits; equal counts mean no split.
      if (next_blocks == num_blocks) break;
      block = std::move(next);
      num_blocks = next_blocks;
    }
    if (statistics != nullptr) {
      *statistics = {};
      statistics->splitters = rounds;  // rounds of signature refinement
      statistics->initial_blocks = initial_blocks;
      statistics->splitting_seconds =
          std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    }
    return model::canonical_partition(block);
  }

 private:
  static constexpr ValueId kUnseen = UINT32_MAX;

  static std::size_t count(const std::vector<std::uint32_t>& block) {
    std::uint32_t largest = 0;
    for (const std::uint32_t b : block)
      largest = std::max(largest, b + 1);
    return largest;
  }

  // By respected labels; rewards belong to the choices, except that a state with none is
  // told apart by its state reward, as Definition 1's engine does (initial_partition.hpp).
  std::vector<std::uint32_t> initial_blocks() {
    SignatureTable table;
    std::vector<std::uint32_t> block(matrix_.num_states);
    for (model::StateIndex s = 0; s < matrix_.num_states; ++s) {
      const std::uint32_t labels = options_.label_class.empty() ? 0 : options_.label_class[s];
      bool any_enabled = false;
      for (model::ActionIndex a = 0; a < matrix_.num_actions && !any_enabled; ++a)
        any_enabled = matrix_.enabled(s, a);
      const std::uint32_t alone = any_enabled ? kUnseen : local_id(rewards_.state[s]);
      block[s] = table.id({labels, alone});
    }
    return block;
  }

  std::vector<std::uint32_t> refine(const std::vector<std::uint32_t>& block) {
    SignatureTable choices;
    SignatureTable states;
    std::vector<std::uint32_t> next(matrix_.num_states);
    std::vector<std::uint32_t> state_signature;
    for (model::StateIndex s = 0; s < matrix_.num_states; ++s) {
      state_signature.clear();
      for (model::ActionIndex a = 0; a < matrix_.num_actions; ++a) {
        if (matrix_.enabled(s, a))
          state_signature.push_back(choices.id(choice_signature(block, s, a)));
      }
      // A set: the order and the repetition of equal choices do not matter.
      std::sort(state_signature.begin(), state_signature.end());
      state_signature.erase(std::unique(state_signature.begin(), state_signature.end()),
                            state_signature.end());
      state_signature.push_back(block[s]);
      next[s] = states.id(state_signature);
    }
    return next;
  }

  // (R(s, a), then (block, probability) by block), numbers as ids of local_.
  const std::vector<std::uint32_t>& choice_signature(const std::vector<std::uint32_t>& block,
                                                     model::StateIndex s, model::ActionIndex a) {
    row_.clear();
    for (model::EdgeIndex e = matrix_.edges_begin(s, a); e < matrix_.edges_end(s, a); ++e)
      row_.emplace_back(block[matrix_.edge_target[e]], matrix_.edge_probability[e]);
    std::sort(row_.begin(), row_.end());
    signature_.clear();
    signature_.push_back(reward_[matrix_.choice(s, a)]);
    for (std::size_t i = 0; i < row_.size();) {
      const std::uint32_t b = row_[i].first;
      std::size_t j = i + 1;
      if (j == row_.size() || row_[j].first != b) {
        signature_.push_back(b);
        signature_.push_back(local_id(row_[i].second));
        i = j;
        continue;
      }
      Rational sum = model_.values[row_[i].second];
      for (; j < row_.size() && row_[j].first == b; ++j)
        sum += model_.values[row_[j].second];
      signature_.push_back(b);
      signature_.push_back(local_.intern(sum));
      i = j;
    }
    return signature_;
  }

  // The model's probability `id` as an id of local_, where sums are interned too, so that
  // equal probabilities have equal ids whether they were summed or not.
  ValueId local_id(ValueId id) {
    ValueId& local = model_to_local_[id];
    if (local == kUnseen) local = local_.intern(model_.values[id]);
    return local;
  }

  const model::ExplicitModel& model_;
  const model::TransitionMatrix& matrix_;
  const model::RewardTable& rewards_;
  const RefinementOptions& options_;
  RationalPool local_;
  std::vector<ValueId> model_to_local_;
  std::vector<ValueId> reward_;  // per choice: R(s, a) in local_
  std::vector<std::pair<std::uint32_t, ValueId>> row_;
  std::vector<std::uint32_t> signature_;
};

}  // namespace

Partition coarsest_unlabelled_bisimulation(const model::ExplicitModel& model, std::size_t context,
                                           const RefinementOptions& options,
                                           RefinementStatistics* statistics) {
  return UnlabelledRefiner(model, context, options).run(statistics);
}

}  // namespace oasis::bisim
