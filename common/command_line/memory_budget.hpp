#pragma once
// The memory budget of one command of oasisc, oasis-sim or oasis-go1 (--memory-budget): a bound
// on what the process may allocate, so that a run too large for the machine stops with
// "PROGRAM: error: out of memory ..." and status 1 instead of being killed by the kernel's OOM
// killer (or dragging the machine through swap first). memory_option.hpp declares the option.
//
// The bound is the soft RLIMIT_DATA, which Linux (since 4.7) applies to the heap and to every
// private writable mapping: what malloc, operator new and GMP obtain, thread stacks included,
// but not the read-only mappings of input files or of code. Past it, malloc returns null,
// operator new throws std::bad_alloc, and so does GMP once support/gmp_allocation.hpp is
// installed; main catches it, AtomicFile and StagedDirectory leave no output behind.
// RLIMIT_AS would also count the address space that glibc's per-thread arenas reserve without
// using (64 MiB each), which makes a budget depend on the thread count.
//
// Sanitizers that keep shadow memory (AddressSanitizer, ThreadSanitizer, MemorySanitizer)
// reserve terabytes of private mappings at start-up, which any such limit would refuse; in
// those builds the budget is not enforced (memory_budget_enforceable() is false) and the
// help text says so.

#include <cstdint>
#include <optional>
#include <string>
#include <string_view>

namespace oasis {

// False in sanitizer builds whose shadow memory a data limit would refuse.
[[nodiscard]] bool memory_budget_enforceable();

// The memory this process can use: the smaller of physical RAM and its control group's memory
// limit (cgroup v2 memory.max or v1 memory.limit_in_bytes, as in a container). nullopt when
// neither can be read.
[[nodiscard]] std::optional<std::uint64_t> available_memory_bytes();

// The budget when none is given: this share of the machine's memory (the smaller of physical RAM
// and the control group's limit), so that no program of ours drives the machine into the OOM
// killer.
inline constexpr unsigned kDefaultMemoryBudgetPercent = 75;

// A budget as the user writes it: "none"; "auto" (kDefaultMemoryBudgetPercent of the
// available memory, none when that is unknown); "N%" of the available memory; or a size in
// bytes with an optional binary unit ("512M", "4G", "4GiB", "1.5G", "65536"). Returns the
// bytes, 0 for no budget, or nullopt with `error` set.
[[nodiscard]] std::optional<std::uint64_t> parse_memory_budget(std::string_view text,
                                                               std::string& error);

// The smallest budget accepted: below it oasisc could not even report its error.
inline constexpr std::uint64_t kMinMemoryBudgetBytes = std::uint64_t{16} << 20;

// Lowers the soft RLIMIT_DATA to `bytes` (never raises it: a lower limit set by the caller's
// shell stays). Returns the budget now in force (0: none), or nullopt with `error` set.
[[nodiscard]] std::optional<std::uint64_t> apply_memory_budget(std::uint64_t bytes,
                                                               std::string& error);

// Gives back the soft data limit that apply_memory_budget() lowered, once the command has run
// out of its budget: for what must still be done after (oasisc-mpi's MPI_Abort, which
// allocates to tell mpirun why). Does nothing when no budget was applied.
void lift_memory_budget();

// The soft RLIMIT_AS (a shell's `ulimit -v`), or nullopt when there is none. It bounds the
// whole address space, so a tight one runs out before the budget: the out-of-memory message
// names whichever is in force and lower.
[[nodiscard]] std::optional<std::uint64_t> address_space_limit();

}  // namespace oasis
