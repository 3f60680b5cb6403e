#pragma once
// The few property forms whose schedulers `oasisc verify` checks, read by a reader of their
// own (not the property language's parser: verify shares no code with it):
//
//   Pmax=? [F T]      Pmin=? [F T]      Pmax=? [phi U T]      Pmin=? [phi U T]
//
// where T and phi are state formulas made of quoted labels ("goal"), true, false, !, &, | and
// parentheses (! binds tightest, then &, then |). Anything else is refused with a message
// that says what verify reads; `oasisc query` answers the rest.

#include <cstddef>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "model/explicit_model.hpp"

namespace oasis::verify {

struct ReachabilityProperty {
  bool maximise = true;      // Pmax; false for Pmin
  std::vector<bool> until;   // phi, per state (all true for F T)
  std::vector<bool> target;  // T, per state
};

// The longest property text read: the formula is evaluated in every state.
inline constexpr std::size_t kMaxPropertyBytes = 10000;

// Reads `text` against `model`'s labels. On failure returns nullopt and sets `error` to one
// sentence (what is wrong and where, then what verify reads).
std::optional<ReachabilityProperty> read_reachability_property(std::string_view text,
                                                               const model::ExplicitModel& model,
                                                               std::string& error);

}  // namespace oasis::verify
