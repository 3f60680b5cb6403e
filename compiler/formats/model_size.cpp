#include "formats/model_size.hpp"

#include <algorithm>
#include <cstdio>
#include <limits>

#include "text/byte_size.hpp"

namespace oasis::formats {
namespace {

constexpr std::uint64_t kSaturated = std::numeric_limits<std::uint64_t>::max();

std::uint64_t times(std::uint64_t a, std::uint64_t b) {
  return b != 0 && a > kSaturated / b ? kSaturated : a * b;
}

std::uint64_t plus(std::uint64_t a, std::uint64_t b) {
  return a > kSaturated - b ? kSaturated : a + b;
}

// The largest rank's share of `count` items spread over `ranks`.
std::uint64_t share(std::uint64_t count, std::uint32_t ranks) {
  return count / ranks + (count % ranks != 0 ? 1 : 0);
}

}  // namespace

std::uint64_t least_reading_bytes(const DeclaredSize& size, std::optional<std::uint32_t> ranks) {
  const std::uint32_t parts = std::max<std::uint32_t>(ranks.value_or(1), 1);
  const std::uint64_t per_choice = ranks ? kRankBytesPerChoice : kReadBytesPerChoice;
  const std::uint64_t per_edge = ranks ? kRankBytesPerEdge : kReadBytesPerEdge;
  const std::uint64_t per_state = ranks ? kRankBytesPerState : kReadBytesPerState;
  // A choice has one edge at least, whatever the header says.
  const std::uint64_t edges = std::max(size.edges, size.choices);
  return plus(
      plus(times(share(size.choices, parts), per_choice), times(share(edges, parts), per_edge)),
      times(share(size.states, parts), per_state));
}

std::optional<std::string> state_count_refusal(std::string_view text, std::uint64_t count,
                                               const ReadOptions& options) {
  if (count > limits::kMaxStates) {
    return std::string(text) + " states, more than the " + std::to_string(limits::kMaxStates) +
           " that oasis can number (states are numbered with 32 bits; no option raises this)";
  }
  if (count > options.max_states) {
    return std::string(text) + " states, more than the limit of " +
           std::to_string(options.max_states) + " (raise it with --max-states)";
  }
  return std::nullopt;
}

std::optional<std::string> memory_refusal(const DeclaredSize& size, const ReadOptions& options,
                                          std::optional<std::uint32_t> ranks) {
  if (options.memory_budget == 0) return std::nullopt;
  const std::uint64_t needed = least_reading_bytes(size, ranks);
  if (needed <= options.memory_budget) return std::nullopt;
  std::string needed_text = text::describe_bytes(needed);
  std::string budget_text = text::describe_bytes(options.memory_budget);
  if (needed_text == budget_text) {  // "3.2 KiB, more than 3.2 KiB" would say nothing
    needed_text = std::to_string(needed) + " bytes";
    budget_text = std::to_string(options.memory_budget) + " bytes";
  }
  if (ranks) {
    const std::string where =
        *ranks == 1 ? " on one rank" : " on the largest of " + std::to_string(*ranks) + " ranks";
    return "reading it takes at least " + needed_text + where +
           ", more than the memory budget of " + budget_text +
           " per rank (raise it with --memory-budget, or run on more ranks)";
  }
  return "reading it takes at least " + needed_text + ", more than the memory budget of " +
         budget_text + " (raise it with --memory-budget)";
}

}  // namespace oasis::formats
