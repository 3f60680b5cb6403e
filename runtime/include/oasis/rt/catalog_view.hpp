// oasis/rt/catalog_view.hpp: the one in-memory schema of an abstraction catalog.
//
// A catalog is what the compiler produces for Online Attention Switching (OAS): one explicit
// MDP state space, N abstractions (one per context, each the coarsest bisimulation quotient of
// the MDP under that context's reward), the abstraction switching model p(phi_t | phi_{t-1}),
// the prior p(phi_0), and optionally the models the robust joint filter needs.
//
// Every type here is a *view*: plain structs of pointers and counts that own nothing. The
// arrays behind them may be generated `constexpr`/`const` tables compiled into the robot
// binary, or buffers filled by a file loader; either way they must outlive the view and every
// filter built on it. Nothing in this header allocates.
//
// Trust: a generated table is trusted (the compiler checked it). Anything read from a file or
// a network is not: call validate() (catalog_validation.hpp) before handing the view to
// AttentionFilter. validate()
// reads only the elements that the counts in the view say exist, in an order that checks each
// count before using it, so a view whose arrays really have the stated lengths cannot make it
// read out of bounds, however wrong the numbers in those arrays are.
//
// Conventions used throughout:
//  * indices are std::uint32_t; states are 0..num_states-1, actions 0..num_actions-1,
//    abstractions 0..num_abstractions-1, blocks of abstraction i 0..num_blocks-1;
//  * "row-major N x M" means element (r, c) is at [r * M + c];
//  * a probability row "sums to 1" within kProbabilityTolerance (absolute);
//  * strings are NUL-terminated UTF-8 and must be non-null unless marked optional.
#pragma once

#include <cmath>
#include <cstddef>
#include <cstdint>
#include <string>

#include "oasis/rt/bsp_locator.hpp"
#include "oasis/rt/grid_locator.hpp"

namespace oasis::rt {

/// Version of the layout below. Emitters write it, loaders and validate() reject any other.
/// 2: continuous catalogs (grid fields at the end of AbstractionView and CatalogView).
inline constexpr std::uint32_t kCatalogFormat = 2;

/// Absolute tolerance for "a probability distribution sums to 1" in validate(). Generated
/// tables round exact rationals to the nearest double, so their sums are off by a few ulp per
/// term; 1e-9 leaves room for rows of up to about 10^6 terms.
inline constexpr double kProbabilityTolerance = 1e-9;

/// Marker in AbstractionView::policy for a block in which no action is enabled.
inline constexpr std::uint32_t kNoAction = 0xFFFFFFFFu;

/// A transition relation in compressed sparse rows, one row per (row, action) pair.
///
/// Row `r * num_actions + a` holds the successors of source `r` (a block of a quotient, or a
/// state of the full model) under action `a`: edges choice_begin[k] .. choice_begin[k+1]-1,
/// edge e going to `target[e]` with probability `probability[e]`.
///
/// Invariants checked by validate() (R = number of sources, A = num_actions):
///  * choice_begin has R*A+1 entries, choice_begin[0] == 0, non-decreasing,
///    choice_begin[R*A] == num_edges;
///  * target and probability have num_edges entries; every target < number of destinations;
///  * every probability is finite and in (0, 1]; every non-empty row sums to 1.
/// An empty row means the action is not enabled in that source. Targets within a row need not
/// be sorted or distinct (a loader may keep them as emitted), though emitters write them
/// sorted and merged.
struct TransitionsCsr {
  const std::uint32_t* choice_begin = nullptr;  ///< [R*A + 1] first edge of each row
  const std::uint32_t* target = nullptr;        ///< [num_edges] destination of each edge
  const double* probability = nullptr;          ///< [num_edges] probability of each edge
  std::uint32_t num_edges = 0;                  ///< length of target and probability
};

/// One abstraction phi^i: the quotient of the MDP under context i, its policy and values.
struct AbstractionView {
  /// Name of the context this abstraction was computed for (the spec's `context NAME`).
  const char* context = nullptr;

  /// Number of blocks (abstract states z) of the quotient; at least 1.
  std::uint32_t num_blocks = 0;

  /// [num_states] z^i(s): the block of every explicit state. Every value < num_blocks and
  /// every block holds at least one state.
  const std::uint32_t* block_of = nullptr;

  /// [num_blocks] the state reward R(s) of the states in each block (bisimulation makes it
  /// equal within a block). This is what the detection model p(r_t | phi^i, s_t) compares the
  /// observed reward with: r_t "matches" abstraction i at state s when
  /// |r_t - block_reward[block_of[s]]| <= the filter's reward tolerance. Finite.
  const double* block_reward = nullptr;

  /// The quotient's transitions P^Z(z' | z, a): num_blocks sources, targets are blocks.
  /// Optional (an analysis product; the filter does not read it): all pointers null and
  /// num_edges 0 when the catalog does not carry it.
  TransitionsCsr quotient;

