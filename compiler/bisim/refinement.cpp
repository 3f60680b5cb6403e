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
// times: O(m log n) edge visits. Grouping reads each touched state's |A| choice records and
// hashes its signature: O(|A|) per touched state, charged to the edge that touched it, so
// O(|A| m log n) in all (|A| is a small constant for the models this tool is for).
// Memory: compact arrays only, 32-bit indices. Beyond the model, 4 bytes per edge (the
// reverse edges, packed: incoming_edges.hpp; 8 when a record does not fit in 32 bits), 8 per
// choice (choice_weight_) and 20 per state; docs/PERFORMANCE.md has the budget.

#include "bisim/refinement.hpp"

#include <algorithm>
#include <bit>
#include <chrono>
#include <limits>
#include <optional>
#include <stdexcept>

#include "bisim/incoming_edges.hpp"
#include "bisim/initial_partition.hpp"
#include "bisim/unlabelled_refinement.hpp"
#include "bisim/weights.hpp"
#include "support/hash.hpp"

namespace oasis::bisim {
namespace {

using model::ActionIndex;
using model::ChoiceIndex;
using model::EdgeIndex;
using model::StateIndex;

constexpr std::uint32_t kNone = std::numeric_limits<std::uint32_t>::max();

class Stopwatch {
 public:
  // Seconds since the previous lap (or construction).
  double lap() {
    const auto now = std::chrono::steady_clock::now();
    const double seconds = std::chrono::duration<double>(now - last_).count();
    last_ = now;
    return seconds;
  }

 private:
  std::chrono::steady_clock::time_point last_ = std::chrono::steady_clock::now();
};

class Refiner {
 public:
  Refiner(const model::ExplicitModel& model, std::size_t context, const RefinementOptions& options)
      : model_(model),
        matrix_(*model.contexts[context].transitions),
        context_(context),
        options_(options),
        num_states_(model.num_states()),
        num_actions_(model.num_actions()),
        weights_(
            WeightTable::choose(model, matrix_, options.rounding_step, options.rational_sums)) {}

  Partition run(RefinementStatistics* statistics) {
    statistics_.exact_integer_sums = weights_.mode == WeightMode::Integer;
    if (num_states_ == 0) return {};
    Stopwatch clock;
    build_reverse_edges();
    statistics_.setup_seconds = clock.lap();
    initial_partition();
    statistics_.initial_seconds = clock.lap();
    allocate_scratch();
    while (!queue_.empty()) {
      if (batch_pays_off()) {
        split_by_whole_queue();
      } else {
        const BlockIndex splitter = queue_.back();
        queue_.pop_back();
        dequeue(splitter);
        split_by(splitter);
        ++statistics_.splitters;
      }
      if (options_.progress && (++steps_ & 0x3FFFU) == 0) {
        options_.progress(
            {statistics_.splitters, queue_.size(), static_cast<std::uint32_t>(blocks_.size())});
      }
    }
    statistics_.splitting_seconds = clock.lap();
    if (statistics != nullptr) *statistics = statistics_;
    std::vector<BlockIndex> block_of(num_states_);
    for (StateIndex s = 0; s < num_states_; ++s)
      block_of[s] = state_scratch_[s].block;
    return model::canonical_partition(block_of);
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
    StateIndex first_state;       // list through StateScratch::next_in_group
    std::uint32_t next_in_block;  // list of the block's groups
    std::uint32_t next_same_hash;
    std::uint32_t signature_begin;  // the representative's signature in group_signatures_
    std::uint32_t signature_end;
  };

  // One (action, weight) pair of a signature. `key` is the integer sum (Integer mode), the
  // rounded sum (Rounded) or the slot of the exact sum in rational_sum_ (Rational).
  struct SignatureEntry {
    ActionIndex action;
    std::uint32_t splitter;  // batch passes: which queued splitter; 0 otherwise
    std::uint64_t key;
    double real = 0;  // batch passes in Rounded mode: the unrounded sum
  };

  // Per state: its block and position (kept), whether the splitter touched it and its next
  // state in its group (scratch). One record, so that a state costs one cache miss.
  struct StateScratch {
    BlockIndex block = 0;
    std::uint32_t position = 0;
    std::uint32_t touched = 0;
    StateIndex next_in_group = kNone;
  };

  // ---- set-up -----------------------------------------------------------------------------

  void build_reverse_edges() { incoming_.emplace(matrix_); }

