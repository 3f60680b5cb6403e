#pragma once
// Writer for PRISM's explicit model files of an MDP; the counterpart of read_prism.

#include <cstddef>
#include <string>

#include "model/explicit_model.hpp"

namespace oasis::formats {

// Writes context `context` of `model` as `<base>.tra`, `<base>.lab` (initial and deadlock
// states, and the model's own labels), `<base>.srew`, `<base>.sta` when the model has variables and
// `<base>.trew` when some enabled choice has a non-zero choice reward; a stale .sta or .trew from
// an earlier write is removed so that reading `<base>.tra` gives back this model. `base` may end in
// ".tra". Values are exact: decimals where finite ("0.25"), fractions otherwise ("1/3").
// Each file appears whole or not at all; nothing is committed unless all were written.
// Returns false and sets `error` on failure (including action names with blanks).
bool write_prism(const model::ExplicitModel& model, std::size_t context, const std::string& base,
                 std::string& error);

}  // namespace oasis::formats
