// Coarsest bisimulation by partition refinement, processing the smaller half.
//
// The method is the one of Valmari and Franceschinis, "Simple O(m log n) time Markov chain
// lumping" (TACAS 2010), carried over to MDPs with one distribution per state and action
// (as in Groote, Rivera Verduzco and de Vink, "An efficient algorithm to determine
// probabilistic bisimulation", 2018, whose setting is more general).
//
// State. A partition of the states into blocks, each a contiguous range of `elements_`, and
// a queue of splitters. For a splitter B and a state s, the weight of s for action a is
// w(s, a, B) = P(B | s, a), the probability that action a moves s into B.
//
// Step. Pop a splitter B. Walk the incoming edges of B's states, adding each edge's
// probability to the weight of its (source, action) pair; the sources are the "touched"
// states. Inside every block, touched states are grouped by their weight signature (the
// actions with a non-zero weight, and the weights); untouched states form one more group
// (all weights 0). A block with more than one group is split into its groups.
//
// Invariant. Let U be the set of all states. For every block X and every block C that is
// not in the queue, states of X agree on w(., a, C) for all a. Initially this holds for
// C = U because the initial partition separates states by their set of enabled actions
// (w(s, a, U) is 1 when a is enabled in s and 0 otherwise) and by R(s, a).
//
// Smaller half. When a block C splits into parts C1..Ck and C is in the queue, every part
// is queued. When C is not in the queue, weights with respect to C are already equal within
// every block, so w(., a, Cj) for the largest part follows from the others:
// w(s, a, C_largest) = w(s, a, C) - sum of the other parts. Only the other parts are queued.
// (The initial blocks are parts of U in the same way: all but the largest are queued.)
// At the end the queue is empty, so every block agrees on the weights to every block:
// the partition is a bisimulation, and since blocks are split only when some states
// provably differ, it is the coarsest one.
//
// Cost. A state enters the queue in a part at most half the size of the part it entered
// before, so it is in a processed splitter O(log n) times and each edge is walked O(log n)
// times: O(m log n) edge visits. Grouping hashes each touched state's signature: expected
// O(1) per touched (state, action) pair, which is charged to the edge that touched it.
// Memory: compact arrays only, 32-bit indices; about 25 bytes per edge and 24 per choice.

#include "bisim/refinement.hpp"

#include <algorithm>
#include <limits>
#include <unordered_map>

#include "bisim/weights.hpp"

namespace oasis::bisim {
namespace {

using model::ActionIndex;
using model::ChoiceIndex;
using model::EdgeIndex;
using model::StateIndex;

constexpr std::uint32_t kNone = std::numeric_limits<std::uint32_t>::max();

std::uint64_t mix(std::uint64_t x) {
  x ^= x >> 30U;
  x *= 0xbf58476d1ce4e5b9ULL;
  x ^= x >> 27U;
  x *= 0x94d049bb133111ebULL;
  x ^= x >> 31U;
  return x;
}

class Refiner {
 public:
  Refiner(const model::ExplicitModel& model, std::size_t context, const RefinementOptions& options)
      : model_(model),
        matrix_(*model.contexts[context].transitions),
        context_(context),
        options_(options),
        num_states_(model.num_states()),
        num_actions_(model.num_actions()),
        weights_(WeightTable::choose(model, matrix_, options.epsilon)) {}

  Partition run(RefinementStatistics* statistics) {
    statistics_.exact_integer_sums = weights_.mode == WeightMode::Integer;
    if (num_states_ == 0) return {};
    build_reverse_edges();
    initial_partition();
    allocate_scratch();
    while (!queue_.empty()) {
      const BlockIndex splitter = queue_.back();
      queue_.pop_back();
      blocks_[splitter].queued = false;
      split_by(splitter);
      ++statistics_.splitters;
      if (options_.progress && (statistics_.splitters & 0x3FFFU) == 0) {
        options_.progress({statistics_.splitters, queue_.size(), static_cast<std::uint32_t>(blocks_.size())});
      }
    }
    if (statistics != nullptr) *statistics = statistics_;
    return canonical_partition(block_of_);
  }