  void initial_partition() {
    const InitialBlocks initial =
        blocks_by_rewards(model_, context_, options_.rounding_step, options_.label_class);
    state_scratch_.resize(num_states_);
    std::vector<std::uint32_t> sizes(initial.count, 0);
    for (StateIndex s = 0; s < num_states_; ++s) {
      state_scratch_[s].block = initial.block_of[s];
      ++sizes[initial.block_of[s]];
    }
    place_initial_blocks(sizes);
    statistics_.initial_blocks = static_cast<std::uint32_t>(blocks_.size());
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
    for (StateIndex s = 0; s < num_states_; ++s) {
      StateScratch& state = state_scratch_[s];
      Block& block = blocks_[state.block];
      state.position = block.end;
      elements_[block.end++] = s;
    }
    for (BlockIndex b = 0; b < blocks_.size(); ++b) {
      if (b != largest) enqueue(b);
    }
  }

  void allocate_scratch() {
    const std::size_t num_choices = std::size_t{num_states_} * num_actions_;
    choice_weight_.assign(num_choices, 0);
    block_first_group_.assign(num_states_, kNone);
  }

  void enqueue(BlockIndex block, bool count_edges = true) {
    blocks_[block].queued = true;
    queue_.push_back(block);
    if (count_edges) queued_edges_ += incoming_edges(block);
  }

  void dequeue(BlockIndex block) {
    blocks_[block].queued = false;
    queued_edges_ -= incoming_edges(block);
  }

  // Edges into the block's states. Summing costs the block's size; a state is enqueued
  // O(log n) times, so this adds O(n log n) in all.
  [[nodiscard]] std::uint64_t incoming_edges(BlockIndex block) const {
    std::uint64_t count = 0;
    for (std::uint32_t i = blocks_[block].begin; i < blocks_[block].end; ++i) {
      const StateIndex t = elements_[i];
      count += incoming_->end(t) - incoming_->begin(t);
    }
    return count;
  }

  // ---- the whole queue at once ------------------------------------------------------------
  //
  // When the queued splitters together receive a large share of the edges, walking their
  // incoming edges one splitter at a time scatters reads and writes over the whole model.
  // Then one forward pass over every choice, in memory order, computes each state's weight
  // to every queued splitter at once; blocks split by the joint signature. This is the same
  // refinement as taking the splitters one by one (a state's weights to several splitters
  // separate it exactly when the weights to some one of them do), the queue rule for the
  // parts is unchanged, and the pass costs O(m + n |A|), charged to the >= m / 4 edge
  // visits it replaces, so the O(m log n) bound stands. Exact rational sums are left to the
  // one-splitter path.

  [[nodiscard]] bool batch_pays_off() const {
    return weights_.mode != WeightMode::Rational && queued_edges_ * 4 >= incoming_->size() &&
           queue_.size() > 1;
  }

  void split_by_whole_queue() {
    if (batch_slot_.size() < blocks_.size()) batch_slot_.resize(blocks_.size(), kNone);
    for (std::size_t i = 0; i < queue_.size(); ++i) {
      batch_slot_[queue_[i]] = static_cast<std::uint32_t>(i);
      blocks_[queue_[i]].queued = false;
    }
    const std::vector<BlockIndex> batch = std::move(queue_);
    queue_.clear();
    queued_edges_ = 0;
    statistics_.splitters += batch.size();
    statistics_.edge_visits += incoming_->size();
    ++statistics_.batch_passes;

    groups_.clear();
    group_signatures_.clear();
    std::size_t table_size = 16;
    while (table_size < 2 * std::size_t{num_states_})
      table_size *= 2;
    group_table_.assign(table_size, kNone);
    for (StateIndex s = 0; s < num_states_; ++s) {
      batch_signature(s, signature_);
      if (!signature_.empty()) add_to_group(s, signature_);
    }
    for (BlockIndex b : batch)
      batch_slot_[b] = kNone;
    split_touched_blocks();
    reset_scratch();
  }

  // For each enabled action of `s`, the weight to each queued splitter its edges reach, in
  // (action, splitter) order. Empty when no edge reaches a splitter.
  void batch_signature(StateIndex s, std::vector<SignatureEntry>& out) {
    out.clear();
    constexpr std::uint32_t kAhead = 16;
    for (ActionIndex a = 0; a < num_actions_; ++a) {
      const ChoiceIndex c = s * num_actions_ + a;
      const std::size_t first = out.size();
      for (EdgeIndex e = matrix_.choice_begin[c]; e < matrix_.choice_begin[c + 1]; ++e) {
        if (e + kAhead < matrix_.edge_target.size()) {
          __builtin_prefetch(&state_scratch_[matrix_.edge_target[e + kAhead]]);
        }
        const std::uint32_t slot = batch_slot_[state_scratch_[matrix_.edge_target[e]].block];
        if (slot == kNone) continue;
        add_batch_weight(out, first, a, slot, matrix_.edge_probability[e]);
      }
      std::sort(
          out.begin() + static_cast<std::ptrdiff_t>(first), out.end(),
          [](const SignatureEntry& x, const SignatureEntry& y) { return x.splitter < y.splitter; });
    }
  }