  /// [num_blocks * num_actions] R^Z(z, a), the quotient's reward for taking a in z, row-major.
  /// Meaningful only where action a is enabled in z; finite everywhere (emitters write 0 for
  /// disabled actions).
  const double* reward = nullptr;

  /// [num_blocks] pi^i(z): the optimal action in each block. Either an action whose quotient
  /// row in this block is non-empty, or kNoAction when no action is enabled in the block.
  const std::uint32_t* policy = nullptr;

  /// [num_blocks] V^i(z): the optimal discounted value of each block. Finite.
  const double* value = nullptr;

  /// Optional, for the robust joint filter only: the full-state transition model
  /// P^i(s' | s, a) with num_states sources and states as targets. Present exactly when the
  /// catalog's observation model is present (CatalogView::observation.kind != kNone);
  /// otherwise all its pointers must be null and num_edges 0.
  TransitionsCsr state_transitions;

  // ---- Continuous catalogs only (CatalogView::state_dimension > 0); null/0 otherwise. ----

  /// The grid over the variables this abstraction attends to (grid_locator.hpp): its axes
  /// index the continuous state vector.
  GridView grid;

  /// [cells of the grid] the block of every cell.
  const std::uint32_t* cell_block = nullptr;

  /// The block of every state outside the grid's domain (absorbing, reward 0).
  std::uint32_t outside_block = 0;

  /// The sound bound on the error of this abstraction's transition rows (0: an exact
  /// bisimulation), as the compiler computed it; informational for the filter.
  double epsilon = 0.0;

  /// Polytope cells (bsp_locator.hpp): a BSP over the relevant variables inside the grid's
  /// domain box, which then has a single cell; the BSP's leaves are the cells of cell_block.
  /// Empty (num_nodes 0) for gridded abstractions.
  BspView bsp;

  /// Optional: [catalog.properties.count * kGuaranteeFields] what this abstraction's policy
  /// and the optimum give each of the catalog's properties (PropertyStatements), property
  /// by property: kPolicyLower, kPolicyUpper, kOptimumLower, kOptimumUpper. Null when the
  /// catalog states no properties.
  const double* guarantee = nullptr;
};

/// The fields of one property's guarantee (AbstractionView::guarantee): each value as an
/// interval that contains the exact one (lower == upper only when the double is exact).
enum GuaranteeField : std::uint32_t {
  kPolicyLower = 0,  ///< the property's value when the abstraction's policy acts
  kPolicyUpper = 1,
  kOptimumLower = 2,  ///< its value at the optimum its operator names (Pmax, Rmin, ...)
  kOptimumUpper = 3,
};
inline constexpr std::uint32_t kGuaranteeFields = 4;

/// The properties a catalog states values for (a spec's `property` items,
/// docs/spec-language.md): PRISM properties answered by the compiler in every context, under
/// the context's policy and at the optimum (AbstractionView::guarantee).
struct PropertyStatements {
  std::uint32_t count = 0;
  const char* const* names = nullptr;  ///< [count]
  const char* const* texts = nullptr;  ///< [count] each property as written
};

/// The cells of a continuous abstraction (the length of cell_block): its BSP's leaves, or
/// its grid's cells.
inline std::uint64_t partition_cells(const AbstractionView& abs) noexcept {
  return abs.bsp.num_nodes != 0 ? abs.bsp.num_cells : grid_cells(abs.grid);
}

/// How an observed state relates to the true state, for the robust joint filter.
enum class ObservationKind : std::uint32_t {
  /// No robust section in this catalog: only the paper's filter can run.
  kNone = 0,
  /// p(o | s) = p_correct if o == s, else (1 - p_correct) / (num_states - 1): the sensor
  /// reports the true state with probability p_correct and otherwise one of the other states
  /// uniformly (the paper's sigma is 1 - p_correct). With one state, p_correct must be 1.
  kSymmetric = 1,
  /// p(o | s) = confusion[s * num_states + o]: a full confusion matrix, one row per true
  /// state s, each row a distribution over observed states o.
  kMatrix = 2,
};

/// Which state the reward the robot receives belongs to, when the observed state may be wrong.
enum class RewardSource : std::uint32_t {
  /// The reward follows the true state: R^i(s) with s the true state (the robust filter's
  /// model; Table I's "observed" reading).
  kTrueState = 0,
  /// The reward follows the observed state: R^i(o), as when the reward is itself perceived
  /// from the same wrong reading (Table I's "perceived" reading). Algorithm 1 is exact here.
  kObservedState = 1,
};

/// Marks, in PositionNoise::object_of, a continuous variable that no object measures: it is
/// observed exactly.
inline constexpr std::uint32_t kExactVariable = 0xFFFFFFFFu;

/// Continuous catalogs: how the sensor measures the state vector. The variables are grouped
/// into objects (a person's x and y), each detected or missed as a whole. A detected object's
/// variables are read with independent Gaussian errors of standard deviation
/// sigma(d) = a + b d + c d^2 (negative values read as 0), where d is the object's distance:
/// the Euclidean norm of its variables (the distance from the robot when, as in the Go1 spec,
/// positions are relative to the robot). A missed object's variables are NaN.
struct PositionNoise {
  /// Number of objects; 0 means no model (every variable observed exactly, always).
  std::uint32_t num_objects = 0;
  /// [state_dimension] the object measuring each variable, or kExactVariable.
  const std::uint32_t* object_of = nullptr;
  /// [num_objects * 3] a, b, c of each object's sigma(d), metres (or the variables' unit).
  /// Finite, a >= 0.
  const double* sigma = nullptr;
  /// [num_objects] the probability that the object is detected in a frame, in (0, 1].
  const double* detection = nullptr;
};

/// sigma(d) of object k (k < noise.num_objects).
inline double object_sigma(const PositionNoise& noise, std::uint32_t k, double distance) noexcept {
  const double* c = noise.sigma + static_cast<std::size_t>(k) * 3;
  const double sigma = c[0] + distance * (c[1] + distance * c[2]);
  return sigma > 0.0 ? sigma : 0.0;
}

/// The state-observation model p(observed state | true state), catalog-wide (the sensor does
/// not depend on the context).
struct ObservationModel {
  ObservationKind kind = ObservationKind::kNone;
  /// kSymmetric only: in [0, 1]. Ignored otherwise.
  double p_correct = 1.0;
  /// kMatrix only: [num_states * num_states], row-major, each row sums to 1. Must be null
  /// otherwise.
  const double* confusion = nullptr;
  /// Which state generates the reward (declared in the spec's `observation` block; catalogs
  /// that predate it load as kTrueState, what the robust filter has always assumed).
  RewardSource reward_source = RewardSource::kTrueState;
  /// Continuous catalogs only: the Gaussian measurement model of the state vector (none when
  /// num_objects is 0). Independent of `kind`, which describes discrete states.
  PositionNoise position;
};

/// The whole catalog. A generated table or a loader fills one of these; nothing is owned.
struct CatalogView {
  /// Must equal kCatalogFormat.
  std::uint32_t format = kCatalogFormat;

