#include "distributed/signature_refinement.hpp"

#include <algorithm>
#include <bit>
#include <deque>
#include <string>
#include <string_view>
#include <unordered_map>

#include <gmpxx.h>

#include "bisim/weights.hpp"
namespace oasis::distributed {
namespace {

using model::StateIndex;

// How masses are added: integers over a common denominator when it fits in 62 bits (a sum
// of probabilities is at most that denominator), else exact GMP rationals. The denominator is
// the least common multiple of every rank's own (bisim/weights.hpp), so it is the same on all.
class Masses {
 public:
  Masses(const OwnedModel& owned, const Communicator& communicator, bool rational_sums) {
    const std::vector<bool> used = bisim::used_values(owned.values.size(), owned.edge_probability);
    const std::optional<mpz_class> local = bisim::common_denominator(owned.values, used);
    // Collective whatever this rank found: "0" says its own denominator is already too large.
    const std::vector<std::string> all = communicator.all_gather(local ? local->get_str() : "0");
    if (rational_sums) return;
    mpz_class denominator = 1;
    for (const std::string& text : all) {
      const mpz_class other(text);
      if (other == 0 || !bisim::extend_common_denominator(denominator, other)) return;
    }
    integer_ = true;
    numerator_ = bisim::numerators_over(owned.values, used, denominator);
  }

  [[nodiscard]] bool integer() const { return integer_; }
  [[nodiscard]] std::uint64_t numerator(ValueId id) const { return numerator_[id]; }

 private:
  bool integer_ = false;
  std::vector<std::uint64_t> numerator_;
};

// The blocks of the states that this rank's edges lead to. Set up once: each rank asks each
// owner for the list of its states it needs (ascending), and every round each owner answers
// with their blocks in that order. Edge targets are renumbered to slots of the answers: the
// slot of a target is its rank among the needed states, ordered by owner then local index.
// Found with one bit per state of the model and a running count per 64 states (0.19 bytes
// per state), without sorting the targets.
class GhostBlocks {
 public:
  GhostBlocks(OwnedModel& owned, const Communicator& communicator)
      : communicator_(communicator), ownership_(owned.ownership) {
    const std::uint32_t ranks = communicator.size();
    std::vector<std::uint64_t> first(ranks + 1, 0);  // position of each owner's first state
    for (std::uint32_t q = 0; q < ranks; ++q)
      first[q + 1] = first[q] + ownership_.share(owned.num_states, q);
    const auto position = [&](StateIndex t) {
      return first[ownership_.owner(t)] + ownership_.local(t);
    };
    std::vector<std::uint64_t> needed((owned.num_states + 63) / 64, 0);
    for (StateIndex t : owned.edge_target)
      needed[position(t) / 64] |= std::uint64_t{1} << (position(t) % 64);
    std::vector<std::uint32_t> before(needed.size() + 1, 0);  // needed states before word w
    for (std::size_t w = 0; w < needed.size(); ++w)
      before[w + 1] = before[w] + static_cast<std::uint32_t>(std::popcount(needed[w]));
    for (StateIndex& t : owned.edge_target) {
      const std::uint64_t at = position(t);
      const std::uint64_t lower = needed[at / 64] & ((std::uint64_t{1} << (at % 64)) - 1);
      t = before[at / 64] + static_cast<std::uint32_t>(std::popcount(lower));
    }
    std::vector<Bytes> requests(ranks);
    offset_.assign(ranks + 1, 0);
    for (std::uint32_t q = 0; q < ranks; ++q) {
      ByteWriter writer(requests[q]);
      for (std::uint64_t at = first[q]; at < first[q + 1]; ++at) {
        if (needed[at / 64] >> (at % 64) & 1U)
          writer.put(static_cast<std::uint32_t>(at - first[q]));
      }
      offset_[q + 1] = offset_[q] + static_cast<std::uint32_t>(requests[q].size() / 4);
    }
    needed = {};
    before = {};
    const std::vector<Bytes> asked = communicator.exchange(requests);
    served_.resize(ranks);
    for (std::uint32_t q = 0; q < ranks; ++q) {
      served_[q].resize(asked[q].size() / sizeof(std::uint32_t));
      std::copy_n(asked[q].data(), asked[q].size(), reinterpret_cast<char*>(served_[q].data()));
    }
    block_.resize(offset_[ranks]);
  }

