#pragma once
// The partitions a compiled binary catalog carries, for `oasisc verify MODEL CATALOG.bin`.

#include <cstdint>
#include <optional>
#include <string>

#include "cli/partition_result_reader.hpp"

namespace oasis::cli {

// Loads the catalog (refusing damaged files: magic, version, sizes, checksum), checks that
// it was compiled from a model with this hash and shape, and returns each abstraction's
// partition. nullopt with `error` (one sentence, without the path) otherwise.
std::optional<PartitionResult> read_catalog_partitions(const std::string& path,
                                                       const model::ExplicitModel& model,
                                                       std::uint64_t model_hash,
                                                       std::string& error);

}  // namespace oasis::cli