  void add_batch_weight(std::vector<SignatureEntry>& out, std::size_t first, ActionIndex a,
                        std::uint32_t slot, ValueId probability) const {
    for (std::size_t i = first; i < out.size(); ++i) {
      if (out[i].splitter == slot) {
        add_to_key(out[i], probability);
        return;
      }
    }
    out.push_back({a, slot, 0});
    add_to_key(out.back(), probability);
  }

  // Rounded keys are summed as doubles in `real` and rounded by finish_batch_key().
  void add_to_key(SignatureEntry& entry, ValueId probability) const {
    if (weights_.mode == WeightMode::Integer) {
      entry.key += weights_.integer[probability];
    } else {
      entry.real += weights_.real[probability];
      entry.key = static_cast<std::uint64_t>(weights_.rounded_key(entry.real));
    }
  }

  // ---- one splitter -----------------------------------------------------------------------

  void split_by(BlockIndex splitter) {
    accumulate_weights(splitter);
    group_touched_states();
    split_touched_blocks();
    reset_scratch();
  }

  // Random access into the per-choice and per-state records dominates on large models, so
  // the records of edges a few steps ahead are prefetched.
  void accumulate_weights(BlockIndex splitter) {
    constexpr std::uint32_t kAhead = 16;
    const Block block = blocks_[splitter];
    for (std::uint32_t i = block.begin; i < block.end; ++i) {
      if (i + kAhead < block.end) incoming_->prefetch(elements_[i + kAhead]);
      const StateIndex t = elements_[i];
      const EdgeIndex end = incoming_->end(t);
      statistics_.edge_visits += end - incoming_->begin(t);
      for (EdgeIndex e = incoming_->begin(t); e < end; ++e) {
        if (e + kAhead < incoming_->size()) {
          const ChoiceIndex ahead = incoming_->choice(e + kAhead);
          __builtin_prefetch(&choice_weight_[ahead], 1);
          __builtin_prefetch(&state_scratch_[ahead / num_actions_], 1);
        }
        add_weight(incoming_->choice(e), incoming_->probability(e));
      }
    }
  }

  void add_weight(ChoiceIndex c, ValueId probability) {
    std::uint64_t& weight = choice_weight_[c];
    if (weight == 0) {
      const StateIndex s = c / num_actions_;
      std::uint32_t& state_touched = state_scratch_[s].touched;
      if (state_touched == 0) touched_states_.push_back(s);
      state_touched = 1;
      if (weights_.mode == WeightMode::Rational) {
        if (rational_sum_.size() == rational_sums_used_) rational_sum_.emplace_back();
        rational_sum_[rational_sums_used_] = 0;
        weight = ++rational_sums_used_;
      }
    }
    switch (weights_.mode) {
      case WeightMode::Integer:
        weight += weights_.integer[probability];
        break;
      case WeightMode::Rounded: {
        const double sum = std::bit_cast<double>(weight) + weights_.real[probability];
        weight = sum == 0 ? kReachedZero : std::bit_cast<std::uint64_t>(sum);
        break;
      }
      case WeightMode::Rational:
        rational_sum_[weight - 1] += model_.values[probability];
        break;
    }
  }

  // The touched choices of `s` in action order, with their weights: its signature. The
  // choice records are cleared on the way, while their cache line is at hand. Costs O(|A|)
  // per touched state: one cache line for the small action sets of robot models.
  void collect_signature(StateIndex s, std::vector<SignatureEntry>& out) {
    out.clear();
    const ChoiceIndex first = s * num_actions_;
    for (ActionIndex a = 0; a < num_actions_; ++a) {
      std::uint64_t& weight = choice_weight_[first + a];
      if (weight == 0) continue;
      switch (weights_.mode) {
        case WeightMode::Integer:
          out.push_back({a, 0, weight});
          break;
        case WeightMode::Rounded:
          out.push_back(
              {a, 0,
               static_cast<std::uint64_t>(weights_.rounded_key(std::bit_cast<double>(weight)))});
          break;
        case WeightMode::Rational:
          out.push_back({a, 0, weight - 1});
          break;
      }
      weight = 0;
    }
  }

