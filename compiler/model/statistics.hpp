#pragma once
// Size and reward figures of each context of an explicit model, as `oasisc info` reports.

#include <cstdint>
#include <optional>
#include <vector>

#include "model/explicit_model.hpp"

namespace oasis::model {

struct ContextStatistics {
  std::uint64_t states = 0;
  std::uint64_t actions = 0;
  std::uint64_t choices = 0;           // enabled (state, action) pairs
  std::uint64_t transitions = 0;       // (state, action, successor) with positive probability
  std::optional<Rational> reward_min;  // over R(s, a) of enabled pairs
  std::optional<Rational> reward_max;
};

std::vector<ContextStatistics> context_statistics(const ExplicitModel& model);

}  // namespace oasis::model
