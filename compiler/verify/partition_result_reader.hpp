#pragma once
// Reading the partitions in a RESULT file (`oasisc quotient --format json --partition`) back
// into Partitions of a model's states, for `oasisc verify`. Every way the file can fail to
// describe a partition of the model is an error here, so that the verifier only ever sees
// well-formed partitions and its violations are about bisimulation.

#include <cstddef>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "model/explicit_model.hpp"
#include "model/partition.hpp"

namespace oasis::verify {

struct ContextPartition {
  std::size_t context = 0;  // index in model.contexts
  // Blocks numbered from 0 in the order the file lists them (not renumbered), so that
  // messages about "block 2" point at the file's third block.
  model::Partition partition;
};

struct PartitionResult {
  std::vector<ContextPartition> contexts;  // in the order of the file
  bool approximate = false;                // the file says "exact": false (--epsilon)
  std::string respected_labels = "all";    // "respected_labels" (quotient --respect-labels)
  bool unlabelled_choices = false;         // "choices": "unlabelled" (quotient --choices)
};

// Reads `path`. States are names as model.states.name() prints them, or integer indices.
// On failure (also a file larger than `max_bytes`) returns nullopt and sets `error` to one
// sentence (without the path).
std::optional<PartitionResult> read_partition_result(const std::string& path,
                                                     const model::ExplicitModel& model,
                                                     std::size_t max_bytes, std::string& error);
// The same on the file's text.
std::optional<PartitionResult> parse_partition_result(std::string_view text,
                                                      const model::ExplicitModel& model,
                                                      std::string& error);

}  // namespace oasis::verify
