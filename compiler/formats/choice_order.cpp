// Where each choice of a state is written (choice_order.hpp).

#include "formats/choice_order.hpp"

#include "formats/explicit_reader.hpp"

namespace oasis::formats {

using model::ActionIndex;
using model::StateIndex;

std::optional<std::uint32_t> unlabelled_slot(const std::string& name) {
  if (name.size() < 3 || name.front() != '[' || name.back() != ']') return std::nullopt;
  std::uint32_t value = 0;
  for (std::size_t i = 1; i + 1 < name.size(); ++i) {
    if (name[i] < '0' || name[i] > '9' || value > 100'000'000) return std::nullopt;
    value = value * 10 + static_cast<std::uint32_t>(name[i] - '0');
  }
  return unlabelled_action_name(value) == name ? std::optional(value) : std::nullopt;
}

ChoiceOrder::ChoiceOrder(const model::ExplicitModel& model, const model::TransitionMatrix& matrix)
    : matrix_(matrix) {
  for (const std::string& name : model.actions)
    slots_.push_back(unlabelled_slot(name));
}

void ChoiceOrder::operator()(StateIndex s, std::vector<ActionIndex>& order,
                             std::vector<bool>& unlabelled) const {
  std::vector<ActionIndex> enabled;
  for (ActionIndex a = 0; a < matrix_.num_actions; ++a) {
    if (matrix_.enabled(s, a)) enabled.push_back(a);
  }
  constexpr ActionIndex kFree = UINT32_MAX;
  order.assign(enabled.size(), kFree);
  unlabelled.assign(enabled.size(), false);
  std::vector<ActionIndex> rest;
  for (ActionIndex a : enabled) {
    const std::optional<std::uint32_t> slot = slots_[a];
    if (slot && *slot < order.size() && order[*slot] == kFree) {
      order[*slot] = a;
      unlabelled[*slot] = true;
    } else {
      rest.push_back(a);
    }
  }
  std::size_t next = 0;
  for (ActionIndex& entry : order) {
    if (entry == kFree) entry = rest[next++];
  }
}

}  // namespace oasis::formats
