#pragma once
// Writer for Storm's explicit DRN format (.drn); the counterpart of read_drn. docs/formats.md,
// "Storm's DRN", gives the layout: the header (@type from the model's ModelType, @value_type
// rational, the reward models), then each state with its rewards and labels, its choices
// and their transitions, values exact (decimals where finite, fractions otherwise).

#include <cstddef>
#include <span>
#include <string>

#include "model/explicit_model.hpp"
#include "support/atomic_file.hpp"

namespace oasis::formats {

// Writes `contexts` of `model`, which must share one transition matrix, to `out` (already
// open; the caller commits): one reward model per context, named after it, except that a lone
// context "default" without rewards writes none. The states of model.states.initial carry the
// label "init" (first), the model's other labels follow sorted by name, so the output does
// not depend on the order of the label table. Choices are written in ChoiceOrder; an
// unlabelled one ("[j]" at place j) as Storm's `__NOLABEL__`; a DTMC's one choice as
// `action 0`. Returns false and sets `error` for what DRN cannot carry (names with blanks,
// a DTMC state with two choices, contexts with different transitions).
bool write_drn(const model::ExplicitModel& model, std::span<const std::size_t> contexts,
               AtomicFile& out, std::string& error);

// The same into the file at `path`, which appears only if everything was written.
bool write_drn_file(const model::ExplicitModel& model, std::span<const std::size_t> contexts,
                    const std::string& path, std::string& error);

// Whether contexts `a` and `b` of `model` have the same transitions (one DRN file can hold
// both as reward models).
bool same_transitions(const model::ExplicitModel& model, std::size_t a, std::size_t b);

}  // namespace oasis::formats
