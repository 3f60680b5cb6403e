// oasis/rt/catalog_sections.hpp: the layout of binary catalog files, shared by the compiler's
// writer and the runtime's loader. C++17, standard library only.
//
// A file is a 64-byte header, a table of sections, and the sections' arrays (all integers
// little-endian, every array 8-byte aligned):
//
//     offset  size  field
//          0     8  magic "OASISCAT"
//          8     4  file format (kCatalogFileFormat; the loader also reads format 1)
//         12     4  number of entries in the section table
//         16     8  file size in bytes
//         24     8  checksum: FNV-1a 64 of every byte from offset 32 to the end
//         32     8  spec hash
//         40     4  num_states     44  4  num_actions
//         48     4  num_abstractions   52  4  observation kind
//         56     8  p_correct (IEEE-754 double)
//         64        section table
//
// The observation model (the robust section) is the header's kind and p_correct, plus
// catalog-wide sections: the confusion matrix of a kMatrix model (required: a runtime that
// cannot read it must refuse the file), the reward source (optional: a file without it, or a
// runtime that skips it, has the reward follow the true state, as it always did) and, in
// continuous catalogs, the position noise (optional: without it the state reads as exact).
//
// Format 2 (today's): each table entry is 24 bytes, u32 tag, u32 abstraction (the index of
// the abstraction the section belongs to, or kCatalogWide), u64 offset, u64 element count.
// Sections may come in any order; a reader looks them up by (tag, abstraction). A tag with
// kRequiredSection set must be understood: a reader that does not know it refuses the file
// ("needs a newer runtime"); any other unknown section is skipped. So a section added later
// is either optional (old runtimes still load the file) or required (they refuse it plainly).
//
// Format 1 (the first files, still read): each entry is 16 bytes, u64 offset and u64 count,
// in a fixed order: the five catalog-wide sections, then per abstraction the eleven of
// kFormat1AbstractionOrder.
#pragma once

#include <cstddef>
#include <cstdint>