  [[nodiscard]] std::uint64_t entry_hash(const SignatureEntry& entry) const {
    if (weights_.mode == WeightMode::Rational) return hash_value(rational_sum_[entry.key]);
    return entry.key;
  }

  [[nodiscard]] bool same_entry(const SignatureEntry& a, const SignatureEntry& b) const {
    if (a.action != b.action || a.splitter != b.splitter) return false;
    if (weights_.mode == WeightMode::Rational) return rational_sum_[a.key] == rational_sum_[b.key];
    return a.key == b.key;
  }

  [[nodiscard]] std::uint64_t signature_hash(BlockIndex block,
                                             const std::vector<SignatureEntry>& signature) const {
    std::uint64_t hash = mix_bits(block + 0x9e3779b97f4a7c15ULL);
    for (const SignatureEntry& entry : signature) {
      hash = mix_bits(hash ^ entry.action ^ (std::uint64_t{entry.splitter} << 32U)) ^
             mix_bits(entry_hash(entry));
    }
    return hash;
  }

  [[nodiscard]] bool same_signature(const std::vector<SignatureEntry>& a,
                                    const Group& group) const {
    if (a.size() != group.signature_end - group.signature_begin) return false;
    for (std::size_t i = 0; i < a.size(); ++i) {
      if (!same_entry(a[i], group_signatures_[group.signature_begin + i])) return false;
    }
    return true;
  }

  // Groups are found through an open-addressing table sized for this splitter's touched
  // states, so that clearing it costs what the splitter touched, not the largest splitter
  // seen so far. Each slot heads a chain of groups whose signature hashes collide there.
  void group_touched_states() {
    groups_.clear();
    group_signatures_.clear();
    std::size_t table_size = 16;
    while (table_size < 2 * touched_states_.size())
      table_size *= 2;
    group_table_.assign(table_size, kNone);
    constexpr std::size_t kAhead = 8;
    for (std::size_t i = 0; i < touched_states_.size(); ++i) {
      if (i + kAhead < touched_states_.size()) {
        const StateIndex ahead = touched_states_[i + kAhead];
        __builtin_prefetch(&state_scratch_[ahead]);
        __builtin_prefetch(&choice_weight_[std::size_t{ahead} * num_actions_]);
      }
      const StateIndex s = touched_states_[i];
      collect_signature(s, signature_);
      add_to_group(s, signature_);
    }
  }

  // Puts `s` into the group of its block with the same signature, making one if needed.
  void add_to_group(StateIndex s, const std::vector<SignatureEntry>& signature) {
    const BlockIndex block = state_scratch_[s].block;
    const std::uint64_t hash = signature_hash(block, signature);
    std::uint32_t& head = group_table_[hash & (group_table_.size() - 1)];
    std::uint32_t group = head;
    for (; group != kNone; group = groups_[group].next_same_hash) {
      if (groups_[group].block == block && same_signature(signature, groups_[group])) break;
    }
    if (group == kNone) {
      group = static_cast<std::uint32_t>(groups_.size());
      const auto begin = static_cast<std::uint32_t>(group_signatures_.size());
      group_signatures_.insert(group_signatures_.end(), signature.begin(), signature.end());
      groups_.push_back({s, block, 0, kNone, block_first_group_[block], head, begin,
                         static_cast<std::uint32_t>(group_signatures_.size())});
      head = group;
      if (block_first_group_[block] == kNone) touched_blocks_.push_back(block);
      block_first_group_[block] = group;
    }
    state_scratch_[s].next_in_group = groups_[group].first_state;
    state_scratch_[s].touched = 1;
    groups_[group].first_state = s;
    ++groups_[group].size;
  }

  void split_touched_blocks() {
    for (BlockIndex block : touched_blocks_)
      split_block(block);
  }

