#include "property/value_reduction.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace oasis::property {
namespace {

using modelcheck::Mode;
using modelcheck::Value;

double down(double x) {
  return std::nextafter(x, -std::numeric_limits<double>::infinity());
}
double up(double x) {
  return std::nextafter(x, std::numeric_limits<double>::infinity());
}

Value infinite_value() {
  Value v;
  v.infinite = true;
  v.lower = v.upper = std::numeric_limits<double>::infinity();
  return v;
}

// a < b for exact values, or a.upper < b.upper then a.lower < b.lower for intervals: the
// order min and max pick by (an interval's ends are each the min/max of the ends).
bool less_exact(const Value& a, const Value& b) {
  if (a.infinite || b.infinite) return !a.infinite && b.infinite;
  return a.exact < b.exact;
}

Value extreme(const std::vector<Value>& values, const modelcheck::StateSet& states, Mode mode,
              bool minimum) {
  Value result;
  bool first = true;
  for (std::size_t s = 0; s < values.size(); ++s) {
    if (!states[s]) continue;
    const Value& v = values[s];
    if (first) {
      result = v;
      first = false;
      continue;
    }
    if (mode == Mode::kExact) {
      if (less_exact(v, result) == minimum && (less_exact(v, result) || less_exact(result, v)))
        result = v;
    } else {
      result.lower = minimum ? std::min(result.lower, v.lower) : std::max(result.lower, v.lower);
      result.upper = minimum ? std::min(result.upper, v.upper) : std::max(result.upper, v.upper);
      result.infinite = minimum ? result.infinite && v.infinite : result.infinite || v.infinite;
    }
  }
  return result;
}

Value total(const std::vector<Value>& values, const modelcheck::StateSet& states, bool average) {
  Value result;
  std::uint64_t count = 0;
  for (std::size_t s = 0; s < values.size(); ++s) {
    if (!states[s]) continue;
    ++count;
    if (values[s].infinite) return infinite_value();
    result.exact += values[s].exact;
    result.lower = down(result.lower + values[s].lower);
    result.upper = up(result.upper + values[s].upper);
  }
  if (average && count > 0) {
    result.exact /= static_cast<unsigned long>(count);
    result.lower = down(result.lower / static_cast<double>(count));
    result.upper = up(result.upper / static_cast<double>(count));
  }
  return result;
}

}  // namespace

std::string filter_name(Filter::Op op) {
  switch (op) {
    case Filter::Op::kFirst:
      return "first";
    case Filter::Op::kMin:
      return "min";
    case Filter::Op::kMax:
      return "max";
    case Filter::Op::kAvg:
      return "avg";
    case Filter::Op::kSum:
      return "sum";
    case Filter::Op::kCount:
      return "count";
    case Filter::Op::kForall:
      return "forall";
    case Filter::Op::kExists:
      return "exists";
  }
  return "?";
}

bool reduce_values(Filter::Op op, const std::vector<Value>& values,
                   const modelcheck::StateSet& states, Mode mode, Value& result) {
  switch (op) {
    case Filter::Op::kFirst:
      result = values[static_cast<std::size_t>(std::find(states.begin(), states.end(), true) -
                                               states.begin())];
      return true;
    case Filter::Op::kMin:
    case Filter::Op::kMax:
      result = extreme(values, states, mode, op == Filter::Op::kMin);
      return true;
    case Filter::Op::kSum:
    case Filter::Op::kAvg:
      result = total(values, states, op == Filter::Op::kAvg);
      if (mode == Mode::kExact && !result.infinite)
        result.lower = result.upper = result.exact.get_d();
      return true;
    case Filter::Op::kCount:
    case Filter::Op::kForall:
    case Filter::Op::kExists:
      return false;
  }
  return false;
}

bool compare_with_bound(const std::vector<Value>& values, Quantifier::Comparison comparison,
                        const Rational& bound, Mode mode, modelcheck::StateSet& holds) {
  const bool greater = comparison == Quantifier::Comparison::kGreater ||
                       comparison == Quantifier::Comparison::kGreaterEqual;
  const bool strict =
      comparison == Quantifier::Comparison::kGreater || comparison == Quantifier::Comparison::kLess;
  // Whether x ~ bound, exactly (a double is a rational: its comparison is exact too).
  const auto satisfies = [&](const Rational& x) {
    const int order = cmp(x, bound);
    return greater ? (strict ? order > 0 : order >= 0) : (strict ? order < 0 : order <= 0);
  };
  for (std::size_t s = 0; s < values.size(); ++s) {
    const Value& v = values[s];
    if (v.infinite) {
      holds[s] = greater;
      continue;
    }
    if (mode == Mode::kExact) {
      holds[s] = satisfies(v.exact);
      continue;
    }
    // The true value lies in [lower, upper]: the bound is decided when both ends agree.
    const bool at_lower = satisfies(Rational(v.lower));
    const bool at_upper = satisfies(Rational(v.upper));
    if (at_lower != at_upper) return false;
    holds[s] = at_lower;
  }
  return true;
}

}  // namespace oasis::property
