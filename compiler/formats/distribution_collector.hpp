#pragma once
// Collects the distributions of an MDP file, one per (source state, action), in file order,
// and turns them into the CSR TransitionMatrix. Unlike TransitionBuilder it keeps each
// distribution as a unit, so it can tell when a file gives one state two distributions for
// the same action (not an MDP) and point at both places. The action set may still grow
// while distributions are added: choice indices are only formed in finish().
//
// Files written in (state, action) order, which is what our writers and most tools produce,
// are finished without a second copy of their edges: a distribution whose targets are not
// sorted is sorted where it lies.

#include <cstdint>
#include <optional>
#include <utility>
#include <vector>

#include "model/explicit_model.hpp"
#include "support/huge_page_growth.hpp"
#include "support/source_manager.hpp"

namespace oasis::formats {

class DistributionCollector {
 public:
  struct Duplicate {
    std::uint32_t first;   // the distribution given first in the file
    std::uint32_t second;  // a later one for the same (source, action)
  };

  // What is kept of each distribution besides its source and action: its offset in its file
  // (8 bytes, for diagnostics) and the reader's payload (4 bytes). A reader that can find a
  // place again by reading its file once more keeps payloads only; an explorer, whose
  // distributions come from no file, keeps neither.
  enum class Kept { OffsetsAndPayloads, Payloads, Nothing };

  DistributionCollector() = default;
  explicit DistributionCollector(Kept kept) : kept_(kept) {}

  void reserve(std::size_t distributions, std::size_t edges);
  // Room for `edges` edges in all, for a reader that learns their number while reading.
  void reserve_edges(std::size_t edges) {
    targets_.reserve(edges);
    probabilities_.reserve(edges);
  }

  // Starts distribution number size(). `offset` locates it in its file for diagnostics;
  // `payload` is the reader's (a reward id, a choice index). Each is dropped when not kept.
  void begin(model::StateIndex source, model::ActionIndex action, SourceOffset offset,
             std::uint32_t payload);
  // The same, for a collector that keeps neither.
  void begin(model::StateIndex source, model::ActionIndex action);
  void add(model::StateIndex target, ValueId probability) {
    // Within one distribution targets should strictly increase; otherwise finish() sorts.
    if (targets_.size() > edge_begin_.back() && targets_.back() >= target) sorted_ = false;
    push_back_huge(targets_, target);
    push_back_huge(probabilities_, probability);
  }
  [[nodiscard]] std::size_t size() const { return sources_.size(); }
  [[nodiscard]] std::size_t num_edges() const { return targets_.size(); }
  // Edge indices are 32-bit; readers stop before this is reached.
  [[nodiscard]] bool full() const { return targets_.size() >= UINT32_MAX - 1; }
  [[nodiscard]] model::StateIndex source(std::uint32_t d) const { return sources_[d]; }
  [[nodiscard]] model::ActionIndex action(std::uint32_t d) const { return actions_[d]; }
  // Only where they are kept (both by default).
  [[nodiscard]] SourceOffset offset(std::uint32_t d) const { return offsets_.at(d); }
  [[nodiscard]] std::uint32_t payload(std::uint32_t d) const { return payloads_.at(d); }

  // Builds the matrix; `num_states * num_actions` must be below 2^32. Repeated
  // (source, action) pairs are listed in `duplicates` in file order and yield nullopt.
  // Probabilities of a target repeated within one distribution are added. The collected
  // edges are consumed; the per-distribution accessors stay valid until release().
  std::optional<model::TransitionMatrix> finish(std::uint32_t num_states, std::uint32_t num_actions,
                                                RationalPool& values,
                                                std::vector<Duplicate>& duplicates);
  // Frees what is left once the caller has read the per-distribution accessors.
  void release();

 private:
  static constexpr std::uint32_t kNone = UINT32_MAX;

  void build_copying(model::TransitionMatrix& matrix, RationalPool& values);
  void normalize_in_place(RationalPool& values);
  // Whether the targets of edges [first, last) strictly increase.
  [[nodiscard]] bool strictly_increasing(std::size_t first, std::size_t last) const;
  void copy_distribution(std::uint32_t d,
                         std::vector<std::pair<model::StateIndex, ValueId>>& row) const;
  void build_in_place(model::TransitionMatrix& matrix);

  Kept kept_ = Kept::OffsetsAndPayloads;
  std::vector<model::StateIndex> sources_;
  std::vector<model::ActionIndex> actions_;
  std::vector<SourceOffset> offsets_;
  std::vector<std::uint32_t> payloads_;
  std::vector<model::EdgeIndex> edge_begin_;  // where each distribution's edges start
  std::vector<model::StateIndex> targets_;
  std::vector<ValueId> probabilities_;
  bool sorted_ = true;  // targets strictly increase within every distribution
};

}  // namespace oasis::formats
