#pragma once
// Writer for mCRL2's probabilistic Aldebaran (.aut) format; the counterpart of read_aut.

#include <cstddef>
#include <string>

#include "model/explicit_model.hpp"
#include "support/atomic_file.hpp"

namespace oasis::formats {

// Writes context `context` of `model` to `out` (already open; the caller commits). Every
// enabled (state, action) becomes one line, in state then action order, targets ascending,
// exact fractions; R(s, a) travels in the label (aut_label.hpp). One initial state is
// written as it is, several as a uniform distribution over them (read back as the same
// set), none as state 0. Returns false and sets `error` if an action name cannot be
// written as a label.
bool write_aut(const model::ExplicitModel& model, std::size_t context, AtomicFile& out,
               std::string& error);

// The same into the file at `path`, which appears only if everything was written.
bool write_aut_file(const model::ExplicitModel& model, std::size_t context, const std::string& path,
                    std::string& error);

}  // namespace oasis::formats
