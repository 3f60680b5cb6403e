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
// kFormat1AbstractionOrder (both derived from kSectionTable's format-1 positions).
//
// kSectionTable below describes every section once: its tag, name, scope, element type,
// whether it is required (the tag's kRequiredSection bit) and the first format that has it.
// A new section is a new Section value and a new row (runtime/README.md, "Adding a catalog
// field").
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <iterator>

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
  // Stated properties (PropertyStatements), optional: a runtime that skips them runs the
  // catalog as it always did.
  kPropertyText = 12,                       ///< char: per property its name, NUL, its text, NUL
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
  kGuarantee = 44,  ///< f64 [properties * kGuaranteeFields], per abstraction; optional
};

/// Where a section belongs: the catalog as a whole (its table entry's abstraction is
/// kCatalogWide), or one abstraction (one entry per abstraction that has it).
enum class SectionScope : std::uint8_t { kCatalog, kAbstraction };

/// The type of a section's elements (little-endian in the file).
enum class SectionElement : std::uint8_t { kU32, kF64, kChar };

/// The C++ type of a SectionElement, for the loader and the writer.
template <SectionElement element>
struct SectionElementType;
template <>
struct SectionElementType<SectionElement::kU32> {
  using type = std::uint32_t;
};
template <>
struct SectionElementType<SectionElement::kF64> {
  using type = double;
};
template <>
struct SectionElementType<SectionElement::kChar> {
  using type = char;
};

/// SectionInfo::format1_position of a section that format 1 does not have.
inline constexpr std::uint32_t kNotInFormat1 = 0xFFFFFFFFu;

/// One row of kSectionTable: everything a reader or a writer needs to know about a tag.
struct SectionInfo {
  Section tag;
  /// What the loader's messages call the section ("array 'NAME' has ..."); the quotient's
  /// and the state model's transition sections share theirs ("transition rows", ...).
  const char* name;
  SectionScope scope;
  SectionElement element;
  /// The first file format that has the section.
  std::uint32_t first_format;
  /// Format 1 only: the entry's place in its fixed table, among the catalog-wide entries or
  /// among one abstraction's (kNotInFormat1 for a section added later).
  std::uint32_t format1_position;

  /// A reader that does not know a required section refuses the file.
  constexpr bool required() const noexcept {
    return (static_cast<std::uint32_t>(tag) & kRequiredSection) != 0;
  }
};

namespace detail {

// Rows of kSectionTable, by scope (format1_position: kNotInFormat1 unless format 1 has it).
constexpr SectionInfo wide(Section tag, const char* name, SectionElement element,
                           std::uint32_t first_format,
                           std::uint32_t format1_position = kNotInFormat1) noexcept {
  return {tag, name, SectionScope::kCatalog, element, first_format, format1_position};
}
constexpr SectionInfo each(Section tag, const char* name, SectionElement element,
                           std::uint32_t first_format,
                           std::uint32_t format1_position = kNotInFormat1) noexcept {
  return {tag, name, SectionScope::kAbstraction, element, first_format, format1_position};
}

/// Every section of the file format, one row per Section tag (checked below and in
/// tests/unit/runtime/catalog_sections_test.cpp). The loader (catalog_file.hpp) takes from
/// it which tags it knows, the format-1 table order, each array's element type and its name;
/// the compiler's writer (codegen/binary_catalog.cpp) the element type and scope it writes.
/// Columns: scope (wide: catalog-wide; each: per abstraction), tag, name, element type, first
/// format, format-1 position.
// clang-format off
inline constexpr SectionInfo kSectionRows[] = {
    wide(Section::kNameText,              "name text",                SectionElement::kChar, 1, 0),
    wide(Section::kStringOffsets,         "string offsets",           SectionElement::kU32,  1, 1),
    wide(Section::kSwitching,             "switching",                SectionElement::kF64,  1, 2),
    wide(Section::kPrior,                 "prior",                    SectionElement::kF64,  1, 3),
    wide(Section::kBlockCounts,           "block counts",             SectionElement::kU32,  1, 4),
    each(Section::kBlockOf,               "block_of",                 SectionElement::kU32,  1, 0),
    each(Section::kBlockReward,           "block_reward",             SectionElement::kF64,  1, 1),
    each(Section::kQuotientRows,          "transition rows",          SectionElement::kU32,  1, 2),
    each(Section::kQuotientTargets,       "transition targets",       SectionElement::kU32,  1, 3),
    each(Section::kQuotientProbabilities, "transition probabilities", SectionElement::kF64,  1, 4),
    each(Section::kReward,                "reward",                   SectionElement::kF64,  1, 5),
    each(Section::kPolicy,                "policy",                   SectionElement::kU32,  1, 6),
    each(Section::kValue,                 "value",                    SectionElement::kF64,  1, 7),
    each(Section::kStateRows,             "transition rows",          SectionElement::kU32,  1, 8),
    each(Section::kStateTargets,          "transition targets",       SectionElement::kU32,  1, 9),
    each(Section::kStateProbabilities,    "transition probabilities", SectionElement::kF64,  1, 10),
    wide(Section::kStateDimension,        "state dimension",          SectionElement::kU32,  2),
    wide(Section::kConfusion,             "confusion matrix",         SectionElement::kF64,  2),
    wide(Section::kRewardSource,          "reward source",            SectionElement::kU32,  2),
    wide(Section::kObjectOf,              "object of each variable",  SectionElement::kU32,  2),
    wide(Section::kObjectSigma,           "object sigma",             SectionElement::kF64,  2),
    wide(Section::kObjectDetection,       "object detection",         SectionElement::kF64,  2),
    each(Section::kGridAxes,              "grid axes",                SectionElement::kU32,  2),
    each(Section::kGridBreakBegin,        "grid break offsets",       SectionElement::kU32,  2),
    each(Section::kGridBreaks,            "grid breakpoints",         SectionElement::kF64,  2),
    each(Section::kCellBlock,             "cell blocks",              SectionElement::kU32,  2),
    each(Section::kOutsideBlock,          "outside block",            SectionElement::kU32,  2),
    each(Section::kEpsilon,               "epsilon",                  SectionElement::kF64,  2),
    each(Section::kBspCounts,             "BSP counts",               SectionElement::kU32,  2),
    each(Section::kBspNormal,             "BSP normals",              SectionElement::kF64,  2),
    each(Section::kBspBound,              "BSP bounds",               SectionElement::kF64,  2),
    each(Section::kBspBelow,              "BSP below",                SectionElement::kU32,  2),
    each(Section::kBspAbove,              "BSP above",                SectionElement::kU32,  2),
    each(Section::kBspCell,               "BSP cells",                SectionElement::kU32,  2),
    wide(Section::kPropertyText,          "property text",            SectionElement::kChar, 2),
    each(Section::kGuarantee,             "guarantees",               SectionElement::kF64,  2),
};
// clang-format on

}  // namespace detail

