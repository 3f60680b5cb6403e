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
// times: O(m log n) edge visits. Grouping reads each touched state's |A| weights and
// hashes its signature: O(|A|) per touched state, charged to the edge that touched it, so
// O(|A| m log n) in all (|A| is a small constant for the models this tool is for).
// Memory: compact arrays only, 32-bit indices. Beyond the model, 4 bytes per edge (the
// reverse edges, packed: incoming_edges.hpp; 8 when a record does not fit in 32 bits; built
// only once a splitter is walked alone) and 20 per state (block, position, mark, elements,
// reverse-edge offsets); per block 20 bytes. Scratch is sized by what one splitter touches, or
// by one block in a batch pass: never by the choices, nor by all blocks' groups at once.
// docs/PERFORMANCE.md has the budget.

#include "bisim/refinement.hpp"

#include <algorithm>
#include <bit>
#include <chrono>
#include <limits>
#include <optional>
#include <span>
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
    mark_.assign(num_states_, kNone);
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
    return canonical_blocks();
  }

 private:
  struct Block {
    std::uint32_t begin;
    std::uint32_t end;
    bool queued;
    [[nodiscard]] std::uint32_t size() const { return end - begin; }
  };

  // A set of touched states of one block with the same signature. Its states are
  // members_[member_begin, member_begin + size) once grouping is done.
  struct Group {
    std::uint64_t hash;
    BlockIndex block;
    std::uint32_t size;
    std::uint32_t member_begin;
    std::uint32_t next_in_block;  // list of the block's groups
    std::uint32_t next_same_hash;
    std::uint32_t signature_begin;  // its signature in group_signatures_
    std::uint32_t signature_end;
  };

  // One (action, weight) pair of a signature. `key` is the integer sum (Integer mode), the
  // rounded sum (Rounded; while a batch pass sums, the bits of the double sum) or the slot of
  // the exact sum in rational_sum_ (Rational).
  struct SignatureEntry {
    ActionIndex action;
    std::uint32_t splitter;  // batch passes: which queued splitter; 0 otherwise
    std::uint64_t key;
  };

  // ---- set-up -----------------------------------------------------------------------------

  // Their offsets now; their records when the first splitter is walked alone (split_by).
  void build_reverse_edges() { incoming_.emplace(IncomingEdges::offsets_only(matrix_)); }

  void initial_partition() {
    InitialBlocks initial =
        blocks_by_rewards(model_, context_, options_.rounding_step, options_.label_class);
    block_ = std::move(initial.block_of);
    std::vector<std::uint32_t> sizes(initial.count, 0);
    for (StateIndex s = 0; s < num_states_; ++s)
      ++sizes[block_[s]];
    place_initial_blocks(sizes);
    statistics_.initial_blocks = static_cast<std::uint32_t>(blocks_.size());
  }

  void place_initial_blocks(const std::vector<std::uint32_t>& sizes) {
    std::uint32_t begin = 0;
    BlockIndex largest = 0;
    for (BlockIndex b = 0; b < sizes.size(); ++b) {
      add_block(begin, begin, kNone);
      begin += sizes[b];
      if (sizes[b] > sizes[largest]) largest = b;
    }
    elements_.resize(num_states_);
    position_.resize(num_states_);
    for (StateIndex s = 0; s < num_states_; ++s) {
      Block& block = blocks_[block_[s]];
      position_[s] = block.end;
      elements_[block.end++] = s;
    }
    for (BlockIndex b = 0; b < blocks_.size(); ++b) {
      if (b != largest) enqueue(b);
    }
  }

  // Every per-block array grows with blocks_, so that none is sized by the states.
  // `batch_slot` is the new block's splitter slot in a running batch pass (kNone outside).
  BlockIndex add_block(std::uint32_t begin, std::uint32_t end, std::uint32_t batch_slot) {
    const auto block = static_cast<BlockIndex>(blocks_.size());
    blocks_.push_back({begin, end, false});
    block_first_group_.push_back(kNone);
    batch_slot_.push_back(batch_slot);
    return block;
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

  // The result: blocks numbered in order of their smallest state (model::Partition). Refinement's
  // arrays are released first, so the partition is built beside the model alone.
  Partition canonical_blocks() {
    incoming_.reset();
    std::vector<std::uint32_t>().swap(mark_);
    std::vector<std::uint32_t>().swap(position_);
    std::vector<StateIndex>().swap(elements_);
    std::vector<std::uint64_t>().swap(touched_weights_);
    std::vector<BlockIndex> number(blocks_.size(), kNone);
    Partition partition;
    for (StateIndex s = 0; s < num_states_; ++s) {
      BlockIndex& renumbered = number[block_[s]];
      if (renumbered == kNone) renumbered = partition.num_blocks++;
      block_[s] = renumbered;
    }
    partition.block_of = std::move(block_);
    return partition;
  }

  // ---- the whole queue at once ------------------------------------------------------------
  //
  // When the queued splitters together receive a large share of the edges, walking their
  // incoming edges one splitter at a time scatters reads and writes over the whole model.
  // Then one forward pass over every choice computes each state's weight to every queued
  // splitter at once; blocks split by the joint signature. This is the same refinement as
  // taking the splitters one by one (a state's weights to several splitters separate it
  // exactly when the weights to some one of them do), the queue rule for the parts is
  // unchanged, and the pass costs O(m + n |A|), charged to the >= m / 4 edge visits it
  // replaces, so the O(m log n) bound stands. Exact rational sums are left to the one-splitter
  // path.
  //
  // The pass goes block by block, and each block is split as soon as its states are grouped:
  // the groups and their signatures are those of one block, never of the whole model (with
  // 250,000 blocks they were the refinement's largest structure). Splitting a block while the
  // pass runs changes no weight that the pass has still to compute, because a part of a queued
  // splitter takes the splitter's slot (add_block): a weight is always to the splitter as the
  // pass found it.

  [[nodiscard]] bool batch_pays_off() const {
    return weights_.mode != WeightMode::Rational && queued_edges_ * 4 >= incoming_->size() &&
           queue_.size() > 1;
  }

  void split_by_whole_queue() {
    for (std::size_t i = 0; i < queue_.size(); ++i) {
      batch_slot_[queue_[i]] = static_cast<std::uint32_t>(i);
      blocks_[queue_[i]].queued = false;
    }
    statistics_.splitters += queue_.size();
    queue_.clear();
    queued_edges_ = 0;
    statistics_.edge_visits += incoming_->size();
    ++statistics_.batch_passes;

    // Each state's slot, so that an edge costs one lookup, not two; parts inherit their
    // block's slot, so these stay right while blocks split.
    for (StateIndex t = 0; t < num_states_; ++t)
      mark_[t] = batch_slot_[block_[t]];
    // The blocks' ranges tile elements_: taken in that order, the states ahead are known
    // across the end of a block, for prefetching. A split keeps its parts inside the block's
    // range, so the next range starts where the block ended.
    for (std::uint32_t begin = 0; begin < num_states_;) {
      const BlockIndex block = block_[elements_[begin]];
      const std::uint32_t end = blocks_[block].end;
      group_block_by_batch_signature(block);
      if (!touched_states_.empty()) {
        place_members();
        split_touched_blocks();
        reset_scratch();
      }
      begin = end;
    }
    std::fill(batch_slot_.begin(), batch_slot_.end(), kNone);
    std::fill(mark_.begin(), mark_.end(), kNone);
  }

  // Groups the states of `block` that some queued splitter's edges reach by their weights to
  // the splitters. The states are visited in the blocks' order, not in memory order, so the
  // reads of their choices are prefetched a few states ahead (in elements_, past the block's
  // end): first the choice offsets, then both ends of the edges, then the slots of the targets.
  void group_block_by_batch_signature(BlockIndex block) {
    start_grouping();
    const std::uint32_t begin = blocks_[block].begin;
    const std::uint32_t end = blocks_[block].end;
    const std::uint32_t k = num_actions_;
    for (std::uint32_t i = begin; i < end; ++i) {
      if (i + 16 < num_states_)
        __builtin_prefetch(&matrix_.choice_begin[std::size_t{elements_[i + 16]} * k]);
      if (i + 8 < num_states_) {
        const ChoiceIndex c = elements_[i + 8] * k;
        const EdgeIndex first = matrix_.choice_begin[c];
        const EdgeIndex past = matrix_.choice_begin[c + k];
        if (first < past) {
          __builtin_prefetch(&matrix_.edge_target[first]);
          __builtin_prefetch(&matrix_.edge_probability[first]);
          __builtin_prefetch(&matrix_.edge_target[past - 1]);
          __builtin_prefetch(&matrix_.edge_probability[past - 1]);
        }
      }
      if (i + 4 < num_states_) {
        const ChoiceIndex c = elements_[i + 4] * k;
        for (EdgeIndex e = matrix_.choice_begin[c]; e < matrix_.choice_begin[c + k]; ++e)
          __builtin_prefetch(&mark_[matrix_.edge_target[e]]);
      }
      const StateIndex s = elements_[i];
      batch_signature(s, signature_);
      if (signature_.empty()) continue;
      touched_states_.push_back(s);
      touched_group_.push_back(add_to_group(block, signature_));
    }
  }

  // For each enabled action of `s`, the weight to each queued splitter its edges reach, in
  // (action, splitter) order. Empty when no edge reaches a splitter. `out` is sized for one
  // entry per edge first, so that adding one is a store, not a push_back.
  void batch_signature(StateIndex s, std::vector<SignatureEntry>& out) const {
    const ChoiceIndex choices = s * num_actions_;
    out.resize(matrix_.choice_begin[choices + num_actions_] - matrix_.choice_begin[choices]);
    std::size_t size = 0;
    for (ActionIndex a = 0; a < num_actions_; ++a) {
      const ChoiceIndex c = choices + a;
      const std::size_t first = size;
      for (EdgeIndex e = matrix_.choice_begin[c]; e < matrix_.choice_begin[c + 1]; ++e) {
        const std::uint32_t slot = mark_[matrix_.edge_target[e]];
        if (slot == kNone) continue;
        std::size_t i = first;
        while (i < size && out[i].splitter != slot)
          ++i;
        if (i == size) out[size++] = {a, slot, 0};
        add_to_key(out[i], matrix_.edge_probability[e]);
      }
      // By splitter: an insertion sort, as an action reaches few splitters.
      for (std::size_t i = first + 1; i < size; ++i) {
        const SignatureEntry entry = out[i];
        std::size_t j = i;
        for (; j > first && entry.splitter < out[j - 1].splitter; --j)
          out[j] = out[j - 1];
        out[j] = entry;
      }
    }
    out.resize(size);
    if (weights_.mode == WeightMode::Rounded) {
      for (SignatureEntry& entry : out)
        entry.key =
            static_cast<std::uint64_t>(weights_.rounded_key(std::bit_cast<double>(entry.key)));
    }
  }

  // Rounded keys are summed as doubles in the key's bits (0 is +0.0) and rounded at the end
  // of the state (batch_signature).
  void add_to_key(SignatureEntry& entry, ValueId probability) const {
    if (weights_.mode == WeightMode::Integer) {
      entry.key += weights_.integer[probability];
    } else {
      entry.key = std::bit_cast<std::uint64_t>(std::bit_cast<double>(entry.key) +
                                               weights_.real[probability]);
    }
  }

  // ---- one splitter -----------------------------------------------------------------------

  void split_by(BlockIndex splitter) {
    incoming_->build_records(matrix_);
    accumulate_weights(splitter);
    group_touched_states();
    place_members();
    split_touched_blocks();
    for (StateIndex s : touched_states_)
      mark_[s] = kNone;
    reset_scratch();
  }

  // Random access into the per-state marks dominates on large models, so the marks of the
  // sources of edges a few steps ahead are prefetched.
  void accumulate_weights(BlockIndex splitter) {
    constexpr std::uint32_t kAhead = 16;
    const Block block = blocks_[splitter];
    for (std::uint32_t i = block.begin; i < block.end; ++i) {
      if (i + kAhead < block.end) incoming_->prefetch(elements_[i + kAhead]);
      const StateIndex t = elements_[i];
      const EdgeIndex end = incoming_->end(t);
      statistics_.edge_visits += end - incoming_->begin(t);
      for (EdgeIndex e = incoming_->begin(t); e < end; ++e) {
        if (e + kAhead < incoming_->size())
          __builtin_prefetch(&mark_[incoming_->choice(e + kAhead) / num_actions_], 1);
        add_weight(incoming_->choice(e), incoming_->probability(e));
      }
    }
  }

  // A state's first touch gives it the next slot of touched_weights_, |A| words that hold the
  // weights of its choices; its mark is that slot until it is grouped.
  void add_weight(ChoiceIndex c, ValueId probability) {
    const StateIndex s = c / num_actions_;
    const ActionIndex a = c - s * num_actions_;
    std::uint32_t& slot = mark_[s];
    if (slot == kNone) {
      slot = static_cast<std::uint32_t>(touched_states_.size());
      touched_states_.push_back(s);
      const std::size_t needed = touched_states_.size() * num_actions_;
      if (touched_weights_.size() < needed) touched_weights_.resize(needed, 0);
    }
    std::uint64_t& weight = touched_weights_[std::size_t{slot} * num_actions_ + a];
    if (weight == 0 && weights_.mode == WeightMode::Rational) {
      if (rational_sum_.size() == rational_sums_used_) rational_sum_.emplace_back();
      rational_sum_[rational_sums_used_] = 0;
      weight = ++rational_sums_used_;
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

  // The touched choices of the state in `slot`, in action order, with their weights: its
  // signature. The weights are cleared on the way, so that touched_weights_ is all zero
  // again for the next splitter.
  void collect_signature(std::uint32_t slot, std::vector<SignatureEntry>& out) {
    out.clear();
    const std::size_t first = std::size_t{slot} * num_actions_;
    for (ActionIndex a = 0; a < num_actions_; ++a) {
      std::uint64_t& weight = touched_weights_[first + a];
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

  void group_touched_states() {
    start_grouping();
    for (std::uint32_t slot = 0; slot < touched_states_.size(); ++slot) {
      collect_signature(slot, signature_);
      touched_group_.push_back(add_to_group(block_[touched_states_[slot]], signature_));
    }
  }

  // ---- grouping ---------------------------------------------------------------------------
  //
  // Groups are found through an open-addressing table of chains, grown with the groups, so
  // that it costs what this splitter (or this block of a batch pass) made, not the largest
  // seen so far. Each slot heads a chain of groups whose signature hashes collide there.

  [[nodiscard]] std::uint64_t entry_hash(const SignatureEntry& entry) const {
    if (weights_.mode == WeightMode::Rational) return hash_value(rational_sum_[entry.key]);
    return entry.key;
  }

  [[nodiscard]] bool same_entry(const SignatureEntry& a, const SignatureEntry& b) const {
    if (a.action != b.action || a.splitter != b.splitter) return false;
    if (weights_.mode == WeightMode::Rational) return rational_sum_[a.key] == rational_sum_[b.key];
    return a.key == b.key;
  }

  // One mix per entry: equal hashes are compared entry by entry anyway.
  [[nodiscard]] std::uint64_t signature_hash(BlockIndex block,
                                             const std::vector<SignatureEntry>& signature) const {
    constexpr std::uint64_t kOdd = 0x9e3779b97f4a7c15ULL;
    std::uint64_t hash = block;
    for (const SignatureEntry& entry : signature) {
      const std::uint64_t where = (std::uint64_t{entry.splitter} << 32U) | entry.action;
      hash = mix_bits(hash + where * kOdd + entry_hash(entry));
    }
    return mix_bits(hash);
  }

  [[nodiscard]] bool same_signature(const std::vector<SignatureEntry>& a,
                                    const Group& group) const {
    if (a.size() != group.signature_end - group.signature_begin) return false;
    for (std::size_t i = 0; i < a.size(); ++i) {
      if (!same_entry(a[i], group_signatures_[group.signature_begin + i])) return false;
    }
    return true;
  }

  void start_grouping() {
    groups_.clear();
    group_signatures_.clear();
    group_table_.assign(kInitialTableSize, kNone);
  }

  // Counts a state into the group of its block with the same signature, making one if needed;
  // returns the group.
  std::uint32_t add_to_group(BlockIndex block, const std::vector<SignatureEntry>& signature) {
    const std::uint64_t hash = signature_hash(block, signature);
    std::uint32_t& head = group_table_[hash & (group_table_.size() - 1)];
    std::uint32_t group = head;
    for (; group != kNone; group = groups_[group].next_same_hash) {
      const Group& candidate = groups_[group];
      if (candidate.hash == hash && candidate.block == block &&
          same_signature(signature, candidate))
        break;
    }
    if (group == kNone) {
      group = static_cast<std::uint32_t>(groups_.size());
      const auto begin = static_cast<std::uint32_t>(group_signatures_.size());
      group_signatures_.insert(group_signatures_.end(), signature.begin(), signature.end());
      groups_.push_back({hash, block, 0, 0, block_first_group_[block], head, begin,
                         static_cast<std::uint32_t>(group_signatures_.size())});
      head = group;
      if (block_first_group_[block] == kNone) touched_blocks_.push_back(block);
      block_first_group_[block] = group;
      if (groups_.size() * 2 > group_table_.size()) grow_group_table();
    }
    ++groups_[group].size;
    return group;
  }

  // Twice the slots, every group chained again by its hash (the table stays at most half full).
  void grow_group_table() {
    group_table_.assign(group_table_.size() * 2, kNone);
    const std::size_t mask = group_table_.size() - 1;
    for (std::uint32_t g = 0; g < groups_.size(); ++g) {
      std::uint32_t& head = group_table_[groups_[g].hash & mask];
      groups_[g].next_same_hash = head;
      head = g;
    }
  }

  // Lists the touched states group by group in members_ (a counting sort by their marks).
  void place_members() {
    std::uint32_t next = 0;
    for (Group& group : groups_) {
      group.member_begin = next;
      next += group.size;
    }
    members_.resize(next);
    for (std::size_t i = 0; i < touched_states_.size(); ++i)
      members_[groups_[touched_group_[i]].member_begin++] = touched_states_[i];
    for (Group& group : groups_)
      group.member_begin -= group.size;
  }

  // ---- splitting --------------------------------------------------------------------------

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
    if (untouched == 0 && groups_[first_group].next_in_block == kNone) return;  // one group

    // Move the touched states to the tail of the range, then lay them out group by group.
    std::uint32_t tail = range.end;
    for (std::uint32_t g = first_group; g != kNone; g = groups_[g].next_in_block) {
      for (StateIndex s : group_members(groups_[g]))
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
      for (StateIndex s : group_members(groups_[g]))
        swap_to(s, cursor++);
      BlockIndex part = block;
      if (parts.empty()) {
        blocks_[block].begin = begin;
        blocks_[block].end = cursor;
      } else {
        part = add_block(begin, cursor, batch_slot_[block]);
        for (std::uint32_t i = begin; i < cursor; ++i)
          block_[elements_[i]] = part;
      }
      parts.push_back(part);
    }
    queue_parts(parts, was_queued);
  }

  [[nodiscard]] std::span<const StateIndex> group_members(const Group& group) const {
    return {members_.data() + group.member_begin, group.size};
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
    const std::uint32_t from = position_[s];
    elements_[target] = s;
    position_[s] = target;
    elements_[from] = other;
    position_[other] = from;
  }

  // Weights were cleared while grouping; what is left is the bookkeeping of this splitter.
  void reset_scratch() {
    for (BlockIndex b : touched_blocks_)
      block_first_group_[b] = kNone;
    rational_sums_used_ = 0;
    touched_states_.clear();
    touched_group_.clear();
    touched_blocks_.clear();
  }

  static constexpr std::size_t kInitialTableSize = 16;  // a power of two

  const model::ExplicitModel& model_;
  const model::TransitionMatrix& matrix_;
  std::size_t context_;
  const RefinementOptions& options_;
  std::uint32_t num_states_;
  std::uint32_t num_actions_;
  WeightTable weights_;
  RefinementStatistics statistics_;

  std::optional<IncomingEdges>
      incoming_;  // offsets by build_reverse_edges(), records by split_by()

  // Per state, in separate arrays: each loop reads only the one it needs, and an array of
  // 4 bytes per state stays in the last-level cache longer than a record of several.
  std::vector<BlockIndex> block_;
  std::vector<std::uint32_t> position_;  // in elements_
  // During one splitter: kNone for a state not touched, else its slot in touched_states_ (and
  // touched_weights_). During a batch pass: the splitter slot of its block, or kNone.
  std::vector<std::uint32_t> mark_;
  std::vector<StateIndex> elements_;  // the blocks' states, each block a range

  // Per block, all grown together by add_block().
  std::vector<Block> blocks_;
  std::vector<std::uint32_t> block_first_group_;  // kNone outside grouping
  std::vector<std::uint32_t> batch_slot_;         // the block's index in a batch, or kNone

  std::vector<BlockIndex> queue_;
  std::uint64_t queued_edges_ = 0;  // edges into the queued blocks
  std::uint64_t steps_ = 0;

  // Scratch for one splitter, reset after it.
  // The weights of the touched states' choices, |A| words per touched state, in the order the
  // states were touched; 0 means "no edge reached the choice". By mode:
  //   Integer:  the integer sum; every probability is at least 1 / D, so a reached choice
  //             sums to at least 1.
  //   Rounded:  the bits of the double sum; a reached choice whose sum is 0 (a weight too
  //             small for a double) holds kReachedZero, the bits of -0.0, so it reads as 0.
  //   Rational: one more than the index of its exact sum in rational_sum_.
  // Sized by the largest splitter's touched states, not by the choices of the model.
  std::vector<std::uint64_t> touched_weights_;
  static constexpr std::uint64_t kReachedZero = std::uint64_t{1} << 63U;
  std::vector<Rational> rational_sum_;
  std::size_t rational_sums_used_ = 0;  // for the current splitter
  std::vector<StateIndex> touched_states_;
  std::vector<std::uint32_t> touched_group_;  // the group of each of touched_states_
  std::vector<BlockIndex> touched_blocks_;
  std::vector<Group> groups_;
  std::vector<std::uint32_t> group_table_;
  std::vector<SignatureEntry> signature_;
  std::vector<SignatureEntry> group_signatures_;
  std::vector<StateIndex> members_;  // the touched states, group by group
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
