#pragma once
// How an action and its reward R(s, a) travel in one .aut transition label.
//
// mCRL2 treats an .aut label as a multi-action string: it splits it at top-level '|' and
// sorts the parts, and its probabilistic bisimulation (ltspbisim) compares labels as those
// sorted strings. We therefore write a non-zero reward as one more part of the multi-action,
// `reward(<exact rational>)`, placed where mCRL2's sorting puts it:
//
//   a                 action a, reward 0
//   a|reward(1/2)     action a, reward 1/2
//   reward(-3)|wait   action wait, reward -3 (the parts sort byte-wise, as mCRL2 does)
//
// Because each state has at most one distribution per action, two states match each other's
// labels exactly when they enable the same actions with equal rewards, so ltspbisim
// separates states precisely as our bisimulation (equal R(s, a), equal class
// probabilities) does. docs/formats.md has the details.

#include <optional>
#include <string>
#include <string_view>

#include "support/rational.hpp"

namespace oasis::formats {

struct AutLabel {
  std::string action;
  Rational reward;
};

// The label for `action` with `reward`, in the canonical form above.
std::string format_aut_label(std::string_view action, const Rational& reward);

// Why `action` cannot be written as (part of) an .aut label, or nullopt if it can:
// empty, holding '"' or a line break, unbalanced parentheses, or a `reward(...)` part of its
// own (which would read back as a reward).
std::optional<std::string> aut_action_problem(std::string_view action);

// Splits a label read from a file into action and reward. Labels without a `reward(...)`
// part are their own action name with reward 0. On failure returns nullopt and sets `error`.
std::optional<AutLabel> parse_aut_label(std::string_view label, std::string& error);

}  // namespace oasis::formats