  /// Name of the spec's MDP (the `mdp NAME` block).
  const char* name = nullptr;

  /// Hash of the spec the catalog was compiled from, as the compiler computes it; lets a
  /// robot check that its catalog and its configuration come from the same spec.
  std::uint64_t spec_hash = 0;

  /// Version string of the compiler that produced the catalog (informational).
  const char* compiler_version = nullptr;

  /// Number of explicit states of the MDP; at least 1.
  std::uint32_t num_states = 0;

  /// Number of actions; at least 1.
  std::uint32_t num_actions = 0;

  /// [num_actions] action names, each non-null.
  const char* const* action_names = nullptr;

  /// Optional: [num_states] state names (each non-null), or null when the catalog does not
  /// carry them (large state spaces).
  const char* const* state_names = nullptr;

  /// Number of abstractions N in the catalog; at least 1.
  std::uint32_t num_abstractions = 0;

  /// [N * N] the abstraction transition model, row-major: switching[i * N + j] is
  /// p(phi_t = j | phi_{t-1} = i). Every entry finite in [0, 1], every row sums to 1.
  const double* switching = nullptr;

  /// [N] the prior p(phi_0 = i). Finite, in [0, 1], sums to 1.
  const double* prior = nullptr;

  /// [N] the abstractions, in the catalog's order (the spec's context order).
  const AbstractionView* abstractions = nullptr;

  /// Optional robust section: the state-observation model (kNone when absent). When present,
  /// every abstraction carries state_transitions.
  ObservationModel observation;

  /// True if the robust joint filter can run on this catalog.
  bool has_robust_section() const noexcept { return observation.kind != ObservationKind::kNone; }

  // ---- Continuous catalogs (fields added after format 1: null defaults, so tables generated
  // for discrete catalogs fill them by position without naming them). ----

  /// Number of continuous state variables; 0 for a discrete catalog. A continuous catalog has
  /// num_states == 0, no state names, no block_of and no robust section: its abstractions
  /// map a state vector of this many doubles to blocks through their grids.
  std::uint32_t state_dimension = 0;

  /// Optional: [state_dimension] names of the continuous variables.
  const char* const* variable_names = nullptr;

  /// True for a catalog over continuous states.
  bool is_continuous() const noexcept { return state_dimension > 0; }

  /// Optional: the properties whose values every abstraction states (count 0: none).
  PropertyStatements properties;

  /// True if a filter that models the noise can run on this catalog (FilterMode::kJoint on a
  /// discrete catalog with a robust section, FilterMode::kNoiseAware on a continuous one with a
  /// position-noise model).
  bool has_noise_model() const noexcept {
    return is_continuous() ? observation.position.num_objects > 0 : has_robust_section();
  }
};

}  // namespace oasis::rt