 private:
  struct Block {
    std::uint32_t begin;
    std::uint32_t end;
    bool queued;
    [[nodiscard]] std::uint32_t size() const { return end - begin; }
  };

  // A set of touched states of one block with the same signature.
  struct Group {
    StateIndex representative;
    BlockIndex block;
    std::uint32_t size;
    StateIndex first_state;  // list through next_in_group_
    std::uint32_t next_in_block;  // list of the block's groups
    std::uint32_t next_same_hash;
  };

  // ---- set-up -----------------------------------------------------------------------------

  // in_*: for every state t, the (choice, probability) of each edge into t.
  void build_reverse_edges() {
    in_begin_.assign(std::size_t{num_states_} + 1, 0);
    for (StateIndex t : matrix_.edge_target) ++in_begin_[t + 1];
    for (std::size_t t = 0; t < num_states_; ++t) in_begin_[t + 1] += in_begin_[t];
    in_choice_.resize(matrix_.num_edges());
    in_probability_.resize(matrix_.num_edges());
    std::vector<EdgeIndex> cursor(in_begin_.begin(), in_begin_.end() - 1);
    const std::size_t num_choices = std::size_t{num_states_} * num_actions_;
    for (ChoiceIndex c = 0; c < num_choices; ++c) {
      for (EdgeIndex e = matrix_.choice_begin[c]; e < matrix_.choice_begin[c + 1]; ++e) {
        const EdgeIndex slot = cursor[matrix_.edge_target[e]]++;
        in_choice_[slot] = c;
        in_probability_[slot] = matrix_.edge_probability[e];
      }
    }
  }

  // Blocks by (enabled actions, R(s, a) for each action): the coarsest partition that can
  // hold a bisimulation, and stable with respect to the set of all states.
  void initial_partition() {
    RationalPool rewards;  // R(s, a) values, interned so signatures compare as integers
    std::vector<std::uint32_t> signature(num_actions_);
    std::unordered_map<std::uint64_t, std::vector<std::pair<std::vector<std::uint32_t>, BlockIndex>>> seen;
    block_of_.resize(num_states_);
    std::vector<std::uint32_t> sizes;
    for (StateIndex s = 0; s < num_states_; ++s) {
      std::uint64_t hash = 0x9e3779b97f4a7c15ULL;
      for (ActionIndex a = 0; a < num_actions_; ++a) {
        signature[a] = matrix_.enabled(s, a) ? reward_id(rewards, s, a) : kNone;
        hash = mix(hash ^ signature[a]);
      }
      auto& candidates = seen[hash];
      BlockIndex block = kNone;
      for (const auto& [other, index] : candidates) {
        if (other == signature) block = index;
      }
      if (block == kNone) {
        block = static_cast<BlockIndex>(sizes.size());
        sizes.push_back(0);
        candidates.emplace_back(signature, block);
      }
      block_of_[s] = block;
      ++sizes[block];
    }
    place_initial_blocks(sizes);
    statistics_.initial_blocks = static_cast<std::uint32_t>(blocks_.size());
  }

  std::uint32_t reward_id(RationalPool& rewards, StateIndex s, ActionIndex a) {
    const model::RewardTable& table = model_.contexts[context_].rewards;
    if (table.choice.empty() && weights_.mode != WeightMode::Rounded) {
      return rewards.intern(model_.values[table.state[s]]);
    }
    Rational value = model_.reward(context_, s, a);
    if (weights_.mode == WeightMode::Rounded) {
      value = Rational(weights_.rounded_key(to_double(value)));  // rewards are rounded too
    }
    return rewards.intern(value);
  }

