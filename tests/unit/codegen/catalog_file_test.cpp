// The binary catalog file: written by the compiler, loaded by the runtime. A loaded catalog
// must take the same decisions as the one it was written from; damaged files must be
// refused with a reason and never read out of bounds (run under ASan/UBSan).

#include "oasis/rt/catalog_file.hpp"

#include <cstring>
#include <filesystem>
#include <random>

#include <gtest/gtest.h>
#include <sys/stat.h>

#include "../../support/scratch_directory.hpp"
#include "../../support/spec_models.hpp"
#include "codegen/binary_catalog.hpp"
#include "oasis/rt/attention_filter.hpp"
#include "oasis/rt/catalog_validation.hpp"
#include "pipeline/discrete_catalog.hpp"

namespace oasis {
namespace {

model::CatalogData paper_catalog(std::optional<double> p_correct = std::nullopt) {
  const auto model =
      test::explore_spec_file(std::string(OASIS_SOURCE_DIR) + "/specs/discrete_tracking.oasis");
  pipeline::BuildOptions options;
  options.catalog.p_correct = p_correct;
  std::string error;
  auto catalog = pipeline::build_catalog(model, rt::spec_hash("spec"), options, error);
  EXPECT_TRUE(catalog) << error;
  return std::move(*catalog);
}

rt::LoadedCatalog load(const std::string& bytes) {
  return rt::LoadedCatalog::from_bytes(bytes.data(), bytes.size());
}

// Runs the filter on both views over the same pseudo-random observations and compares
// every decision.
void expect_same_decisions(const rt::CatalogView& a, const rt::CatalogView& b,
                           rt::FilterMode mode) {
  rt::FilterOptions options;
  options.mode = mode;
  options.tie_rule = rt::TieRule::kRandom;
  options.seed = 7;
  std::vector<double> work_a(rt::AttentionFilter::workspace_size(a, options));
  std::vector<double> work_b(rt::AttentionFilter::workspace_size(b, options));
  rt::AttentionFilter fa(a, options, work_a.data(), work_a.size());
  rt::AttentionFilter fb(b, options, work_b.data(), work_b.size());
  ASSERT_TRUE(fa.ok() && fb.ok());
  fa.start(1);
  fb.start(1);
  std::mt19937 random(3);
  for (int t = 0; t < 300; ++t) {
    const auto state = static_cast<std::uint32_t>(random() % 3);
    const double reward = (random() % 2 == 0) ? 0.0 : 1.0;
    const std::uint32_t action = fa.action();
    ASSERT_EQ(action, fb.action());
    ASSERT_EQ(fa.step(state, reward, action), fb.step(state, reward, action));
    ASSERT_EQ(fa.ml_abstraction(), fb.ml_abstraction()) << "step " << t;
    ASSERT_EQ(fa.belief(0), fb.belief(0));
  }
}

TEST(CatalogFile, RoundTripKeepsEverything) {
  model::CatalogData catalog = paper_catalog();
  const std::string bytes = codegen::binary_catalog(catalog);
  EXPECT_EQ(bytes.size() % 8, 0U);
  EXPECT_EQ(bytes, codegen::binary_catalog(catalog)) << "output must be deterministic";
  const rt::LoadedCatalog loaded = load(bytes);
  ASSERT_TRUE(loaded.ok()) << loaded.error();
  const rt::CatalogView& view = loaded.view();
  const rt::CatalogView original = catalog.view();
  EXPECT_EQ(view.spec_hash, original.spec_hash);
  EXPECT_STREQ(view.name, "discrete_tracking");
  EXPECT_STREQ(view.action_names[1], "R");
  EXPECT_STREQ(view.state_names[2], "s3");
  EXPECT_STREQ(view.abstractions[1].context, "object_at_s1");
  EXPECT_EQ(view.abstractions[0].num_blocks, 2U);
  expect_same_decisions(original, view, rt::FilterMode::kPaper);
}

TEST(CatalogFile, RobustSectionRoundTrips) {
  model::CatalogData catalog = paper_catalog(0.3);
  const rt::LoadedCatalog loaded = load(codegen::binary_catalog(catalog));
  ASSERT_TRUE(loaded.ok()) << loaded.error();
  EXPECT_TRUE(loaded.view().has_robust_section());
  EXPECT_DOUBLE_EQ(loaded.view().observation.p_correct, 0.3);
  expect_same_decisions(catalog.view(), loaded.view(), rt::FilterMode::kJoint);
}

TEST(CatalogFile, FileOnDiskLoads) {
  const test::ScratchDirectory scratch("oasis_catalog_file_test");
  const auto path = scratch.path() / "catalog.bin";
  std::string error;
  ASSERT_TRUE(codegen::write_binary_catalog(paper_catalog(), path.string(), error)) << error;
  const rt::LoadedCatalog loaded = rt::LoadedCatalog::from_file(path.string());
  EXPECT_TRUE(loaded.ok()) << loaded.error();
  std::filesystem::remove(path);
  const rt::LoadedCatalog missing = rt::LoadedCatalog::from_file(path.string());
  EXPECT_FALSE(missing.ok());
  EXPECT_NE(missing.error().find("cannot open"), std::string::npos);
}

// Issue 28: a directory is not "too large for a catalog", and a FIFO nobody writes to is
// refused at once rather than blocking the open forever.
TEST(CatalogFile, ADirectoryOrAFifoIsRefusedForWhatItIs) {
  const test::ScratchDirectory scratch("oasis_catalog_file_test");
  const rt::LoadedCatalog folder = rt::LoadedCatalog::from_file(scratch.path().string());
  EXPECT_FALSE(folder.ok());
  EXPECT_NE(folder.error().find("is a directory, not a catalog file"), std::string::npos)
      << folder.error();
  const auto fifo = scratch.path() / "nobody_writes";
  ASSERT_EQ(::mkfifo(fifo.c_str(), 0600), 0);
  const rt::LoadedCatalog pipe = rt::LoadedCatalog::from_file(fifo.string());
  EXPECT_FALSE(pipe.ok());
  EXPECT_NE(pipe.error().find("is not a regular file"), std::string::npos) << pipe.error();
  std::filesystem::remove(fifo);
}

TEST(CatalogFile, ACatalogOfAnotherSpecIsRefusedByItsHash) {
  const test::ScratchDirectory scratch("oasis_catalog_file_test");
  const auto path = (scratch.path() / "catalog.bin").string();
  std::string error;
  ASSERT_TRUE(codegen::write_binary_catalog(paper_catalog(), path, error)) << error;

  const rt::LoadedCatalog same = rt::LoadedCatalog::from_file(path, rt::spec_hash("spec"));
  EXPECT_TRUE(same.ok()) << same.error();
  const rt::LoadedCatalog edited = rt::LoadedCatalog::from_file(path, rt::spec_hash("spec "));
  EXPECT_FALSE(edited.ok());
  EXPECT_EQ(edited.error(), path + ": compiled from another spec (spec hash " +
                                rt::spec_hash_text(rt::spec_hash("spec")) + ", expected " +
                                rt::spec_hash_text(rt::spec_hash("spec ")) + ")");
  // A damaged file keeps its own reason: the hash is only compared on a whole catalog.
  const rt::LoadedCatalog missing = rt::LoadedCatalog::from_file(path + ".none", 0);
  EXPECT_NE(missing.error().find("cannot open"), std::string::npos) << missing.error();
}

TEST(CatalogFile, HashTextIsSixteenHexDigits) {
  EXPECT_EQ(rt::spec_hash_text(rt::spec_hash("a")), "af63dc4c8601ec8c");
  EXPECT_EQ(rt::spec_hash_text(0), "0000000000000000");
  EXPECT_EQ(rt::spec_hash_text(0xF), "000000000000000f");
  EXPECT_EQ(rt::spec_hash_text(~std::uint64_t{0}), "ffffffffffffffff");
}

TEST(CatalogFile, HeaderProblemsAreNamed) {
  const std::string good = codegen::binary_catalog(paper_catalog());
  std::string bad = good;
  bad[0] = 'X';
  EXPECT_NE(load(bad).error().find("bad magic"), std::string::npos);
  bad = good;
  bad[8] = 9;  // format version
  EXPECT_NE(load(bad).error().find("format 9"), std::string::npos);
  bad = good;
  bad[bad.size() - 1] ^= 1;
  EXPECT_NE(load(bad).error().find("checksum"), std::string::npos);
  EXPECT_NE(load(good.substr(0, good.size() - 8)).error().find("size does not match"),
            std::string::npos);
  EXPECT_NE(load(good.substr(0, 10)).error().find("too short"), std::string::npos);
  EXPECT_FALSE(load("").ok());
}

TEST(CatalogFile, EveryTruncationIsRefused) {
  const std::string good = codegen::binary_catalog(paper_catalog(0.5));
  for (std::size_t size = 0; size < good.size(); ++size) {
    EXPECT_FALSE(load(good.substr(0, size)).ok()) << size;
  }
}

// Mutations that keep the checksum right (it is recomputed), so the structural checks and
// validate() must catch them: whatever loads must be a sound catalog the filter can run.
TEST(CatalogFile, MutationsWithAFixedChecksumNeverBreakTheLoader) {
  const std::string good = codegen::binary_catalog(paper_catalog(0.5));
  std::mt19937 random(11);
  int accepted = 0;
  for (int trial = 0; trial < 4000; ++trial) {
    std::string bad = good;
    const int flips = 1 + static_cast<int>(random() % 4);
    for (int f = 0; f < flips; ++f) {
      const std::size_t at = 32 + random() % (bad.size() - 32);
      bad[at] = static_cast<char>(
          random() % 4 == 0 ? 0xFF : bad[at] ^ static_cast<char>(1U << (random() % 8)));
    }
    const std::uint64_t checksum =
        rt::fnv1a64(reinterpret_cast<const unsigned char*>(bad.data()) + 32, bad.size() - 32);
    std::memcpy(bad.data() + 24, &checksum, sizeof checksum);
    const rt::LoadedCatalog loaded = load(bad);
    if (!loaded.ok()) {
      EXPECT_FALSE(loaded.error().empty());
      continue;
    }
    ++accepted;
    std::string why;
    ASSERT_TRUE(rt::validate(loaded.view(), &why)) << why;
    rt::FilterOptions options;
    options.mode = rt::FilterMode::kJoint;
    std::vector<double> work(rt::AttentionFilter::workspace_size(loaded.view(), options));
    rt::AttentionFilter filter(loaded.view(), options, work.data(), work.size());
    if (!filter.ok()) continue;
    filter.start(0);
    for (std::uint32_t t = 0; t < 20; ++t)
      filter.step(t % 3, t % 2, filter.action() % 2);
  }
  // Some mutations (a value inside a double, a state name's letter) leave a valid catalog.
  EXPECT_GT(accepted, 0);
}

}  // namespace
}  // namespace oasis
