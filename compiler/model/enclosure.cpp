#include "model/enclosure.hpp"

#include <algorithm>
#include <cstdint>
#include <deque>
#include <limits>
#include <utility>

#include "model/enclosure_rules.hpp"

namespace oasis::model {
namespace {

using enclosure_rules::binary;
using enclosure_rules::disallowed_name;
using enclosure_rules::exponent;
using enclosure_rules::is_allowed;
using enclosure_rules::is_binary;
using enclosure_rules::is_leaf;
using enclosure_rules::is_unary;
using enclosure_rules::kOne;
using enclosure_rules::operand;
using enclosure_rules::unary;
using enclosure_rules::unary_derivative;

// Where the variables of an expression range: the box holds the continuous variables, by slot,
// and `inputs` the inputs.
struct Ranges {
  std::span<const Interval> box;
  std::span<const Interval> inputs;
};

// A piece narrower than this fraction of the domain on every axis is not bisected further: a
// failure there is taken to be real (find_domain_error).
constexpr double kTinyFraction = 1e-9;

// Refused before anything is evaluated, so the message names the construct, not what an
// evaluation inside it happened to meet.
void check_allowed(const Expression& f) {
  if (!is_allowed(f.op)) {
    throw EnclosureError(f.range,
                         std::string(disallowed_name(f.op)) + " is not allowed in dynamics");
  }
}

// Runs an interval operation, placing its refusal at `f`.
template <typename Operation>
auto at(const Expression& f, Operation operation) -> decltype(operation()) {
  try {
    return operation();
  } catch (const IntervalError& error) {
    throw EnclosureError(f.range, error.what());
  }
}

// A variable's range by slot; a slot beyond the ranges given is the caller's bug.
Interval variable(const Expression& f, std::span<const Interval> values) {
  if (f.slot >= values.size()) {
    throw std::invalid_argument("a variable's slot " + std::to_string(f.slot) +
                                " is beyond the ranges given");
  }
  return values[f.slot];
}

// Variables read their ranges; constants become the tightest outward interval, recomputed
// at each call (no state is kept between calls, so concurrent callers need no lock).
Interval leaf(const Expression& f, const Ranges& ranges) {
  if (f.op == Op::ContinuousVariable) return variable(f, ranges.box);
  if (f.op == Op::InputVariable) return variable(f, ranges.inputs);
  return at(f, [&] { return from_rational(f.constant); });
}

// Bottom-up interval evaluation; a refusal carries the range of the node that refused.
Interval natural(const Expression& f, const Ranges& ranges) {
  check_allowed(f);  // before the operands: "floor is not allowed" beats what is inside it
  if (is_leaf(f.op)) return leaf(f, ranges);
  const Interval x = natural(operand(f, 0), ranges);
  if (f.op == Op::Power) {
    const std::int64_t n = exponent(f);
    return at(f, [&] { return power(x, n); });
  }
  if (is_unary(f.op)) return at(f, [&] { return unary(f.op, x); });
  const Interval y = natural(operand(f, 1), ranges);
  return at(f, [&] { return binary(f.op, x, y); });
}

// ---- Forward-mode differentiation over intervals ----

using Gradient = std::vector<Interval>;  // one entry per continuous variable

// A sub-expression's range over the box and the ranges of its partial derivatives.
struct Dual {
  Interval value;
  Gradient gradient;
};

// Componentwise operations on gradients, for the chain, product and quotient rules.
Gradient scaled(const Gradient& g, Interval factor) {
  Gradient result;
  result.reserve(g.size());
  for (const Interval& d : g)
    result.push_back(d * factor);
  return result;
}

Gradient added(const Gradient& a, const Gradient& b) {
  Gradient result;
  result.reserve(a.size());
  for (std::size_t j = 0; j < a.size(); ++j)
    result.push_back(a[j] + b[j]);
  return result;
}

// At a kink the derivative is either side's: the hull of both, componentwise.
Gradient hulled(const Gradient& a, const Gradient& b) {
  Gradient result;
  result.reserve(a.size());
  for (std::size_t j = 0; j < a.size(); ++j)
    result.push_back(hull(a[j], b[j]));
  return result;
}

// The gradient of a binary operation from its operands' values and gradients (`value` is the
// operation's own range). min and max follow one operand where their ranges do not overlap.
Gradient binary_gradient(Op op, const Dual& u, const Dual& v, Interval value) {
  switch (op) {
    case Op::Add:
      return added(u.gradient, v.gradient);
    case Op::Subtract:
      return added(u.gradient, scaled(v.gradient, {-1, -1}));
    case Op::Multiply:
      return added(scaled(u.gradient, v.value), scaled(v.gradient, u.value));
    case Op::Divide:  // (u' - (u / v) v') / v
      return scaled(added(u.gradient, scaled(v.gradient, -value)), kOne / v.value);
    case Op::Min:
      if (u.value.hi <= v.value.lo) return u.gradient;
      if (v.value.hi <= u.value.lo) return v.gradient;
      return hulled(u.gradient, v.gradient);
    default:  // max
      if (u.value.lo >= v.value.hi) return u.gradient;
      if (v.value.lo >= u.value.hi) return v.gradient;
      return hulled(u.gradient, v.gradient);
  }
}

Dual differentiate(const Expression& f, const Ranges& ranges);

// (u^n)' = n u^(n-1) u'.
Dual differentiate_power(const Expression& f, const Ranges& ranges) {
  const Dual u = differentiate(operand(f, 0), ranges);
  const std::int64_t n = exponent(f);
  const Interval value = at(f, [&] { return power(u.value, n); });
  if (n == 0) return {value, Gradient(ranges.box.size(), Interval{0, 0})};
  if (n == std::numeric_limits<std::int64_t>::min()) {
    throw EnclosureError(f.range, "the exponent is too large to differentiate");
  }
  const Interval factor =
      at(f, [&] { return from_rational(Rational(static_cast<long>(n))) * power(u.value, n - 1); });
  return {value, at(f, [&] { return scaled(u.gradient, factor); })};
}

// Forward mode: each node's range over the box and its gradient, from its operands'. The
// ranges are the natural extension's; the derivatives are enclosed over the whole box, which
// is what the mean-value theorem needs (the point where it holds is unknown).
Dual differentiate(const Expression& f, const Ranges& ranges) {
  check_allowed(f);
  if (is_leaf(f.op)) {
    Gradient gradient(ranges.box.size(), Interval{0, 0});
    if (f.op == Op::ContinuousVariable && f.slot < gradient.size()) gradient[f.slot] = kOne;
    return {leaf(f, ranges), std::move(gradient)};
  }
  if (f.op == Op::Power) return differentiate_power(f, ranges);
  const Dual u = differentiate(operand(f, 0), ranges);
  if (is_unary(f.op)) {
    const Interval value = at(f, [&] { return unary(f.op, u.value); });
    return {value,
            at(f, [&] { return scaled(u.gradient, unary_derivative(f.op, u.value, value)); })};
  }
  const Dual v = differentiate(operand(f, 1), ranges);
  const Interval value = at(f, [&] { return binary(f.op, u.value, v.value); });
  return {value, at(f, [&] { return binary_gradient(f.op, u, v, value); })};
}

// A box must be made of finite, non-empty intervals.
void check_box(std::span<const Interval> box) {
  for (const Interval& side : box) {
    if (!side.is_finite() || side.lo > side.hi) {
      throw std::invalid_argument("an enclosure's box needs finite, non-empty intervals, not " +
                                  to_string(side));
    }
  }
}

// The natural and the mean-value enclosures' common part; the natural one alone when the
// mean-value form cannot be computed.
Interval tightened(const Expression& f, Interval natural_range, std::span<const Interval> box,
                   std::span<const Interval> inputs) {
  Interval mean_value_range;
  try {
    mean_value_range = enclose_mean_value(f, box, inputs);
  } catch (const EnclosureError&) {
    return natural_range;
  }
  const std::optional<Interval> common = intersection(natural_range, mean_value_range);
  if (!common) {
    throw std::logic_error("the natural and the mean-value enclosures " + to_string(natural_range) +
                           " and " + to_string(mean_value_range) +
                           " are disjoint: one of them is unsound");
  }
  return *common;
}

// ---- The domain check ----

using Box = std::vector<Interval>;

// The error of the first component that cannot be enclosed naturally over `box` (the
// mean-value form's failures are no errors: enclose_map falls back).
std::optional<EnclosureError> first_error(std::span<const Expression> f, const Box& box,
                                          std::span<const Interval> inputs) {
  for (const Expression& component : f) {
    try {
      (void)enclose_natural(component, box, inputs);
    } catch (const EnclosureError& error) {
      return error;
    }
  }
  return std::nullopt;
}

// A piece below kTinyFraction of the domain on every axis: bisecting further would only
// spend the budget on what is almost surely a real error.
bool is_tiny(const Box& box, std::span<const Interval> domain) {
  for (std::size_t j = 0; j < box.size(); ++j) {
    if (box[j].width() > kTinyFraction * domain[j].width()) return false;
  }
  return true;
}

// The axis along which `box` is widest relative to the domain, and its halves; nullopt when no
// axis can be split (every axis is a point of the domain, or down to adjacent doubles).
std::optional<std::pair<Box, Box>> bisect(const Box& box, std::span<const Interval> domain) {
  std::optional<std::size_t> widest;
  double widest_ratio = 0;
  for (std::size_t j = 0; j < box.size(); ++j) {
    const double full = domain[j].width();
    const double ratio = full > 0 ? box[j].width() / full : 0;
    if (ratio > widest_ratio) {
      widest = j;
      widest_ratio = ratio;
    }
  }
  if (!widest) return std::nullopt;
  const Interval side = box[*widest];
  const double middle = side.midpoint();
  if (middle <= side.lo || middle >= side.hi) return std::nullopt;
  std::pair<Box, Box> halves{box, box};
  halves.first[*widest].hi = middle;
  halves.second[*widest].lo = middle;
  return halves;
}

// An input's value: "0.5", or "[0, 1]" when it ranges.
std::string point_or_interval(Interval x) {
  if (x.lo != x.hi) return to_string(x);
  const std::string text = to_string(x);  // "[v, v]"
  return text.substr(1, text.find(',') - 1);
}

// The error with the piece of the domain (and the inputs) where it occurred.
EnclosureError naming_the_box(const EnclosureError& error, const Box& box,
                              std::span<const Interval> inputs) {
  std::string where;
  for (const Interval& side : box)
    where += (where.empty() ? "" : " x ") + to_string(side);
  std::string message = std::string(error.what()) + " (where the state ranges over " + where;
  for (std::size_t i = 0; i < inputs.size(); ++i)
    message += (i == 0 ? ", with inputs " : ", ") + point_or_interval(inputs[i]);
  return {error.where, message + ")"};
}

// Breadth-first bisection of the failing pieces of `domain` for one combination of inputs.
std::optional<EnclosureError> error_for_inputs(std::span<const Expression> f,
                                               std::span<const Interval> domain,
                                               std::span<const Interval> inputs,
                                               std::size_t max_boxes) {
  std::deque<Box> pending{Box(domain.begin(), domain.end())};
  std::optional<EnclosureError> smallest;  // breadth-first: the last failure is the smallest
  for (std::size_t evaluated = 0;
       !pending.empty() && evaluated < std::max<std::size_t>(max_boxes, 1); ++evaluated) {
    const Box piece = std::move(pending.front());
    pending.pop_front();
    const std::optional<EnclosureError> error = first_error(f, piece, inputs);
    if (!error) continue;
    smallest = naming_the_box(*error, piece, inputs);
    std::optional<std::pair<Box, Box>> halves = bisect(piece, domain);
    if (!halves || is_tiny(piece, domain)) return smallest;
    pending.push_back(std::move(halves->first));
    pending.push_back(std::move(halves->second));
  }
  if (pending.empty()) return std::nullopt;
  return smallest;
}

// The next combination of input values, the last input varying fastest; false after the last.
bool advance(std::vector<std::size_t>& choice, std::span<const std::vector<Interval>> input_sets) {
  for (std::size_t i = choice.size(); i-- > 0;) {
    if (++choice[i] < input_sets[i].size()) return true;
    choice[i] = 0;
  }
  return false;
}

}  // namespace

Interval enclose_natural(const Expression& f, std::span<const Interval> box,
                         std::span<const Interval> inputs) {
  check_box(box);
  check_box(inputs);
  return natural(f, {box, inputs});
}

Interval enclose_mean_value(const Expression& f, std::span<const Interval> box,
                            std::span<const Interval> inputs) {
  check_box(box);
  check_box(inputs);
  Box centre;
  for (const Interval& side : box)
    centre.push_back(Interval::point(side.midpoint()));
  const Interval at_centre = natural(f, {centre, inputs});
  const Dual dual = differentiate(f, {box, inputs});
  return at(f, [&] {
    Interval range = at_centre;
    for (std::size_t j = 0; j < box.size(); ++j)
      range = range + dual.gradient[j] * (box[j] - centre[j]);
    return range;
  });
}

std::vector<Interval> enclose_map(std::span<const Expression> f, std::span<const Interval> box,
                                  std::span<const Interval> inputs) {
  std::vector<Interval> result;
  result.reserve(f.size());
  for (const Expression& component : f)
    result.push_back(tightened(component, enclose_natural(component, box, inputs), box, inputs));
  return result;
}

std::optional<EnclosureError> find_domain_error(std::span<const Expression> f,
                                                std::span<const Interval> box,
                                                std::span<const std::vector<Interval>> input_sets,
                                                std::size_t max_boxes) {
  check_box(box);
  for (const std::vector<Interval>& values : input_sets) {
    if (values.empty()) return std::nullopt;  // no combination of inputs at all
  }
  std::vector<std::size_t> choice(input_sets.size(), 0);
  Box inputs(input_sets.size());
  do {
    for (std::size_t i = 0; i < choice.size(); ++i)
      inputs[i] = input_sets[i][choice[i]];
    if (auto error = error_for_inputs(f, box, inputs, max_boxes)) return error;
  } while (advance(choice, input_sets));
  return std::nullopt;
}

}  // namespace oasis::model
