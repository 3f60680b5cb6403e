#pragma once
// The rules both evaluators of enclosures follow (model/enclosure.cpp walks the expression tree,
// model/enclosure_program.cpp runs a compiled form of it): which operations dynamics may use,
// each operation over intervals, and each unary operation's derivative. Kept in one place so
// the two evaluators cannot drift apart: the compiled form must give bit-identical results.

#include <cstdint>
#include <string_view>

#include "model/expression.hpp"
#include "model/interval.hpp"

namespace oasis::model::enclosure_rules {

inline constexpr Interval kOne{1, 1};

// The operations the dynamics may use: leaves, unary and binary operations, and Op::Power.
bool is_leaf(Op op);
bool is_unary(Op op);
bool is_binary(Op op);
bool is_allowed(Op op);
// What a message calls an operation the dynamics may not use ("floor", "a state test").
std::string_view disallowed_name(Op op);

// Operand i of f; std::invalid_argument when it is missing (a bug of the tree's builder).
const Expression& operand(const Expression& f, std::size_t i);
// The exponent of x^n: an integer constant, or EnclosureError at the exponent.
std::int64_t exponent(const Expression& power_node);

// The interval operation of a unary or a binary op.
Interval unary(Op op, Interval x);
Interval binary(Op op, Interval x, Interval y);
// The chain rule's factor of a unary operation: its derivative over x, whose result is `value`.
Interval unary_derivative(Op op, Interval x, Interval value);

}  // namespace oasis::model::enclosure_rules