  // Rearranges the block's range as [untouched | group 1 | group 2 | ...] and makes every
  // group a block of its own (the first group keeps the block's index when nothing is
  // untouched).
  void split_block(BlockIndex block) {
    const std::uint32_t first_group = block_first_group_[block];
    Block& range = blocks_[block];
    std::uint32_t touched = 0;
    for (std::uint32_t g = first_group; g != kNone; g = groups_[g].next_in_block)
      touched += groups_[g].size;
    const std::uint32_t untouched = range.size() - touched;
    if (untouched == 0 && groups_[first_group].next_in_block == kNone) {  // one group: no split
      for (StateIndex s = groups_[first_group].first_state; s != kNone;)
        s = clear_state(s);
      return;
    }

    // Move the touched states to the tail of the range, then lay them out group by group.
    std::uint32_t tail = range.end;
    for (std::uint32_t g = first_group; g != kNone; g = groups_[g].next_in_block) {
      for (StateIndex s = groups_[g].first_state; s != kNone; s = state_scratch_[s].next_in_group)
        swap_to(s, --tail);
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
      for (StateIndex s = groups_[g].first_state; s != kNone;) {
        swap_to(s, cursor++);
        s = clear_state(s);
      }
      BlockIndex part = block;
      if (parts.empty()) {
        blocks_[block].begin = begin;
        blocks_[block].end = cursor;
      } else {
        part = static_cast<BlockIndex>(blocks_.size());
        blocks_.push_back({begin, cursor, false});
        for (std::uint32_t i = begin; i < cursor; ++i)
          state_scratch_[elements_[i]].block = part;
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
      // Parts carved out of a queued block bring edges already counted in queued_edges_.
      if (was_queued) {
        enqueue(part, /*count_edges=*/false);
      } else if (part != largest) {
        enqueue(part);
      }
    }
  }

  void swap_to(StateIndex s, std::uint32_t target) {
    const StateIndex other = elements_[target];
    const std::uint32_t from = state_scratch_[s].position;
    elements_[target] = s;
    state_scratch_[s].position = target;
    elements_[from] = other;
    state_scratch_[other].position = from;
  }

  // Clears a touched state's scratch and returns the next state of its group.
  StateIndex clear_state(StateIndex s) {
    StateScratch& state = state_scratch_[s];
    const StateIndex next = state.next_in_group;
    state.touched = 0;
    state.next_in_group = kNone;
    return next;
  }

  // Choice and state records were cleared while grouping and splitting; what is left is
  // the bookkeeping of this splitter.
  void reset_scratch() {
    for (BlockIndex b : touched_blocks_)
      block_first_group_[b] = kNone;
    rational_sums_used_ = 0;
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

  std::optional<IncomingEdges> incoming_;  // built by build_reverse_edges()

  std::vector<StateIndex> elements_;
  std::vector<StateScratch> state_scratch_;
  std::vector<Block> blocks_;
  std::vector<BlockIndex> queue_;
  std::uint64_t queued_edges_ = 0;  // edges into the queued blocks
  std::uint64_t steps_ = 0;
  std::vector<std::uint32_t> batch_slot_;  // per block: its index in the batch, or kNone

  // Scratch for one splitter, reset after it.
  // Per choice, the weight an edge into the current splitter gave it, in 64 bits whose 0
  // means "no edge reached the choice". The choices of a state are adjacent (s * |A| + a),
  // so a state's signature is one short scan, usually within one cache line. By mode:
  //   Integer:  the integer sum; every probability is at least 1 / D, so a reached choice
  //             sums to at least 1.
  //   Rounded:  the bits of the double sum; a reached choice whose sum is 0 (a weight too
  //             small for a double) holds kReachedZero, the bits of -0.0, so it reads as 0.
  //   Rational: one more than the index of its exact sum in rational_sum_.
  // 8 bytes per choice in every mode: one array, instead of a flag beside each sum.
  std::vector<std::uint64_t> choice_weight_;
  static constexpr std::uint64_t kReachedZero = std::uint64_t{1} << 63U;
  std::vector<Rational> rational_sum_;
  std::size_t rational_sums_used_ = 0;  // for the current splitter
  std::vector<StateIndex> touched_states_;
  std::vector<std::uint32_t> block_first_group_;  // indexed by block; blocks never exceed states
  std::vector<BlockIndex> touched_blocks_;
  std::vector<Group> groups_;
  std::vector<std::uint32_t> group_table_;
  std::vector<SignatureEntry> signature_;
  std::vector<SignatureEntry> group_signatures_;
  std::vector<BlockIndex> parts_;
};

}  // namespace

Partition coarsest_bisimulation(const model::ExplicitModel& model, std::size_t context,
                                const RefinementOptions& options,
                                RefinementStatistics* statistics) {
  if (options.unlabelled_choices) {
    if (options.rounding_step)
      throw std::invalid_argument("unlabelled choices are compared exactly only");
    return coarsest_unlabelled_bisimulation(model, context, options, statistics);
  }
  return Refiner(model, context, options).run(statistics);
}

}  // namespace oasis::bisim