  // Collective: refreshes the blocks of every slot from the owners' `block_of_owned`.
  void update(const std::vector<std::uint32_t>& block_of_owned) {
    std::vector<Bytes> answers(communicator_.size());
    for (std::uint32_t q = 0; q < communicator_.size(); ++q) {
      ByteWriter writer(answers[q]);
      for (std::uint32_t local : served_[q])
        writer.put(block_of_owned[local]);
    }
    const std::vector<Bytes> received = communicator_.exchange(answers);
    for (std::uint32_t q = 0; q < communicator_.size(); ++q) {
      std::copy_n(received[q].data(), received[q].size(),
                  reinterpret_cast<char*>(block_.data() + offset_[q]));
    }
  }

  [[nodiscard]] std::uint32_t block(std::uint32_t slot) const { return block_[slot]; }

 private:
  const Communicator& communicator_;
  Ownership ownership_;
  std::vector<std::uint32_t> offset_;               // [owner]: first slot of its states
  std::vector<std::vector<std::uint32_t>> served_;  // [asker]: the local states it wants
  std::vector<std::uint32_t> block_;                // per slot
};

// Writes the signatures of the owned states.
class SignatureWriter {
 public:
  SignatureWriter(const OwnedModel& owned, const Masses& masses) : owned_(owned), masses_(masses) {}

  void initial(std::uint32_t local, Bytes& out) const {
    out.clear();
    ByteWriter writer(out);
    for (std::uint32_t c = owned_.state_choice_begin[local];
         c < owned_.state_choice_begin[local + 1]; ++c) {
      writer.put(owned_.choice_action[c]);
      writer.put(owned_.choice_reward[c]);  // value ids are the same on every rank
    }
  }

  void refined(std::uint32_t local, std::uint32_t own_block, const GhostBlocks& ghosts,
               Bytes& out) {
    out.clear();
    ByteWriter writer(out);
    writer.put(own_block);
    for (std::uint32_t c = owned_.state_choice_begin[local];
         c < owned_.state_choice_begin[local + 1]; ++c) {
      writer.put(owned_.choice_action[c]);
      masses_of(c, ghosts);
      writer.put(static_cast<std::uint32_t>(blocks_.size()));
      for (std::size_t i = 0; i < blocks_.size(); ++i) {
        writer.put(blocks_[i].first);
        if (masses_.integer())
          writer.put(blocks_[i].second);
        else
          writer.put_text(rational_[i].get_str());
      }
    }
  }

 private:
  // P(B | s, a) for the blocks B that choice c reaches, in block order, into blocks_ (and,
  // with rational sums, rational_).
  void masses_of(std::uint32_t c, const GhostBlocks& ghosts) {
    pairs_.clear();
    const std::uint32_t begin = owned_.edge_begin[c];
    for (std::uint32_t e = begin; e < begin + owned_.edge_count[c]; ++e)
      pairs_.emplace_back(ghosts.block(owned_.edge_target[e]), owned_.edge_probability[e]);
    std::sort(pairs_.begin(), pairs_.end());
    blocks_.clear();
    rational_.clear();
    for (const auto& [block, probability] : pairs_) {
      const bool same = !blocks_.empty() && blocks_.back().first == block;
      if (masses_.integer()) {
        if (same)
          blocks_.back().second += masses_.numerator(probability);
        else
          blocks_.emplace_back(block, masses_.numerator(probability));
      } else if (same) {
        rational_.back() += owned_.values[probability];
      } else {
        blocks_.emplace_back(block, 0);
        rational_.push_back(owned_.values[probability]);
      }
    }
  }

  const OwnedModel& owned_;
  const Masses& masses_;
  std::vector<std::pair<std::uint32_t, ValueId>> pairs_;
  std::vector<std::pair<std::uint32_t, std::uint64_t>> blocks_;
  std::vector<Rational> rational_;
};

// Gives every owned state the global number of its signature. Distinct signatures go to the
// rank their hash names; that rank numbers them in the order they arrive (by sender, then as
// sent), and the all-gathered counts make the numbers global.
class SignatureNumbering {
 public:
  SignatureNumbering(const Communicator& communicator, std::uint32_t num_owned)
      : communicator_(communicator), signature_of_(num_owned) {}

  void add(std::uint32_t local, const Bytes& signature) {
    const std::string_view key(signature.data(), signature.size());
    auto found = distinct_.find(key);
    if (found == distinct_.end()) {
      texts_.emplace_back(key);
      found = distinct_.emplace(texts_.back(), static_cast<std::uint32_t>(texts_.size() - 1)).first;
    }
    signature_of_[local] = found->second;
  }

