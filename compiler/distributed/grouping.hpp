#pragma once
// Items grouped by a small key in linear time (a counting sort that moves nothing but
// indices): the arrived choices by owned state, the states of a partition by block.

#include <cstdint>
#include <vector>

namespace oasis::distributed {

struct Grouping {
  // The items with key k are order[begin[k]], ..., order[begin[k + 1] - 1], in item order.
  std::vector<std::uint32_t> begin;  // num_keys + 1 entries
  std::vector<std::uint32_t> order;
};

// `keys[i]` is item i's key, below `num_keys`.
inline Grouping group_by_key(const std::vector<std::uint32_t>& keys, std::uint32_t num_keys) {
  Grouping grouping;
  grouping.begin.assign(std::size_t{num_keys} + 1, 0);
  for (std::uint32_t key : keys)
    ++grouping.begin[key + 1];
  for (std::uint32_t k = 0; k < num_keys; ++k)
    grouping.begin[k + 1] += grouping.begin[k];
  grouping.order.resize(keys.size());
  std::vector<std::uint32_t> next(grouping.begin.begin(), grouping.begin.end() - 1);
  for (std::uint32_t i = 0; i < keys.size(); ++i)
    grouping.order[next[keys[i]]++] = i;
  return grouping;
}

}  // namespace oasis::distributed