  void place_initial_blocks(const std::vector<std::uint32_t>& sizes) {
    std::uint32_t begin = 0;
    BlockIndex largest = 0;
    for (BlockIndex b = 0; b < sizes.size(); ++b) {
      blocks_.push_back({begin, begin, false});
      begin += sizes[b];
      if (sizes[b] > sizes[largest]) largest = b;
    }
    elements_.resize(num_states_);
    position_.resize(num_states_);
    for (StateIndex s = 0; s < num_states_; ++s) {
      Block& block = blocks_[block_of_[s]];
      position_[s] = block.end;
      elements_[block.end++] = s;
    }
    for (BlockIndex b = 0; b < blocks_.size(); ++b) {
      if (b != largest) enqueue(b);
    }
  }

  void allocate_scratch() {
    const std::size_t num_choices = std::size_t{num_states_} * num_actions_;
    switch (weights_.mode) {
      case WeightMode::Integer: integer_sum_.assign(num_choices, 0); break;
      case WeightMode::Rounded: real_sum_.assign(num_choices, 0.0); break;
      case WeightMode::Rational: rational_slot_.assign(num_choices, kNone); break;
    }
    touched_choice_.assign(num_choices, false);
    choice_next_.assign(num_choices, kNone);
    state_head_.assign(num_states_, kNone);
    next_in_group_.assign(num_states_, kNone);
    block_first_group_.assign(num_states_, kNone);
  }

  void enqueue(BlockIndex block) {
    blocks_[block].queued = true;
    queue_.push_back(block);
  }

  // ---- one splitter -----------------------------------------------------------------------

  void split_by(BlockIndex splitter) {
    accumulate_weights(splitter);
    group_touched_states();
    split_touched_blocks();
    reset_scratch();
  }

  void accumulate_weights(BlockIndex splitter) {
    const Block block = blocks_[splitter];
    for (std::uint32_t i = block.begin; i < block.end; ++i) {
      const StateIndex t = elements_[i];
      statistics_.edge_visits += in_begin_[t + 1] - in_begin_[t];
      for (EdgeIndex e = in_begin_[t]; e < in_begin_[t + 1]; ++e) add_weight(in_choice_[e], in_probability_[e]);
    }
  }

  void add_weight(ChoiceIndex c, ValueId probability) {
    if (!touched_choice_[c]) {
      touched_choice_[c] = true;
      touched_choices_.push_back(c);
      const StateIndex s = c / num_actions_;
      if (state_head_[s] == kNone) touched_states_.push_back(s);
      choice_next_[c] = state_head_[s];
      state_head_[s] = c;
      if (weights_.mode == WeightMode::Rational) {
        rational_slot_[c] = static_cast<std::uint32_t>(touched_choices_.size() - 1);
        if (rational_sum_.size() < touched_choices_.size()) rational_sum_.emplace_back();
        rational_sum_[rational_slot_[c]] = 0;
      }
    }
    switch (weights_.mode) {
      case WeightMode::Integer: integer_sum_[c] += weights_.integer[probability]; break;
      case WeightMode::Rounded: real_sum_[c] += weights_.real[probability]; break;
      case WeightMode::Rational: rational_sum_[rational_slot_[c]] += model_.values[probability]; break;
    }
  }

  // The touched choices of `s`, sorted by action: its signature.
  void collect_signature(StateIndex s, std::vector<ChoiceIndex>& out) const {
    out.clear();
    for (ChoiceIndex c = state_head_[s]; c != kNone; c = choice_next_[c]) out.push_back(c);
    std::sort(out.begin(), out.end());  // choices of one state sort by action
  }

  [[nodiscard]] std::uint64_t weight_key(ChoiceIndex c) const {
    switch (weights_.mode) {
      case WeightMode::Integer: return integer_sum_[c];
      case WeightMode::Rounded: return static_cast<std::uint64_t>(weights_.rounded_key(real_sum_[c]));
      case WeightMode::Rational: return hash_value(rational_sum_[rational_slot_[c]]);
    }
    return 0;
  }

