#include "model/partition.hpp"

#include <unordered_map>

namespace oasis::model {

std::vector<std::vector<StateIndex>> Partition::blocks() const {
  std::vector<std::vector<StateIndex>> result(num_blocks);
  for (model::StateIndex s = 0; s < block_of.size(); ++s)
    result[block_of[s]].push_back(s);
  return result;
}

Partition canonical_partition(const std::vector<std::uint32_t>& labels) {
  Partition partition;
  partition.block_of.resize(labels.size());
  std::unordered_map<std::uint32_t, BlockIndex> renumbered;
  for (std::size_t s = 0; s < labels.size(); ++s) {
    auto [it, inserted] = renumbered.try_emplace(labels[s], partition.num_blocks);
    if (inserted) ++partition.num_blocks;
    partition.block_of[s] = it->second;
  }
  return partition;
}

}  // namespace oasis::model