/// The rows of detail::kSectionRows (written there beside the helpers that make them).
inline constexpr const auto& kSectionTable = detail::kSectionRows;

inline constexpr std::size_t kSectionCount = std::size(kSectionTable);

/// The row of `tag`, or null for a tag this runtime does not know (a raw tag from a file).
constexpr const SectionInfo* find_section(std::uint32_t tag) noexcept {
  for (const SectionInfo& info : kSectionTable)
    if (static_cast<std::uint32_t>(info.tag) == tag) return &info;
  return nullptr;
}

/// The row of a tag this runtime knows (every Section has one).
constexpr const SectionInfo& section_info(Section tag) noexcept {
  return *find_section(static_cast<std::uint32_t>(tag));
}

/// The C++ type of a section's elements.
template <Section tag>
using SectionElementOf = typename SectionElementType<section_info(tag).element>::type;

namespace detail {

constexpr std::size_t format1_count(SectionScope scope) noexcept {
  std::size_t count = 0;
  for (const SectionInfo& info : kSectionTable)
    if (info.format1_position != kNotInFormat1 && info.scope == scope) ++count;
  return count;
}

// The format-1 sections of `scope` in table order (the sections at their positions).
template <std::size_t count>
constexpr std::array<Section, count> format1_order(SectionScope scope) noexcept {
  std::array<Section, count> order{};
  for (const SectionInfo& info : kSectionTable)
    if (info.format1_position != kNotInFormat1 && info.scope == scope)
      order[info.format1_position] = info.tag;
  return order;
}

// Each tag once; each format-1 position of a scope once and below the scope's count; format
// 1's sections are those of the first format.
constexpr bool section_table_is_consistent() noexcept {
  for (std::size_t a = 0; a < kSectionCount; ++a) {
    const SectionInfo& row = kSectionTable[a];
    if ((row.format1_position != kNotInFormat1) != (row.first_format == 1)) return false;
    if (row.first_format < kOldestCatalogFileFormat || row.first_format > kCatalogFileFormat)
      return false;
    if (row.format1_position != kNotInFormat1 && row.format1_position >= format1_count(row.scope))
      return false;
    for (std::size_t b = a + 1; b < kSectionCount; ++b) {
      const SectionInfo& other = kSectionTable[b];
      if (other.tag == row.tag) return false;
      if (other.scope == row.scope && other.format1_position == row.format1_position &&
          row.format1_position != kNotInFormat1)
        return false;
    }
  }
  return true;
}

}  // namespace detail

static_assert(detail::section_table_is_consistent(),
              "kSectionTable: a tag twice, or format-1 positions that are not 0, 1, 2, ...");

/// The catalog-wide sections of a format-1 file, in table order.
inline constexpr auto kFormat1CatalogOrder =
    detail::format1_order<detail::format1_count(SectionScope::kCatalog)>(SectionScope::kCatalog);
/// The per-abstraction sections of a format-1 file, in table order.
inline constexpr auto kFormat1AbstractionOrder =
    detail::format1_order<detail::format1_count(SectionScope::kAbstraction)>(
        SectionScope::kAbstraction);

}  // namespace rt
}  // namespace oasis
