#include "model/valuation_text.hpp"

#include "support/text.hpp"

namespace oasis::model {

std::string valuation_text(const std::vector<DiscreteVariable>& variables, Valuation valuation) {
  std::string text = "(";
  for (std::size_t v = 0; v < variables.size(); ++v) {
    if (v > 0) text += ',';
    text += variables[v].name + '=' + std::to_string(valuation[v]);
  }
  return text + ')';
}

std::string range_violation(const DiscreteVariable& variable, std::int64_t value) {
  if (value >= variable.low && value <= variable.high) return {};
  return "update sets " + quoted(variable.name) + " to " + std::to_string(value) +
         ", outside its range [" + std::to_string(variable.low) + " .. " +
         std::to_string(variable.high) + "]";
}

}  // namespace oasis::model
