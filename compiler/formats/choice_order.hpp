#pragma once
// The order in which writers list a state's choices. PRISM's explicit files and DRN both name
// a choice by its place in its state, and our readers call an unlabelled choice j the action
// "[j]"; so an action "[j]" is put at place j (and written unlabelled) where it can be, and
// the other actions fill the remaining places in action order. A model read from either
// format is then written back with its unlabelled choices unlabelled.

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "model/explicit_model.hpp"

namespace oasis::formats {

// The j of an action named "[j]" (what the readers call unlabelled choice j), if it is one.
std::optional<std::uint32_t> unlabelled_slot(const std::string& name);

class ChoiceOrder {
 public:
  ChoiceOrder(const model::ExplicitModel& model, const model::TransitionMatrix& matrix);

  // Fills `order` for state `s`; `unlabelled[j]` tells whether choice j is written unlabelled.
  void operator()(model::StateIndex s, std::vector<model::ActionIndex>& order,
                  std::vector<bool>& unlabelled) const;

 private:
  const model::TransitionMatrix& matrix_;
  std::vector<std::optional<std::uint32_t>> slots_;
};

}  // namespace oasis::formats
