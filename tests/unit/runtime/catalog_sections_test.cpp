// The section table (catalog_sections.hpp) describes every Section tag exactly once, and what
// the loader derives from it (the format-1 table orders) is the layout format-1 files have.
// C++17, the runtime only.

#include "oasis/rt/catalog_sections.hpp"

#include <cstdint>
#include <set>
#include <string>
#include <type_traits>

#include <gtest/gtest.h>

namespace {

using oasis::rt::Section;

// True exactly for the enumerators of Section: a switch without a default, so that the
// build (-Wall -Werror: -Wswitch) fails when an enumerator is added and not named here, and
// a value that names none falls through to false.
bool names_an_enumerator(Section tag) {
  switch (tag) {
    case Section::kNameText:
    case Section::kStringOffsets:
    case Section::kSwitching:
    case Section::kPrior:
    case Section::kBlockCounts:
    case Section::kBlockOf:
    case Section::kBlockReward:
    case Section::kQuotientRows:
    case Section::kQuotientTargets:
    case Section::kQuotientProbabilities:
    case Section::kReward:
    case Section::kPolicy:
    case Section::kValue:
    case Section::kStateRows:
    case Section::kStateTargets:
    case Section::kStateProbabilities:
    case Section::kStateDimension:
    case Section::kConfusion:
    case Section::kRewardSource:
    case Section::kObjectOf:
    case Section::kObjectSigma:
    case Section::kObjectDetection:
    case Section::kGridAxes:
    case Section::kGridBreakBegin:
    case Section::kGridBreaks:
    case Section::kCellBlock:
    case Section::kOutsideBlock:
    case Section::kEpsilon:
    case Section::kBspCounts:
    case Section::kBspNormal:
    case Section::kBspBound:
    case Section::kBspBelow:
    case Section::kBspAbove:
    case Section::kBspCell:
    case Section::kPropertyText:
    case Section::kGuarantee:
      return true;
  }
  return false;
}

std::size_t rows_with_tag(std::uint32_t tag) {
  std::size_t rows = 0;
  for (const oasis::rt::SectionInfo& info : oasis::rt::kSectionTable)
    if (static_cast<std::uint32_t>(info.tag) == tag) ++rows;
  return rows;
}

// Every tag a file could hold below 256, required or not: the enumerators are among them.
TEST(SectionTable, HasEveryEnumeratorExactlyOnceAndNothingElse) {
  std::size_t enumerators = 0;
  for (const std::uint32_t required : {0u, oasis::rt::kRequiredSection}) {
    for (std::uint32_t low = 0; low < 256; ++low) {
      const std::uint32_t tag = required | low;
      const bool enumerator = names_an_enumerator(static_cast<Section>(tag));
      enumerators += enumerator ? 1 : 0;
      EXPECT_EQ(rows_with_tag(tag), enumerator ? 1u : 0u) << "tag " << tag;
    }
  }
  EXPECT_EQ(enumerators, oasis::rt::kSectionCount);
}

TEST(SectionTable, RequiredIsTheTagsBit) {
  EXPECT_TRUE(oasis::rt::section_info(Section::kBlockOf).required());
  EXPECT_FALSE(oasis::rt::section_info(Section::kRewardSource).required());
  EXPECT_FALSE(oasis::rt::section_info(Section::kEpsilon).required());
}

// The fixed order of format-1 files (tests/compat/discrete_tracking.format1.bin is one).
TEST(SectionTable, GivesFormat1sTableOrder) {
  const Section catalog_wide[] = {Section::kNameText, Section::kStringOffsets, Section::kSwitching,
                                  Section::kPrior, Section::kBlockCounts};
  const Section per_abstraction[] = {Section::kBlockOf,
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
  ASSERT_EQ(oasis::rt::kFormat1CatalogOrder.size(), std::size(catalog_wide));
  for (std::size_t k = 0; k < std::size(catalog_wide); ++k)
    EXPECT_EQ(oasis::rt::kFormat1CatalogOrder[k], catalog_wide[k]) << k;
  ASSERT_EQ(oasis::rt::kFormat1AbstractionOrder.size(), std::size(per_abstraction));
  for (std::size_t k = 0; k < std::size(per_abstraction); ++k)
    EXPECT_EQ(oasis::rt::kFormat1AbstractionOrder[k], per_abstraction[k]) << k;
}

// The element types the loader reads and the writer writes.
TEST(SectionTable, ElementTypes) {
  static_assert(std::is_same_v<oasis::rt::SectionElementOf<Section::kNameText>, char>);
  static_assert(std::is_same_v<oasis::rt::SectionElementOf<Section::kBlockOf>, std::uint32_t>);
  static_assert(std::is_same_v<oasis::rt::SectionElementOf<Section::kObjectSigma>, double>);
  std::set<std::string> names;
  for (const oasis::rt::SectionInfo& info : oasis::rt::kSectionTable) {
    EXPECT_NE(std::string(info.name), "") << static_cast<std::uint32_t>(info.tag);
    names.insert(info.name);
  }
  // Only the quotient's and the state model's CSR sections share names (3 pairs).
  EXPECT_EQ(names.size(), oasis::rt::kSectionCount - 3);
}

}  // namespace
