#pragma once
// Reads an mCRL2 .aut file on all ranks at once: each rank reads its part of the bytes
// (formats::read_aut_part) and sends every line to the owner of its source state, in
// batches, so that no rank ever holds much more than its share of the model. Checks are the
// sequential reader's: each line where it is read, the number of lines and repeated
// (state, action) pairs across the whole file at the owners.

#include <cstdint>
#include <functional>
#include <optional>
#include <string>

#include "distributed/communicator.hpp"
#include "distributed/owned_model.hpp"
#include "formats/read_options.hpp"

namespace oasis::distributed {

// Called on each rank now and then while it reads its part, with the bytes of the part read
// so far and the part's size.
using ReadProgress = std::function<void(std::uint64_t read, std::uint64_t part)>;

// Collective. Diagnostics go to standard error: rank 0 reports problems of the header and of
// the whole file, every rank those of its own part. nullopt on every rank when any rank found
// an error.
std::optional<OwnedModel> read_aut_distributed(const std::string& path,
                                               const formats::ReadOptions& options,
                                               const Communicator& communicator,
                                               const ReadProgress& progress = {});

}  // namespace oasis::distributed
