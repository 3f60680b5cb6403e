#pragma once
// The distributed partition, brought to rank 0 and written as `oasisc quotient --format json
// --partition` writes it, so that `oasisc verify MODEL PARTITION.json` checks it unchanged.

#include <optional>
#include <string>
#include <vector>

#include "distributed/communicator.hpp"
#include "distributed/owned_model.hpp"
#include "distributed/signature_refinement.hpp"
#include "model/partition.hpp"

namespace oasis::distributed {

struct GatheredPartition {
  // Blocks numbered in order of their smallest state (model::canonical_partition).
  model::Partition partition;
  // canonical[b]: the number in `partition` of block b of DistributedPartition.
  std::vector<model::BlockIndex> canonical;
};

// Collective. Rank 0 gets the partition of the whole model; the other ranks get nullopt.
std::optional<GatheredPartition> gather_partition(const OwnedModel& owned,
                                                  const DistributedPartition& partition,
                                                  const Communicator& communicator);

// What the JSON says besides the partition.
struct RunFacts {
  std::string file;
  std::string model;
  std::uint32_t ranks = 1;
  std::uint64_t transitions = 0;  // edges, as the sequential engine counts them
  std::uint32_t rounds = 0;
  bool exact_integer_sums = false;
  double load_seconds = 0;
  double refinement_seconds = 0;
  std::vector<double> peak_memory_mib;  // per rank
};

// Writes the JSON whole or not at all (AtomicFile). Returns false and sets `error` on failure.
bool write_partition_json(const std::string& path, const model::Partition& partition,
                          const RunFacts& facts, std::string& error);

}  // namespace oasis::distributed
