#pragma once
// Strongly connected components of a directed graph in CSR form (Tarjan's algorithm, iterative
// so that a chain of 10^6 states does not overflow the stack). Components come numbered in
// the order Tarjan completes them, which is a reverse topological order: every edge leads
// from a component to one with a smaller or equal number, so solving components 0, 1, 2, ...
// in turn always finds the values a component depends on already computed.

#include <cstdint>
#include <vector>

namespace oasis::modelcheck {

struct Digraph {
  std::vector<std::uint32_t> first;  // nodes + 1
  std::vector<std::uint32_t> next;   // successor of each edge
  [[nodiscard]] std::uint32_t num_nodes() const {
    return static_cast<std::uint32_t>(first.size() - 1);
  }
};

struct Components {
  std::vector<std::uint32_t> of_node;
  std::uint32_t count = 0;
};

Components strongly_connected_components(const Digraph& graph);

// Nodes grouped by component, components in increasing number: [first[c], first[c+1]).
struct ComponentMembers {
  std::vector<std::uint32_t> first;
  std::vector<std::uint32_t> nodes;
};
ComponentMembers group_by_component(const Components& components);

}  // namespace oasis::modelcheck
