#include "model/catalog_data.hpp"

namespace oasis::model {

std::vector<double> value_doubles(const model::ExplicitModel& model) {
  std::vector<double> doubles(model.values.size());
  for (std::size_t id = 0; id < doubles.size(); ++id)
    doubles[id] = to_double(model.values[static_cast<ValueId>(id)]);
  return doubles;
}

CsrData csr_of(const model::ExplicitModel& model, const model::TransitionMatrix& matrix) {
  const std::vector<double> doubles = value_doubles(model);
  CsrData csr;
  csr.choice_begin.assign(matrix.choice_begin.begin(), matrix.choice_begin.end());
  csr.target.assign(matrix.edge_target.begin(), matrix.edge_target.end());
  csr.probability.reserve(matrix.num_edges());
  for (ValueId id : matrix.edge_probability)
    csr.probability.push_back(doubles[id]);
  return csr;
}

rt::TransitionsCsr CsrData::view() const {
  return {choice_begin.empty() ? nullptr : choice_begin.data(),
          target.empty() ? nullptr : target.data(),
          probability.empty() ? nullptr : probability.data(),
          static_cast<std::uint32_t>(target.size())};
}

rt::CatalogView CatalogData::view() {
  action_name_pointers_.clear();
  for (const std::string& action : action_names)
    action_name_pointers_.push_back(action.c_str());
  state_name_pointers_.clear();
  for (const std::string& state : state_names)
    state_name_pointers_.push_back(state.c_str());
  abstraction_views_.clear();
  for (const AbstractionData& data : abstractions) {
    rt::AbstractionView view;
    view.context = data.context.c_str();
    view.num_blocks = data.num_blocks;
    view.block_of = data.block_of.data();
    view.block_reward = data.block_reward.data();
    view.quotient = data.quotient.view();
    view.reward = data.reward.data();
    view.policy = data.policy.data();
    view.value = data.value.data();
    view.state_transitions = data.state_transitions.view();
    if (!data.grid_axes.empty()) {
      view.block_of = nullptr;
      view.grid = {static_cast<std::uint32_t>(data.grid_axes.size()), data.grid_axes.data(),
                   data.grid_break_begin.data(), data.grid_breaks.data()};
      view.cell_block = data.cell_block.data();
      view.outside_block = data.outside_block;
      view.epsilon = data.epsilon;
      if (!data.bsp_cell.empty()) {
        view.bsp = {static_cast<std::uint32_t>(data.bsp_cell.size()),
                    data.bsp_cells,
                    data.bsp_normal.data(),
                    data.bsp_bound.data(),
                    data.bsp_below.data(),
                    data.bsp_above.data(),
                    data.bsp_cell.data()};
      }
    }
    view.guarantee = data.guarantee.empty() ? nullptr : data.guarantee.data();
    abstraction_views_.push_back(view);
  }
  rt::CatalogView view;
  view.name = name.c_str();
  view.spec_hash = spec_hash;
  view.compiler_version = compiler_version.c_str();
  view.num_states = num_states;
  view.num_actions = num_actions;
  view.action_names = action_name_pointers_.data();
  view.state_names = state_names.empty() ? nullptr : state_name_pointers_.data();
  view.num_abstractions = static_cast<std::uint32_t>(abstractions.size());
  view.switching = switching.data();
  view.prior = prior.data();
  view.abstractions = abstraction_views_.data();
  view.observation.kind = observation;
  view.observation.p_correct = p_correct;
  view.observation.confusion = confusion.empty() ? nullptr : confusion.data();
  view.observation.reward_source = reward_source;
  if (!position.empty()) {
    view.observation.position = {static_cast<std::uint32_t>(position.detection.size()),
                                 position.object_of.data(), position.sigma.data(),
                                 position.detection.data()};
  }
  variable_name_pointers_.clear();
  for (const std::string& variable : variable_names)
    variable_name_pointers_.push_back(variable.c_str());
  view.state_dimension = static_cast<std::uint32_t>(variable_names.size());
  view.variable_names = variable_names.empty() ? nullptr : variable_name_pointers_.data();
  property_name_pointers_.clear();
  property_text_pointers_.clear();
  for (const StatedProperty& property : properties) {
    property_name_pointers_.push_back(property.name.c_str());
    property_text_pointers_.push_back(property.text.c_str());
  }
  if (!properties.empty()) {
    view.properties = {static_cast<std::uint32_t>(properties.size()),
                       property_name_pointers_.data(), property_text_pointers_.data()};
  }
  return view;
}

}  // namespace oasis::model
