#pragma once
// Enclosures of the image of a box under the dynamics x' = f(x, u), f given as expressions
// (docs/guarantees.md). An enclosure is an interval per component that contains f(x, u) for
// every x in the box and every u in the input intervals: what the abstraction needs for the
// successors of a cell to be sound. Expressions may use constants, continuous variables
// (Op::ContinuousVariable, slot into the box), inputs (Op::InputVariable, slot into the
// inputs), + - * /, unary -, ^ with an integer constant exponent, min max abs, sin cos tan
// atan exp log sqrt; anything else is refused at the expression.

#include <cstddef>
#include <optional>
#include <span>
#include <stdexcept>
#include <string>
#include <vector>

#include "model/expression.hpp"
#include "model/interval.hpp"
#include "support/diagnostics.hpp"

namespace oasis::model {

// A refusal located at the offending sub-expression: a divisor whose range reaches 0, log of a
// range reaching 0, sqrt of a range below 0, tan across a pole, a non-finite value, an
// operation not allowed in dynamics.
struct EnclosureError : std::runtime_error {
  EnclosureError(SourceRange location, const std::string& message)
      : std::runtime_error(message), where(location) {}
  SourceRange where;
};

// The natural interval extension: every operation of `f` evaluated over intervals. Sound and
// cheap; loose when a variable occurs more than once (x - x over [0, 1] is [-1, 1]).
Interval enclose_natural(const Expression& f, std::span<const Interval> box,
                         std::span<const Interval> inputs);

// The mean-value form f(c) + sum_j df/dx_j(box) * (box_j - c_j), c the box's midpoint, the
// derivatives enclosed by forward-mode differentiation over intervals (abs, min and max take
// the hull of their one-sided derivatives at a kink inside the box). Its excess over the true
// range shrinks with the square of the box's width, the natural extension's only linearly,
// so it wins on small cells. Throws EnclosureError where a derivative cannot be enclosed
// (sqrt' at 0) as well as where f cannot.
Interval enclose_mean_value(const Expression& f, std::span<const Interval> box,
                            std::span<const Interval> inputs);

// Per component, the intersection of the natural and the mean-value enclosures (each is sound,
// so their common part is, and it is at least as tight as either). Where the mean-value form
// fails the natural extension stands alone; the natural extension's errors propagate.
std::vector<Interval> enclose_map(std::span<const Expression> f, std::span<const Interval> box,
                                  std::span<const Interval> inputs);

// The check made when a spec is read: can every component of f be enclosed over the whole
// domain `box`, for every combination of the inputs' values (input_sets[i] lists input i's;
// every combination is tried, the last input varying fastest)? Interval arithmetic
// over-approximates, so a failure over the domain may be spurious (1 / (x*x + 1/2) over
// [-1, 1]): a failing box is bisected along its widest axis (relative to the domain's width),
// breadth-first, until every piece evaluates (nullopt), or some piece still fails when
// max_boxes boxes have been evaluated for this combination of inputs, or a failing piece is
// tiny (no wider than 1e-9 of the domain on every axis). The error returned is that of the
// smallest failing box, its message naming the box and the inputs.
std::optional<EnclosureError> find_domain_error(std::span<const Expression> f,
                                                std::span<const Interval> box,
                                                std::span<const std::vector<Interval>> input_sets,
                                                std::size_t max_boxes);

}  // namespace oasis::model
