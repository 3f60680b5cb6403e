#pragma once
// A catalog in memory: for every context of a model, its abstraction and the policy solved
// on it, in the runtime's schema (runtime/include/oasis/rt/catalog_view.hpp).
// The data is owned here and read through rt::CatalogView, the same view the generated
// tables and the binary file give, so the emitters serialise exactly what a program built
// on this runs.

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "model/explicit_model.hpp"
#include "oasis/rt/catalog_view.hpp"

namespace oasis::model {

struct CsrData {
  std::vector<std::uint32_t> choice_begin;
  std::vector<std::uint32_t> target;
  std::vector<double> probability;

  [[nodiscard]] rt::TransitionsCsr view() const;
};

struct AbstractionData {
  std::string context;
  std::uint32_t num_blocks = 0;
  std::vector<std::uint32_t> block_of;  // [num_states]
  std::vector<double> block_reward;     // [num_blocks] R(s) of the block's states
  CsrData quotient;                     // over blocks
  std::vector<double> reward;           // [num_blocks * num_actions] R^Z(z, a)
  std::vector<std::uint32_t> policy;    // [num_blocks] action, or rt::kNoAction
  std::vector<double> value;            // [num_blocks]
  CsrData state_transitions;            // over states; only with the robust section
  // Continuous catalogs only (rt::AbstractionView's grid fields): the grid over the relevant
  // variables, the block of every cell, the outside block and the error bound.
  std::vector<std::uint32_t> grid_axes;         // [d] indices into the state vector
  std::vector<std::uint32_t> grid_break_begin;  // [d + 1]
  std::vector<double> grid_breaks;
  std::vector<std::uint32_t> cell_block;  // [cells]
  std::uint32_t outside_block = 0;
  double epsilon = 0.0;
  // Polytope cells (rt::BspView): the grid is then the domain box, one cell.
  std::uint32_t bsp_cells = 0;
  std::vector<double> bsp_normal;  // [nodes * d]
  std::vector<double> bsp_bound;   // [nodes]
  std::vector<std::uint32_t> bsp_below;
  std::vector<std::uint32_t> bsp_above;
  std::vector<std::uint32_t> bsp_cell;  // rt::kInternalNode for internal nodes
  // The catalog's stated properties (CatalogData::properties), each as rt::kGuaranteeFields
  // doubles: the policy's value and the optimum, each an interval around the exact value.
  std::vector<double> guarantee;
  // [properties * 2]: the policy's and the optimum's exact values as fractions ("1/6"), for
  // the JSON; empty strings where only the interval is known (a sound answer).
  std::vector<std::string> guarantee_exact;
};

// A property a catalog states values for (a spec's `property` item): its name and its text.
struct StatedProperty {
  std::string name;
  std::string text;
};

// Continuous catalogs: the position noise (rt::PositionNoise); all empty without one.
struct PositionNoiseData {
  std::vector<std::string> object_names;  // [objects], for the JSON and messages
  std::vector<std::uint32_t> object_of;   // [state_dimension]: an object or rt::kExactVariable
  std::vector<double> sigma;              // [objects * 3] a, b, c of sigma(d)
  std::vector<double> detection;          // [objects]

  [[nodiscard]] bool empty() const { return detection.empty(); }
};

struct CatalogData {
  std::string name;
  std::uint64_t spec_hash = 0;
  std::string compiler_version;
  std::uint32_t num_states = 0;
  std::uint32_t num_actions = 0;
  std::vector<std::string> action_names;
  std::vector<std::string> state_names;
  std::vector<double> switching;  // [N * N] row-major p(phi_t = j | phi_{t-1} = i)
  std::vector<double> prior;      // [N]
  std::vector<AbstractionData> abstractions;
  rt::ObservationKind observation = rt::ObservationKind::kNone;
  double p_correct = 1.0;
  std::vector<double> confusion;  // kMatrix only: [num_states * num_states], row = true state
  rt::RewardSource reward_source = rt::RewardSource::kTrueState;
  // Continuous catalogs: the state vector's variables (empty for a discrete catalog, which
  // has num_states explicit states instead).
  std::vector<std::string> variable_names;
  PositionNoiseData position;              // continuous catalogs
  std::vector<StatedProperty> properties;  // each abstraction's guarantee, in this order

  // A view into this object: valid until it is changed, moved or destroyed. Not const: the
  // view's name tables are kept here.
  rt::CatalogView view();

 private:
  std::vector<const char*> action_name_pointers_;
  std::vector<const char*> state_name_pointers_;
  std::vector<const char*> variable_name_pointers_;
  std::vector<const char*> property_name_pointers_;
  std::vector<const char*> property_text_pointers_;
  std::vector<rt::AbstractionView> abstraction_views_;
};

// The nearest double of every value of `model`'s pool, by ValueId: edges share few distinct
// values, so converting each once is much cheaper than once per edge.
std::vector<double> value_doubles(const model::ExplicitModel& model);

// A transition matrix of `model` as CSR arrays of doubles (nearest to each exact value).
CsrData csr_of(const model::ExplicitModel& model, const model::TransitionMatrix& matrix);

}  // namespace oasis::model
