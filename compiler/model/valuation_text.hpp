#pragma once
// Words about valuations that both explorers (model/explorer.cpp for .oasis specs,
// prism/explorer.cpp for PRISM programs) print, so that their messages read the same.

#include <cstdint>
#include <string>
#include <vector>

#include "model/expression.hpp"
#include "model/model_ir.hpp"

namespace oasis::model {

// "(x=1,y=0)": a factored state by its variables.
std::string valuation_text(const std::vector<DiscreteVariable>& variables, Valuation valuation);

// "update sets 'x' to 4, outside its range [0 .. 3]", or "" when `value` is in range.
std::string range_violation(const DiscreteVariable& variable, std::int64_t value);

}  // namespace oasis::model
