#pragma once
// The coarsest bisimulation of one context of an explicit MDP (Definition 1 of the paper,
// after Givan, Dean and Greig 2003): states s and t are equivalent iff for every action a
//   - a is enabled in both or in neither,
//   - R(s, a) = R(t, a), and
//   - P(B | s, a) = P(B | t, a) for every block B of the partition.
// Computed by partition refinement that processes the smaller half (see refinement.cpp).

#include <cstdint>
#include <functional>
#include <optional>

#include "model/explicit_model.hpp"
#include "model/partition.hpp"

namespace oasis::bisim {

// The partition is a model-level value (model/partition.hpp): bisimulation makes it, the
// quotient, the policy layer and the verifier read it.
using model::BlockIndex;
using model::Partition;

struct RefinementProgress {
  std::uint64_t splitters_processed = 0;
  std::uint64_t splitters_queued = 0;
  std::uint32_t blocks = 0;
};

struct RefinementOptions {
  // Approximate mode for models whose probabilities were floating point (the user's
  // --epsilon): sums are compared after rounding to multiples of this step; see
  // docs/bisimulation.md for exactly what it guarantees. Unset: exact.
  std::optional<double> rounding_step;
  // Add probabilities with GMP even when integers over a common denominator would be exact.
  // Slower; it exists so that tests can check both exact paths against each other.
  bool rational_sums = false;
  // Called now and then during refinement.
  std::function<void(const RefinementProgress&)> progress;
  // Empty, or one class per state (model::label_classes): states whose respected labels
  // differ are never merged.
  std::vector<std::uint32_t> label_class;
  // Storm's MDP semantics: a state's choices are a set of distributions, their action names
  // ignored (unlabelled_refinement.hpp). Exact only. False: Definition 1, action by action.
  bool unlabelled_choices = false;
};

struct RefinementStatistics {
  std::uint64_t splitters = 0;       // blocks used as splitters
  std::uint64_t edge_visits = 0;     // incoming edges scanned over all splitters
  std::uint64_t batch_passes = 0;    // forward passes that took the whole queue at once
  std::uint32_t initial_blocks = 0;  // blocks of the reward/enabled-action signature
  bool exact_integer_sums = false;   // sums were exact integers over a common denominator
  // Wall-clock seconds of the phases: reverse edges (their offsets: the records are built
  // when a splitter is first walked alone, and counted in splitting), initial partition,
  // splitting.
  double setup_seconds = 0;
  double initial_seconds = 0;
  double splitting_seconds = 0;
};

Partition coarsest_bisimulation(const model::ExplicitModel& model, std::size_t context,
                                const RefinementOptions& options = {},
                                RefinementStatistics* statistics = nullptr);

}  // namespace oasis::bisim