  [[nodiscard]] bool same_weight(ChoiceIndex c, ChoiceIndex d) const {
    if (weights_.mode == WeightMode::Rational) {
      return rational_sum_[rational_slot_[c]] == rational_sum_[rational_slot_[d]];
    }
    return weight_key(c) == weight_key(d);
  }

  [[nodiscard]] std::uint64_t signature_hash(BlockIndex block, const std::vector<ChoiceIndex>& signature) const {
    std::uint64_t hash = mix(block + 0x9e3779b97f4a7c15ULL);
    for (ChoiceIndex c : signature) hash = mix(hash ^ (c % num_actions_)) ^ mix(weight_key(c));
    return hash;
  }

  [[nodiscard]] bool same_signature(const std::vector<ChoiceIndex>& a, const std::vector<ChoiceIndex>& b) const {
    if (a.size() != b.size()) return false;
    for (std::size_t i = 0; i < a.size(); ++i) {
      if (a[i] % num_actions_ != b[i] % num_actions_ || !same_weight(a[i], b[i])) return false;
    }
    return true;
  }

  // Groups are found through an open-addressing table sized for this splitter's touched
  // states, so that clearing it costs what the splitter touched, not the largest splitter
  // seen so far. Each slot heads a chain of groups whose signature hashes collide there.
  void group_touched_states() {
    groups_.clear();
    std::size_t table_size = 16;
    while (table_size < 2 * touched_states_.size()) table_size *= 2;
    group_table_.assign(table_size, kNone);
    for (StateIndex s : touched_states_) {
      const BlockIndex block = block_of_[s];
      collect_signature(s, signature_);
      const std::uint64_t hash = signature_hash(block, signature_);
      std::uint32_t& head = group_table_[hash & (table_size - 1)];
      std::uint32_t group = head;
      for (; group != kNone; group = groups_[group].next_same_hash) {
        if (groups_[group].block != block) continue;
        collect_signature(groups_[group].representative, other_signature_);
        if (same_signature(signature_, other_signature_)) break;
      }
      if (group == kNone) {
        group = static_cast<std::uint32_t>(groups_.size());
        groups_.push_back({s, block, 0, kNone, block_first_group_[block], head});
        head = group;
        if (block_first_group_[block] == kNone) touched_blocks_.push_back(block);
        block_first_group_[block] = group;
      }
      next_in_group_[s] = groups_[group].first_state;
      groups_[group].first_state = s;
      ++groups_[group].size;
    }
  }

  void split_touched_blocks() {
    for (BlockIndex block : touched_blocks_) split_block(block);
  }

  // Rearranges the block's range as [untouched | group 1 | group 2 | ...] and makes every
  // group a block of its own (the first group keeps the block's index when nothing is
  // untouched).
  void split_block(BlockIndex block) {
    const std::uint32_t first_group = block_first_group_[block];
    Block& range = blocks_[block];
    std::uint32_t touched = 0;
    for (std::uint32_t g = first_group; g != kNone; g = groups_[g].next_in_block) touched += groups_[g].size;
    const std::uint32_t untouched = range.size() - touched;
    if (untouched == 0 && groups_[first_group].next_in_block == kNone) return;  // one group: no split

    // Move the touched states to the tail of the range, then lay them out group by group.
    std::uint32_t tail = range.end;
    for (std::uint32_t g = first_group; g != kNone; g = groups_[g].next_in_block) {
      for (StateIndex s = groups_[g].first_state; s != kNone; s = next_in_group_[s]) swap_to(s, --tail);
    }
    std::uint32_t cursor = range.begin + untouched;
    const bool was_queued = range.queued;
    std::vector<BlockIndex>& parts = parts_;
    parts.clear();
    if (untouched > 0) {
      range.end = range.begin + untouched;
      parts.push_back(block);
    }
    for (std::uint32_t g = first_group; g != kNone; g = groups_[g].next_in_block) {
      const std::uint32_t begin = cursor;
      for (StateIndex s = groups_[g].first_state; s != kNone; s = next_in_group_[s]) place(s, cursor++);
      BlockIndex part = block;
      if (parts.empty()) {
        blocks_[block].begin = begin;
        blocks_[block].end = cursor;
      } else {
        part = static_cast<BlockIndex>(blocks_.size());
        blocks_.push_back({begin, cursor, false});
        for (std::uint32_t i = begin; i < cursor; ++i) block_of_[elements_[i]] = part;
      }
      parts.push_back(part);
    }
    queue_parts(parts, was_queued);
  }

