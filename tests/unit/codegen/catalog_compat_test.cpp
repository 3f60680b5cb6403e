// Catalog files stay loadable as the format grows: a format-1 file written by the first
// compiler (tests/compat/) loads and takes the same decisions as today's catalog; the
// format-2 section table skips sections it does not know unless they are marked required,
// refuses duplicates, and carries the quotient's transitions as an optional section.

#include <cstring>
#include <fstream>
#include <iterator>
#include <string>

#include <gtest/gtest.h>

#include "../../support/spec_models.hpp"
#include "codegen/binary_catalog.hpp"
#include "oasis/rt/attention_filter.hpp"
#include "oasis/rt/catalog_file.hpp"
#include "oasis/rt/catalog_validation.hpp"
#include "pipeline/discrete_catalog.hpp"

namespace oasis {
namespace {

std::string read_all(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

model::CatalogData todays_catalog() {
  const std::string spec = std::string(OASIS_SOURCE_DIR) + "/specs/discrete_tracking.oasis";
  std::string error;
  auto catalog = pipeline::build_catalog(test::explore_spec_file(spec),
                                         rt::spec_hash(read_all(spec)), {}, error);
  EXPECT_TRUE(catalog) << error;
  return std::move(*catalog);
}

rt::LoadedCatalog load(const std::string& bytes) {
  return rt::LoadedCatalog::from_bytes(bytes.data(), bytes.size());
}

void fix_checksum(std::string& bytes) {
  const std::uint64_t checksum =
      rt::fnv1a64(reinterpret_cast<const unsigned char*>(bytes.data()) + 32, bytes.size() - 32);
  std::memcpy(bytes.data() + 24, &checksum, sizeof checksum);
}

// The table entry k of a format-2 file, as (tag, abstraction, offset, count) at its bytes.
std::size_t entry_at(std::size_t k) {
  return rt::kCatalogHeaderBytes + k * rt::kFormat2EntryBytes;
}

TEST(CatalogCompat, AFormat1FileStillLoadsAndDecidesAsToday) {
  const std::string old_bytes =
      read_all(std::string(OASIS_SOURCE_DIR) + "/tests/compat/discrete_tracking.format1.bin");
  ASSERT_GT(old_bytes.size(), 64U);
  std::uint32_t format = 0;
  std::memcpy(&format, old_bytes.data() + 8, sizeof format);
  ASSERT_EQ(format, 1U) << "the compat file must stay a format-1 file";
  const rt::LoadedCatalog old_catalog = load(old_bytes);
  ASSERT_TRUE(old_catalog.ok()) << old_catalog.error();
  model::CatalogData today = todays_catalog();
  const rt::CatalogView now = today.view();
  const rt::CatalogView& then = old_catalog.view();
  // The file was compiled from the spec as it was before it declared its observation model
  // (issue 12): the same spec without that block, byte for byte.
  std::string spec_text =
      test::read_text_file(std::string(OASIS_SOURCE_DIR) + "/specs/discrete_tracking.oasis");
  const std::size_t block = spec_text.find("\n\n  // The sensor of Table I");
  ASSERT_NE(block, std::string::npos);
  spec_text.erase(block + 1, spec_text.rfind("}\n") - block - 1);
  EXPECT_EQ(then.spec_hash, rt::spec_hash(spec_text));
  EXPECT_NE(now.spec_hash, then.spec_hash);
  EXPECT_FALSE(then.has_robust_section());
  EXPECT_EQ(then.observation.reward_source, rt::RewardSource::kTrueState);
  EXPECT_TRUE(now.has_robust_section());
  ASSERT_EQ(then.num_abstractions, now.num_abstractions);
  for (std::uint32_t i = 0; i < now.num_abstractions; ++i) {
    EXPECT_STREQ(then.abstractions[i].context, now.abstractions[i].context);
    ASSERT_EQ(then.abstractions[i].num_blocks, now.abstractions[i].num_blocks);
    for (std::uint32_t s = 0; s < now.num_states; ++s)
      EXPECT_EQ(then.abstractions[i].block_of[s], now.abstractions[i].block_of[s]);
    for (std::uint32_t z = 0; z < now.abstractions[i].num_blocks; ++z)
      EXPECT_EQ(then.abstractions[i].policy[z], now.abstractions[i].policy[z]);
  }
  // The same decisions on a reward sequence.
  std::vector<double> work_then(rt::AttentionFilter::workspace_size(then, {}));
  std::vector<double> work_now(rt::AttentionFilter::workspace_size(now, {}));
  rt::AttentionFilter filter_then(then, {}, work_then.data(), work_then.size());
  rt::AttentionFilter filter_now(now, {}, work_now.data(), work_now.size());
  filter_then.start(1);
  filter_now.start(1);
  for (std::uint32_t t = 0; t < 50; ++t) {
    const std::uint32_t action = filter_now.action();
    ASSERT_EQ(filter_then.action(), action);
    filter_then.step(t % 3, (t / 7) % 2, action);
    filter_now.step(t % 3, (t / 7) % 2, action);
    ASSERT_EQ(filter_then.ml_abstraction(), filter_now.ml_abstraction()) << t;
  }
}

TEST(CatalogCompat, TodaysFilesAreFormat2) {
  const std::string bytes = codegen::binary_catalog(todays_catalog());
  std::uint32_t format = 0;
  std::memcpy(&format, bytes.data() + 8, sizeof format);
  EXPECT_EQ(format, rt::kCatalogFileFormat);
  EXPECT_EQ(format, 2U);
}

// Re-tags table entry k and fixes the checksum.
std::string retagged(std::string bytes, std::size_t k, std::uint32_t tag) {
  std::memcpy(bytes.data() + entry_at(k), &tag, sizeof tag);
  fix_checksum(bytes);
  return bytes;
}

std::size_t find_entry(const std::string& bytes, rt::Section tag, std::uint32_t abstraction) {
  std::uint32_t entries = 0;
  std::memcpy(&entries, bytes.data() + 12, sizeof entries);
  for (std::size_t k = 0; k < entries; ++k) {
    std::uint32_t entry_tag = 0;
    std::uint32_t entry_abstraction = 0;
    std::memcpy(&entry_tag, bytes.data() + entry_at(k), sizeof entry_tag);
    std::memcpy(&entry_abstraction, bytes.data() + entry_at(k) + 4, sizeof entry_abstraction);
    if (entry_tag == static_cast<std::uint32_t>(tag) && entry_abstraction == abstraction) return k;
  }
  ADD_FAILURE() << "no such section";
  return 0;
}

TEST(CatalogCompat, UnknownOptionalSectionsAreSkippedAndRequiredOnesRefused) {
  const std::string bytes = codegen::binary_catalog(todays_catalog());
  // The quotient's rows become an unknown optional section: the file loads without a quotient
  // only if the other two quotient sections go too, so re-tag all three.
  std::string unknown = bytes;
  for (rt::Section section : {rt::Section::kQuotientRows, rt::Section::kQuotientTargets,
                              rt::Section::kQuotientProbabilities}) {
    unknown = retagged(unknown, find_entry(unknown, section, 0),
                       1000 + static_cast<std::uint32_t>(section));
  }
  const rt::LoadedCatalog loaded = load(unknown);
  ASSERT_TRUE(loaded.ok()) << loaded.error();
  EXPECT_EQ(loaded.view().abstractions[0].quotient.choice_begin, nullptr);
  EXPECT_NE(loaded.view().abstractions[1].quotient.choice_begin, nullptr);

  const std::string required =
      retagged(bytes, find_entry(bytes, rt::Section::kQuotientRows, 0), rt::kRequiredSection | 999);
  const rt::LoadedCatalog refused = load(required);
  EXPECT_FALSE(refused.ok());
  EXPECT_NE(refused.error().find("needs a newer runtime"), std::string::npos) << refused.error();
}

TEST(CatalogCompat, DuplicateAndMissingSectionsAreRefused) {
  const std::string bytes = codegen::binary_catalog(todays_catalog());
  // Abstraction 1's policy re-labelled as abstraction 0's: a duplicate, and 1's is missing.
  std::string duplicate = bytes;
  const std::size_t k = find_entry(bytes, rt::Section::kPolicy, 1);
  const std::uint32_t zero = 0;
  std::memcpy(duplicate.data() + entry_at(k) + 4, &zero, sizeof zero);
  fix_checksum(duplicate);
  EXPECT_NE(load(duplicate).error().find("appears twice"), std::string::npos)
      << load(duplicate).error();
  const std::string missing =
      retagged(bytes, find_entry(bytes, rt::Section::kValue, 0), 77);  // optional, unknown
  EXPECT_NE(load(missing).error().find("section 'value' is missing"), std::string::npos)
      << load(missing).error();
}

TEST(CatalogCompat, AQuotientlessCatalogValidatesWithPlainActionChecks) {
  model::CatalogData catalog = todays_catalog();
  for (model::AbstractionData& abstraction : catalog.abstractions)
    abstraction.quotient = {};
  std::string why;
  EXPECT_TRUE(rt::validate(catalog.view(), &why)) << why;
  const rt::LoadedCatalog loaded = load(codegen::binary_catalog(catalog));
  ASSERT_TRUE(loaded.ok()) << loaded.error();
  catalog.abstractions[0].policy[0] = 7;  // no such action
  EXPECT_FALSE(rt::validate(catalog.view(), &why));
  EXPECT_NE(why.find("not an action"), std::string::npos) << why;
}

}  // namespace
}  // namespace oasis
