#pragma once
// What a filter makes of per-state values (PRISM's filter(op, property, states)), and how a
// bound is compared with values that are exact or sound intervals. An interval is compared
// only where it decides: [lower, upper] >= b holds when lower >= b, fails when upper < b, and
// is undecided otherwise, which the caller resolves by asking for a tighter interval.

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "modelcheck/engine.hpp"
#include "property/property.hpp"

namespace oasis::property {

std::string filter_name(Filter::Op op);

// first, min, max, sum, avg over the values of the states in `states` (not empty) into
// `result`; false for an op that reads truth values (count, forall, exists).
bool reduce_values(Filter::Op op, const std::vector<modelcheck::Value>& values,
                   const modelcheck::StateSet& states, modelcheck::Mode mode,
                   modelcheck::Value& result);

// Per state, whether value ~ bound; false when some interval is undecided.
bool compare_with_bound(const std::vector<modelcheck::Value>& values,
                        Quantifier::Comparison comparison, const Rational& bound,
                        modelcheck::Mode mode, modelcheck::StateSet& holds);

}  // namespace oasis::property
