#pragma once
// Every limit oasisc enforces on its inputs and its own work, in one place: its default, the
// flag that changes it (or none, when the bound is structural), and what happens beyond it.
// docs/RELIABILITY.md ("Limits") has the same table for users; keep the two in step.
//
// Each limit is reported as an error, never a crash: a spec's at its file:line:col, a file's
// as `path: error: ...`, a command's as `oasisc: error: ...`; the status is 1 and no output
// file is left half-written.

#include <cstddef>
#include <cstdint>

namespace oasis::limits {

// --- Input files -------------------------------------------------------------------------

// .oasis specs (--max-spec-size). Specs are hand-written; anything larger is almost
// certainly the wrong file.
inline constexpr std::size_t kDefaultMaxSpecBytes = std::size_t{16} << 20;

// Machine-written inputs: .aut and PRISM models, the fits' CSV logs, the JSON results that
// `verify` reads (--max-input-size). Source positions are 64-bit offsets, so any size can be
// read; the default stops a wrong file long before it matters, while a 10^8-transition .aut
// (5.3 GB) passes. What bounds a large model is the memory budget below.
inline constexpr std::size_t kDefaultMaxInputBytes = std::size_t{64} << 30;

// Binary catalogs: the runtime's loader refuses files larger than rt::kMaxCatalogFileBytes
// (8 GiB, runtime/include/oasis/rt/catalog_sections.hpp), and `compile` refuses to write one.

// --- The spec language -------------------------------------------------------------------

// Expressions nested deeper than this are refused, never a stack overflow (no flag).
inline constexpr int kMaxNesting = 200;

// The numerator and the denominator of every exact number a spec or a model file holds, and
// of every constant the checker folds, have at most this many bits (--max-number-bits):
// 2^20 bits is about 315,000 decimal digits, room for 1e-100000 squared, while repeated
// squaring of a constant (`const b = a * a; const c = b * b; ...`) stops with an error at
// the constant instead of doubling its size until memory runs out.
inline constexpr std::size_t kDefaultMaxNumberBits = std::size_t{1} << 20;

// Decimal exponents beyond this (`1e100001`) are refused as out of range (no flag): 10^100000
// already has about 330,000 bits.
inline constexpr long kMaxDecimalExponent = 100000;

// A variable's range holds at most this many values, so that exploration can pack states.
inline constexpr std::int64_t kMaxVariableRange = std::int64_t{1} << 40;

// A catalog has at most this many contexts: the runtime filter's cost grows with N^2.
inline constexpr std::size_t kMaxContexts = 4096;

// `horizon n;` is at most this many steps.
inline constexpr std::int64_t kMaxHorizon = 1'000'000'000;

// `max_cells n;` (and --max-cells) is at most this many cells per context; the defaults when
// neither gives one are pipeline::kDefaultGridCells and pipeline::kDefaultPolytopeCells.
inline constexpr std::int64_t kMaxCellsSetting = 100'000'000;

// -j N: threads at most (far beyond any machine's cores; a typo must not start a million).
inline constexpr unsigned kMaxJobs = 1024;

// --- The work ----------------------------------------------------------------------------

// States are numbered with 32 bits, and the largest number marks "no state" where one is
// needed (the refiners' lists, the state store's slots): no model has more states than this,
// whatever the options. A header declaring more is refused, naming this limit.
inline constexpr std::uint32_t kMaxStates = 4'294'967'294;

// Exploration of a factored spec, and the state count a model file's header may declare,
// stop past this many states (--max-states). By default nothing below the index's limit: what
// bounds a model is the memory budget (a header declaring more than reading it could fit is
// refused before the body is read, formats/model_size.hpp; exploration stops with "out of
// memory"). Until issue 41 the default was 20,000,000, which refused models that fit.
inline constexpr std::uint32_t kDefaultMaxStates = kMaxStates;

// Diagnostics shown before a command stops (--max-errors).
inline constexpr std::size_t kDefaultMaxErrors = 20;

// The memory a command may allocate (--memory-budget): common/command_line/memory_budget.hpp,
// shared by the three programs.

}  // namespace oasis::limits