  // Collective. Returns the number of distinct signatures over all ranks and sets the
  // global number of every owned state's signature in `block_of_owned`.
  std::uint64_t number(std::vector<std::uint32_t>& block_of_owned) {
    const std::uint32_t ranks = communicator_.size();
    std::vector<Bytes> outgoing(ranks);
    std::vector<std::uint32_t> owner(texts_.size());
    std::vector<std::uint32_t> position(texts_.size());
    std::vector<std::uint32_t> sent(ranks, 0);
    for (std::size_t i = 0; i < texts_.size(); ++i) {
      owner[i] = static_cast<std::uint32_t>(std::hash<std::string_view>{}(texts_[i]) % ranks);
      position[i] = sent[owner[i]]++;
      ByteWriter(outgoing[owner[i]]).put_text(texts_[i]);
    }
    distinct_.clear();
    texts_.clear();
    const std::vector<std::uint32_t> number =
        number_received(communicator_.exchange(outgoing), owner, position);
    block_of_owned.resize(signature_of_.size());
    for (std::size_t local = 0; local < signature_of_.size(); ++local)
      block_of_owned[local] = number[signature_of_[local]];
    return total_;
  }

 private:
  // Numbers the signatures sent here, answers each sender, and returns the global number of
  // each of this rank's own distinct signatures.
  std::vector<std::uint32_t> number_received(const std::vector<Bytes>& received,
                                             const std::vector<std::uint32_t>& owner,
                                             const std::vector<std::uint32_t>& position) {
    const std::uint32_t ranks = communicator_.size();
    std::unordered_map<std::string_view, std::uint32_t> numbers;
    std::vector<Bytes> answers(ranks);
    for (std::uint32_t q = 0; q < ranks; ++q) {
      ByteReader reader(received[q]);
      ByteWriter writer(answers[q]);
      while (!reader.at_end()) {
        const auto [it, inserted] =
            numbers.try_emplace(reader.get_text(), static_cast<std::uint32_t>(numbers.size()));
        writer.put(it->second);
      }
    }
    const std::vector<std::uint64_t> counts = communicator_.all_gather(numbers.size());
    std::vector<std::uint64_t> first(ranks + 1, 0);
    for (std::uint32_t q = 0; q < ranks; ++q)
      first[q + 1] = first[q] + counts[q];
    total_ = first[ranks];
    numbers.clear();
    const std::vector<Bytes> replies = communicator_.exchange(answers);
    std::vector<std::uint32_t> global(owner.size());
    for (std::size_t i = 0; i < owner.size(); ++i) {
      std::uint32_t local_number = 0;
      std::copy_n(replies[owner[i]].data() + std::size_t{position[i]} * sizeof(std::uint32_t),
                  sizeof(std::uint32_t), reinterpret_cast<char*>(&local_number));
      global[i] = static_cast<std::uint32_t>(first[owner[i]] + local_number);
    }
    return global;
  }

  const Communicator& communicator_;
  std::unordered_map<std::string_view, std::uint32_t> distinct_;  // views into texts_
  std::deque<std::string> texts_;
  std::vector<std::uint32_t> signature_of_;  // per local state: index into texts_
  std::uint64_t total_ = 0;
};

}  // namespace

DistributedPartition refine_distributed(OwnedModel& owned, const Communicator& communicator,
                                        const DistributedOptions& options) {
  DistributedPartition result;
  const Masses masses(owned, communicator, options.rational_sums);
  result.exact_integer_sums = masses.integer();
  GhostBlocks ghosts(owned, communicator);
  SignatureWriter signatures(owned, masses);
  const std::uint32_t num_owned = owned.num_owned();
  Bytes signature;
  std::uint64_t previous = 0;
  for (std::uint32_t round = 0;; ++round) {
    if (options.on_round) options.on_round(round, previous);
    SignatureNumbering numbering(communicator, num_owned);
    if (round > 0) ghosts.update(result.block_of_owned);
    for (std::uint32_t local = 0; local < num_owned; ++local) {
      if (round == 0)
        signatures.initial(local, signature);
      else
        signatures.refined(local, result.block_of_owned[local], ghosts, signature);
      numbering.add(local, signature);
    }
    const std::uint64_t blocks = numbering.number(result.block_of_owned);
    result.rounds = round + 1;
    if (round > 0 && blocks == previous) break;
    previous = blocks;
  }
  result.num_blocks = previous;
  // The targets' final blocks, for writing the quotient.
  ghosts.update(result.block_of_owned);
  for (StateIndex& target : owned.edge_target)
    target = ghosts.block(target);
  return result;
}

}  // namespace oasis::distributed