  void queue_parts(const std::vector<BlockIndex>& parts, bool was_queued) {
    BlockIndex largest = parts.front();
    for (BlockIndex part : parts) {
      if (blocks_[part].size() > blocks_[largest].size()) largest = part;
    }
    for (BlockIndex part : parts) {
      if (blocks_[part].queued) continue;  // the original block, still waiting
      if (was_queued || part != largest) enqueue(part);
    }
  }

  void swap_to(StateIndex s, std::uint32_t target) {
    const StateIndex other = elements_[target];
    const std::uint32_t from = position_[s];
    elements_[target] = s;
    position_[s] = target;
    elements_[from] = other;
    position_[other] = from;
  }

  void place(StateIndex s, std::uint32_t target) { swap_to(s, target); }

  void reset_scratch() {
    for (ChoiceIndex c : touched_choices_) {
      touched_choice_[c] = false;
      choice_next_[c] = kNone;
      if (weights_.mode == WeightMode::Integer) integer_sum_[c] = 0;
      if (weights_.mode == WeightMode::Rounded) real_sum_[c] = 0;
      if (weights_.mode == WeightMode::Rational) rational_slot_[c] = kNone;
    }
    for (StateIndex s : touched_states_) {
      state_head_[s] = kNone;
      next_in_group_[s] = kNone;
    }
    for (BlockIndex b : touched_blocks_) block_first_group_[b] = kNone;
    touched_choices_.clear();
    touched_states_.clear();
    touched_blocks_.clear();
  }

  const model::ExplicitModel& model_;
  const model::TransitionMatrix& matrix_;
  std::size_t context_;
  const RefinementOptions& options_;
  std::uint32_t num_states_;
  std::uint32_t num_actions_;
  WeightTable weights_;
  RefinementStatistics statistics_;

  std::vector<EdgeIndex> in_begin_;
  std::vector<ChoiceIndex> in_choice_;
  std::vector<ValueId> in_probability_;

  std::vector<StateIndex> elements_;
  std::vector<std::uint32_t> position_;
  std::vector<BlockIndex> block_of_;
  std::vector<Block> blocks_;
  std::vector<BlockIndex> queue_;

  // Scratch for one splitter, reset after it.
  std::vector<std::uint64_t> integer_sum_;
  std::vector<double> real_sum_;
  std::vector<std::uint32_t> rational_slot_;
  std::vector<Rational> rational_sum_;
  std::vector<bool> touched_choice_;
  std::vector<ChoiceIndex> touched_choices_;
  std::vector<std::uint32_t> choice_next_;
  std::vector<std::uint32_t> state_head_;
  std::vector<StateIndex> touched_states_;
  std::vector<StateIndex> next_in_group_;
  std::vector<std::uint32_t> block_first_group_;  // indexed by block; blocks never exceed states
  std::vector<BlockIndex> touched_blocks_;
  std::vector<Group> groups_;
  std::vector<std::uint32_t> group_table_;
  std::vector<ChoiceIndex> signature_;
  std::vector<ChoiceIndex> other_signature_;
  std::vector<BlockIndex> parts_;
};

}  // namespace

Partition coarsest_bisimulation(const model::ExplicitModel& model, std::size_t context,
                                const RefinementOptions& options, RefinementStatistics* statistics) {
  return Refiner(model, context, options).run(statistics);
}

}  // namespace oasis::bisim