namespace oasis {
namespace rt {

/// "OASISCAT" read as a little-endian 64-bit integer.
inline constexpr std::uint64_t kCatalogMagic = 0x5441435349534153ULL;
inline constexpr std::size_t kCatalogHeaderBytes = 64;
/// The file format the compiler writes.
inline constexpr std::uint32_t kCatalogFileFormat = 2;
/// The oldest file format the loader reads.
inline constexpr std::uint32_t kOldestCatalogFileFormat = 1;
/// Bytes per section-table entry, by file format.
inline constexpr std::size_t kFormat1EntryBytes = 16;
inline constexpr std::size_t kFormat2EntryBytes = 24;
/// Refuse files larger than this (8 GiB). The tables a robot loads are small (the Go1
/// catalog: 1.2 MB), but a catalog written with its transition rows for analysis
/// (`oasisc compile --with-transitions`) reaches 2 GB at the Go1 spec's epsilon 0.05; the
/// limit keeps a damaged size field from asking for absurd memory.
inline constexpr std::uint64_t kMaxCatalogFileBytes = std::uint64_t{8} << 30;

/// The abstraction field of a catalog-wide section.
inline constexpr std::uint32_t kCatalogWide = 0xFFFFFFFFu;
/// Set in a tag that a reader must understand to use the file.
inline constexpr std::uint32_t kRequiredSection = 0x80000000u;

/// Section tags. Required unless noted.
enum class Section : std::uint32_t {
  kNameText = kRequiredSection | 1,  ///< char: every string, each ending in NUL
  kStringOffsets =
      kRequiredSection | 2,              ///< u32: name, compiler version, actions, states, contexts
  kSwitching = kRequiredSection | 3,     ///< f64 [N*N]
  kPrior = kRequiredSection | 4,         ///< f64 [N]
  kBlockCounts = kRequiredSection | 5,   ///< u32 [N]
  kBlockOf = kRequiredSection | 16,      ///< u32 [num_states], per abstraction
  kBlockReward = kRequiredSection | 17,  ///< f64 [blocks]
  kQuotientRows = 18,                    ///< u32 [blocks*actions + 1]; optional (analysis)
  kQuotientTargets = 19,                 ///< u32 [edges]; optional
  kQuotientProbabilities = 20,           ///< f64 [edges]; optional
  kReward = kRequiredSection | 21,       ///< f64 [blocks*actions]
  kPolicy = kRequiredSection | 22,       ///< u32 [blocks]
  kValue = kRequiredSection | 23,        ///< f64 [blocks]
  kStateRows = kRequiredSection | 24,    ///< u32 [states*actions + 1]; robust section only
  kStateTargets = kRequiredSection | 25,        ///< u32 [edges]; robust section only
  kStateProbabilities = kRequiredSection | 26,  ///< f64 [edges]; robust section only
  // Continuous catalogs (format 2 and later); the variable names follow the contexts in the
  // string table.
  kStateDimension = kRequiredSection | 6,  ///< u32 [1]: the number of continuous variables
  // The observation model beyond the header's kind and p_correct (format 2 and later).
  kConfusion = kRequiredSection | 7,  ///< f64 [num_states^2]; only with kind kMatrix
  kRewardSource = 8,                  ///< u32 [1]: a RewardSource; optional (kTrueState)
  // Continuous catalogs' position noise (PositionNoise), optional as a whole: a runtime that
  // skips it reads the state as exact, as Algorithm 1 does.
  kObjectOf = 9,          ///< u32 [state_dimension]: each variable's object, or kExactVariable
  kObjectSigma = 10,      ///< f64 [objects * 3]: a, b, c of sigma(d)
  kObjectDetection = 11,  ///< f64 [objects]: detection probability
  kGridAxes = kRequiredSection | 32,        ///< u32 [d], per abstraction
  kGridBreakBegin = kRequiredSection | 33,  ///< u32 [d + 1]
  kGridBreaks = kRequiredSection | 34,      ///< f64 [break_begin[d]]
  kCellBlock = kRequiredSection | 35,       ///< u32 [cells]
  kOutsideBlock = kRequiredSection | 36,    ///< u32 [1]
  kEpsilon = 37,                            ///< f64 [1]; optional (informational)
  // Polytope cells (bsp_locator.hpp), per abstraction, present only in such abstractions:
  kBspCounts = kRequiredSection | 38,  ///< u32 [2]: num_nodes, num_cells
  kBspNormal = kRequiredSection | 39,  ///< f64 [num_nodes * d]
  kBspBound = kRequiredSection | 40,   ///< f64 [num_nodes]
  kBspBelow = kRequiredSection | 41,   ///< u32 [num_nodes]
  kBspAbove = kRequiredSection | 42,   ///< u32 [num_nodes]
  kBspCell = kRequiredSection | 43,    ///< u32 [num_nodes]
};

/// Every section this runtime understands beyond the format-1 ones.
inline constexpr Section kContinuousSections[] = {
    Section::kStateDimension, Section::kGridAxes,  Section::kGridBreakBegin,
    Section::kGridBreaks,     Section::kCellBlock, Section::kOutsideBlock,
    Section::kEpsilon,        Section::kBspCounts, Section::kBspNormal,
    Section::kBspBound,       Section::kBspBelow,  Section::kBspAbove,
    Section::kBspCell};

/// The observation model's sections (format 2 and later).
inline constexpr Section kObservationSections[] = {Section::kConfusion, Section::kRewardSource,
                                                   Section::kObjectOf, Section::kObjectSigma,
                                                   Section::kObjectDetection};

/// The catalog-wide sections of a format-1 file, in table order.
inline constexpr Section kFormat1CatalogOrder[] = {Section::kNameText, Section::kStringOffsets,
                                                   Section::kSwitching, Section::kPrior,
                                                   Section::kBlockCounts};
/// The per-abstraction sections of a format-1 file, in table order.
inline constexpr Section kFormat1AbstractionOrder[] = {Section::kBlockOf,
                                                       Section::kBlockReward,
                                                       Section::kQuotientRows,
                                                       Section::kQuotientTargets,
                                                       Section::kQuotientProbabilities,
                                                       Section::kReward,
                                                       Section::kPolicy,
                                                       Section::kValue,
                                                       Section::kStateRows,
                                                       Section::kStateTargets,
                                                       Section::kStateProbabilities};

}  // namespace rt
}  // namespace oasis
