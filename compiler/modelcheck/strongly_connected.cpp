// Tarjan's strongly connected components (strongly_connected.hpp), with an explicit stack of
// (node, next edge) frames in place of recursion.

#include "modelcheck/strongly_connected.hpp"

#include <algorithm>
#include <utility>

namespace oasis::modelcheck {
namespace {

constexpr std::uint32_t kUnvisited = UINT32_MAX;

class Tarjan {
 public:
  explicit Tarjan(const Digraph& graph)
      : graph_(graph),
        index_(graph.num_nodes(), kUnvisited),
        low_(graph.num_nodes(), 0),
        on_stack_(graph.num_nodes(), false) {
    result_.of_node.assign(graph.num_nodes(), 0);
  }

  Components run() {
    for (std::uint32_t v = 0; v < graph_.num_nodes(); ++v) {
      if (index_[v] == kUnvisited) visit(v);
    }
    return std::move(result_);
  }

 private:
  void open(std::uint32_t v) {
    index_[v] = low_[v] = counter_++;
    stack_.push_back(v);
    on_stack_[v] = true;
    frames_.emplace_back(v, graph_.first[v]);
  }

  void visit(std::uint32_t root) {
    open(root);
    while (!frames_.empty()) {
      auto& [v, edge] = frames_.back();
      if (edge < graph_.first[v + 1]) {
        const std::uint32_t w = graph_.next[edge++];
        if (index_[w] == kUnvisited) {
          open(w);
        } else if (on_stack_[w]) {
          low_[v] = std::min(low_[v], index_[w]);
        }
        continue;
      }
      const std::uint32_t done = v;
      frames_.pop_back();
      if (!frames_.empty()) {
        const std::uint32_t parent = frames_.back().first;
        low_[parent] = std::min(low_[parent], low_[done]);
      }
      if (low_[done] == index_[done]) close_component(done);
    }
  }

  void close_component(std::uint32_t root) {
    std::uint32_t w = 0;
    do {
      w = stack_.back();
      stack_.pop_back();
      on_stack_[w] = false;
      result_.of_node[w] = result_.count;
    } while (w != root);
    ++result_.count;
  }

  const Digraph& graph_;
  std::vector<std::uint32_t> index_;
  std::vector<std::uint32_t> low_;
  std::vector<bool> on_stack_;
  std::vector<std::uint32_t> stack_;
  std::vector<std::pair<std::uint32_t, std::uint32_t>> frames_;
  std::uint32_t counter_ = 0;
  Components result_;
};

}  // namespace

Components strongly_connected_components(const Digraph& graph) {
  return Tarjan(graph).run();
}

ComponentMembers group_by_component(const Components& components) {
  ComponentMembers members;
  members.first.assign(components.count + 1, 0);
  for (const std::uint32_t c : components.of_node)
    ++members.first[c + 1];
  for (std::uint32_t c = 0; c < components.count; ++c)
    members.first[c + 1] += members.first[c];
  members.nodes.resize(components.of_node.size());
  std::vector<std::uint32_t> next(members.first.begin(), members.first.end() - 1);
  for (std::uint32_t v = 0; v < components.of_node.size(); ++v)
    members.nodes[next[components.of_node[v]]++] = v;
  return members;
}

}  // namespace oasis::modelcheck
