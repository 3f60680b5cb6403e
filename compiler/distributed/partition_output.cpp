#include "distributed/partition_output.hpp"

#include <algorithm>

#include <nlohmann/json.hpp>

#include "distributed/grouping.hpp"
#include "support/atomic_file.hpp"

namespace oasis::distributed {

std::optional<GatheredPartition> gather_partition(const OwnedModel& owned,
                                                  const DistributedPartition& partition,
                                                  const Communicator& communicator) {
  std::vector<Bytes> outgoing(communicator.size());
  ByteWriter writer(outgoing[0]);
  for (std::uint32_t block : partition.block_of_owned)
    writer.put(block);
  const std::vector<Bytes> received = communicator.exchange(outgoing);
  if (!communicator.is_root()) return std::nullopt;
  std::vector<std::uint32_t> labels(owned.num_states);
  for (std::uint32_t q = 0; q < communicator.size(); ++q) {
    ByteReader reader(received[q]);
    for (std::uint32_t local = 0; !reader.at_end(); ++local)
      labels[owned.ownership.global(local, q)] = reader.get<std::uint32_t>();
  }
  GatheredPartition gathered;
  gathered.partition = model::canonical_partition(labels);
  gathered.canonical.resize(partition.num_blocks);
  for (std::size_t s = 0; s < labels.size(); ++s)
    gathered.canonical[labels[s]] = gathered.partition.block_of[s];
  return gathered;
}

namespace {

// The blocks as arrays of state indices, ascending, streamed: no per-block containers.
void append_blocks(AtomicFile& out, const model::Partition& partition) {
  const Grouping by_block = group_by_key(partition.block_of, partition.num_blocks);
  const std::vector<std::uint32_t>& first = by_block.begin;
  const std::vector<std::uint32_t>& members = by_block.order;  // ascending within a block
  out.append('[');
  for (std::uint32_t b = 0; b < partition.num_blocks; ++b) {
    out.append(b == 0 ? "[" : ",[");
    for (std::uint32_t i = first[b]; i < first[b + 1]; ++i) {
      if (i != first[b]) out.append(',');
      out.append_number(members[i]);
    }
    out.append(']');
  }
  out.append(']');
}

}  // namespace

bool write_partition_json(const std::string& path, const model::Partition& partition,
                          const RunFacts& facts, std::string& error) {
  AtomicFile out;
  if (!out.open(path, error)) return false;
  const double peak =
      facts.peak_memory_mib.empty()
          ? 0
          : *std::max_element(facts.peak_memory_mib.begin(), facts.peak_memory_mib.end());
  nlohmann::json head{{"file", facts.file},
                      {"model", facts.model},
                      {"engine", "mpi"},
                      {"ranks", facts.ranks},
                      {"exact", true},
                      {"epsilon", nullptr},
                      {"load_seconds", facts.load_seconds},
                      {"peak_memory_mib", peak},
                      {"peak_memory_mib_per_rank", facts.peak_memory_mib}};
  std::string text = head.dump();
  text.pop_back();  // the closing brace: "contexts" follows
  out.append(text);
  nlohmann::json context{{"name", "default"},
                         {"states", partition.num_states()},
                         {"transitions", facts.transitions},
                         {"blocks", partition.num_blocks},
                         {"rounds", facts.rounds},
                         {"seconds", facts.refinement_seconds},
                         {"exact_integer_sums", facts.exact_integer_sums}};
  text = context.dump();
  text.pop_back();
  out.append(",\"contexts\":[");
  out.append(text);
  out.append(",\"partition\":");
  append_blocks(out, partition);
  out.append("}]}\n");
  return out.commit(error);
}

}  // namespace oasis::distributed
