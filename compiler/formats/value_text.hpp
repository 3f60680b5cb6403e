#pragma once
// The text of pool values for writers, formatted once per distinct value: a model with 10^7
// edges usually has a handful of probabilities, and GMP's printing is not cheap.

#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "support/rational.hpp"

namespace oasis::formats {

enum class ValueStyle {
  Fraction,  // "1/2", "1/3", "-2": what .aut requires
  Decimal,   // "0.5" when the value has a finite decimal expansion, else "1/3"
};

// A finite decimal expansion of `value` ("0.125", "-2.5", "3"), if it has one.
std::optional<std::string> exact_decimal(const Rational& value);

class ValueText {
 public:
  ValueText(const RationalPool& values, ValueStyle style) : values_(values), style_(style) {}

  std::string_view operator()(ValueId id) {
    if (id >= texts_.size()) texts_.resize(values_.size());
    std::string& text = texts_[id];
    if (text.empty()) text = format(values_[id]);
    return text;
  }
  [[nodiscard]] std::string format(const Rational& value) const;

 private:
  const RationalPool& values_;
  ValueStyle style_;
  std::vector<std::string> texts_;
};

}  // namespace oasis::formats
