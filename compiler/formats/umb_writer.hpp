#pragma once
// Writer for UMB (.umb); the counterpart of read_umb. docs/formats.md, "UMB", gives the
// layout: a gzip-compressed tar of index.json and the arrays, every probability and reward a
// rational of the smallest size that holds all of its array exactly, so nothing is rounded.
// The same model gives the same bytes (no dates, entries in a fixed order).

#include <cstddef>
#include <span>
#include <string>

#include "model/explicit_model.hpp"
#include "support/atomic_file.hpp"

namespace oasis::formats {

// Writes `contexts` of `model`, which must share one transition matrix, to `out` (already
// open; the caller commits): one reward annotation per context, aliased by its name, except
// that a lone context "default" without rewards writes none. The initial states go to
// state-is-initial.bin, the other labels to atomic propositions (sorted by name), the
// variables to state valuations (umb_valuations.hpp). Choices are
// written in ChoiceOrder; an unlabelled one ("[j]" at place j) with the empty action string,
// which is action 0 when there is one. Returns false and sets `error` for what UMB or its
// reader cannot carry (a DTMC state with two choices, names that are not UTF-8 text,
// contexts with different transitions).
bool write_umb(const model::ExplicitModel& model, std::span<const std::size_t> contexts,
               AtomicFile& out, std::string& error);

// The same into `bytes` (replaced).
bool write_umb_bytes(const model::ExplicitModel& model, std::span<const std::size_t> contexts,
                     std::string& bytes, std::string& error);

// The same into the file at `path`, which appears only if everything was written.
bool write_umb_file(const model::ExplicitModel& model, std::span<const std::size_t> contexts,
                    const std::string& path, std::string& error);

}  // namespace oasis::formats
