#pragma once
// The size a model file declares in its header, checked before its body is read: against
// the 32-bit state index, against --max-states when the user gives one, and against the
// memory budget (--memory-budget), so that a model too large for the machine is refused at
// once, in its header, rather than after minutes of reading or by the kernel's OOM killer.
//
// The memory check is a lower bound, never a guess: it counts only the arrays every reader
// fills in proportion to the header's numbers (docs/PERFORMANCE.md, "Half the memory, and
// 10^8 transitions"), with one edge per choice when the header does not say how many. So a
// refusal is certain to be right; a model that passes may still need more later (the
// refinement's arrays, a file with many edges per choice), and then the budget itself stops
// the command with "out of memory" (common/command_line/memory_budget.hpp).

#include <cstdint>
#include <optional>
#include <string>
#include <string_view>

#include "formats/read_options.hpp"

namespace oasis::formats {

// What a header declares. `edges` may be 0 when the header does not say (then each choice
// is counted with one edge).
struct DeclaredSize {
  std::uint64_t states = 0;
  std::uint64_t choices = 0;
  std::uint64_t edges = 0;
};

// Bytes per choice and per edge that a sequential reader holds while reading
// (DistributionCollector: source, action, file offset, payload and first edge per choice;
// target and probability id per edge), and per state in the model it returns (the choices'
// offsets, one action at least).
inline constexpr std::uint64_t kReadBytesPerChoice = 24;
inline constexpr std::uint64_t kReadBytesPerEdge = 8;
inline constexpr std::uint64_t kReadBytesPerState = 4;

// The same for one rank of the distributed reader (distributed/distributed_reader.cpp,
// Arrivals: state, action, reward and first edge per choice; target and probability per edge;
// the first choice of each owned state), which holds about 1/P of each.
inline constexpr std::uint64_t kRankBytesPerChoice = 16;
inline constexpr std::uint64_t kRankBytesPerEdge = 8;
inline constexpr std::uint64_t kRankBytesPerState = 4;

// The bytes the sequential reader (`ranks` nullopt) or the largest of `ranks` ranks of the
// distributed one holds at least while reading a model of this size. Saturates instead of
// wrapping.
[[nodiscard]] std::uint64_t least_reading_bytes(const DeclaredSize& size,
                                                std::optional<std::uint32_t> ranks);

// Why a header declaring `count` states (written as `text` in the file) cannot be read, or
// nullopt: the message's tail after "... declares ", naming --max-states when that is the
// limit, or the state index when no option can raise it.
[[nodiscard]] std::optional<std::string> state_count_refusal(std::string_view text,
                                                             std::uint64_t count,
                                                             const ReadOptions& options);

// Why a model of this size does not fit options.memory_budget (per rank, for `ranks` ranks of
// the distributed reader), or nullopt (also when there is no budget): "reading it takes at
// least ..., more than the memory budget of ... (raise it with --memory-budget)".
[[nodiscard]] std::optional<std::string> memory_refusal(
    const DeclaredSize& size, const ReadOptions& options,
    std::optional<std::uint32_t> ranks = std::nullopt);

}  // namespace oasis::formats
