// The in-memory catalog: what the compiler hands the runtime. For the paper's example it
// must pass the runtime's own validation, carry the two abstractions and their policies, and
// drive the attention filter to the context that explains the rewards.

#include <cmath>
#include <fstream>
#include <iterator>
#include <string>
#include <utility>

#include <gtest/gtest.h>

#include "../../support/run_oasisc.hpp"
#include "../../support/scratch_directory.hpp"
#include "../../support/spec_models.hpp"
#include "oasis/rt/attention_filter.hpp"
#include "oasis/rt/catalog_file.hpp"
#include "oasis/rt/catalog_validation.hpp"
#include "oasis/rt/catalog_view.hpp"
#include "oasis/rt/spec_hash.hpp"
#include "pipeline/discrete_catalog.hpp"

namespace oasis {
namespace {

model::ExplicitModel discrete_tracking() {
  return test::explore_spec_file(std::string(OASIS_SOURCE_DIR) + "/specs/discrete_tracking.oasis");
}

model::CatalogData build(const model::ExplicitModel& model, pipeline::BuildOptions options = {}) {
  std::string error;
  auto catalog = pipeline::build_catalog(model, 42, options, error);
  EXPECT_TRUE(catalog) << error;
  return catalog ? std::move(*catalog) : model::CatalogData{};
}

TEST(CatalogData, PaperExampleIsAValidCatalog) {
  model::CatalogData catalog = build(discrete_tracking());
  const rt::CatalogView view = catalog.view();
  std::string why;
  ASSERT_TRUE(rt::validate(view, &why)) << why;
  EXPECT_EQ(view.num_states, 3U);
  EXPECT_EQ(view.num_actions, 2U);
  ASSERT_EQ(view.num_abstractions, 2U);
  EXPECT_EQ(view.spec_hash, 42U);
  EXPECT_STREQ(view.abstractions[0].context, "object_at_s3");
  // object_at_s3: {s1, s2} -> 0, {s3} -> 1; rewarded in block 1.
  const rt::AbstractionView& at_s3 = view.abstractions[0];
  EXPECT_EQ(at_s3.num_blocks, 2U);
  EXPECT_EQ(std::vector<std::uint32_t>(at_s3.block_of, at_s3.block_of + 3),
            (std::vector<std::uint32_t>{0, 0, 1}));
  EXPECT_EQ(at_s3.block_reward[0], 0.0);
  EXPECT_EQ(at_s3.block_reward[1], 1.0);
  // The policy moves right towards s3 and stays there (R at s3 keeps it: 10 > 8.36).
  EXPECT_EQ(at_s3.policy[0], 1U);
  EXPECT_EQ(at_s3.policy[1], 1U);
  // object_at_s1: {s1} -> 0, {s2, s3} -> 1; the policy moves left.
  const rt::AbstractionView& at_s1 = view.abstractions[1];
  EXPECT_EQ(std::vector<std::uint32_t>(at_s1.block_of, at_s1.block_of + 3),
            (std::vector<std::uint32_t>{0, 1, 1}));
  EXPECT_EQ(at_s1.policy[0], 0U);
  EXPECT_EQ(at_s1.policy[1], 0U);
  EXPECT_DOUBLE_EQ(view.switching[0], 0.8);
  EXPECT_DOUBLE_EQ(view.prior[1], 0.5);
}

TEST(CatalogData, RobustSectionValidates) {
  pipeline::BuildOptions options;
  options.catalog.p_correct = 0.3;
  model::CatalogData catalog = build(discrete_tracking(), options);
  const rt::CatalogView view = catalog.view();
  std::string why;
  ASSERT_TRUE(rt::validate(view, &why)) << why;
  EXPECT_TRUE(view.has_robust_section());
  EXPECT_EQ(view.abstractions[0].state_transitions.num_edges, 10U);
}

// The runtime's validation of stated properties: an interval per value (an infinite reward
// as +infinity both ways), each abstraction holding them, none without properties.
TEST(CatalogData, StatedPropertiesValidateAsIntervals) {
  model::CatalogData catalog = build(discrete_tracking());
  catalog.properties.push_back({"p", "Pmax=? [F \"s3\"]"});
  const auto validates = [&catalog](const char* what) {
    std::string why;
    const bool ok = rt::validate(catalog.view(), &why);
    return ok ? std::string("ok") : std::string(what) + ": " + why;
  };
  for (model::AbstractionData& data : catalog.abstractions)
    data.guarantee = {0.25, 0.25, 1.0, 1.0};
  EXPECT_EQ(validates("exact values"), "ok");
  catalog.abstractions[1].guarantee = {HUGE_VAL, HUGE_VAL, 0.5, 0.5000001};
  EXPECT_EQ(validates("infinite and an interval"), "ok");
  catalog.abstractions[1].guarantee = {0.5, 0.25, 1.0, 1.0};
  EXPECT_NE(validates("lower above upper").find("is not an interval"), std::string::npos);
  catalog.abstractions[1].guarantee = {0.25, std::nan(""), 1.0, 1.0};
  EXPECT_NE(validates("NaN").find("is not an interval"), std::string::npos);
  catalog.abstractions[1].guarantee.clear();
  EXPECT_NE(validates("missing").find("have no values"), std::string::npos);
  catalog.properties.clear();
  catalog.abstractions[1].guarantee = {0.25, 0.25, 1.0, 1.0};
  EXPECT_NE(validates("without properties").find("guarantees without properties"),
            std::string::npos);
}

TEST(CatalogData, FilterFollowsTheRewards) {
  model::CatalogData catalog = build(discrete_tracking());
  const rt::CatalogView view = catalog.view();
  rt::FixedWorkspace<2> workspace;
  rt::AttentionFilter filter(view, {}, workspace);
  ASSERT_TRUE(filter.ok());
  filter.start(1);  // s2
  // At s1 with reward 1: only "object at s1" explains it.
  EXPECT_EQ(filter.step(0, 1.0, 0), rt::StepStatus::kOk);
  EXPECT_EQ(filter.ml_abstraction(), 1U);
  EXPECT_EQ(filter.action(), 0U);  // go left, towards the object
  // At s3 with reward 1: now only "object at s3" does.
  filter.step(2, 1.0, 1);
  EXPECT_EQ(filter.ml_abstraction(), 0U);
  EXPECT_EQ(filter.action(), 1U);
}

TEST(CatalogData, BlockWithMixedStateRewardsIsRefused) {
  // s1 and s2 are bisimilar through R(s, a) (1 + 0 = 0 + 1) but their state rewards differ.
  const model::ExplicitModel model = test::explore_spec_text(R"(
mdp m {
  states s1, s2;
  actions a;
  s1, a -> s1;
  s2, a -> s2;
  reward s1 : 1;
  reward [a] s2 : 1;
}
)");
  std::string error;
  EXPECT_FALSE(pipeline::build_catalog(model, 0, {}, error));
  EXPECT_NE(error.find("one reward R(s) per abstract state"), std::string::npos) << error;
}

TEST(CatalogData, SpecHashIsFnv1a64) {
  EXPECT_EQ(rt::spec_hash("mdp m {}"), rt::spec_hash("mdp m {}"));
  EXPECT_NE(rt::spec_hash("mdp m {}"), rt::spec_hash("mdp n {}"));
  // Published FNV-1a 64 test values.
  EXPECT_EQ(rt::spec_hash(""), 0xcbf29ce484222325ULL);
  EXPECT_EQ(rt::spec_hash("a"), 0xaf63dc4c8601ec8cULL);
  EXPECT_EQ(rt::spec_hash("foobar"), 0x85944171f73967e8ULL);
  const std::string_view text = "foobar";
  EXPECT_EQ(rt::fnv1a64(reinterpret_cast<const unsigned char*>(text.data()), text.size()),
            rt::spec_hash(text));
}

// oasisc hashes the bytes its front end or reader parsed, once (input/model_loader.cpp): the
// catalog it writes carries rt::spec_hash of the input file, for a spec and an import alike.
TEST(CatalogData, ACompiledCatalogCarriesTheHashOfItsInputsBytes) {
  const test::ScratchDirectory scratch("oasis_spec_hash");
  const std::pair<const char*, const char*> inputs[] = {
      {"specs/discrete_tracking.oasis", "discrete_tracking"},
      {"tests/data/formats/coin.aut", "coin"}};
  for (const auto& [input, name] : inputs) {
    const std::string path = std::string(OASIS_SOURCE_DIR) + "/" + input;
    const auto out = scratch.path() / name;
    const auto compiled =
        test::run_oasisc("compile " + path + " -o " + out.string() + " --format bin");
    ASSERT_EQ(compiled.status, 0) << compiled.output;
    const rt::LoadedCatalog catalog =
        rt::LoadedCatalog::from_file((out / (std::string(name) + ".bin")).string());
    ASSERT_TRUE(catalog.ok()) << catalog.error();
    std::ifstream in(path, std::ios::binary);
    const std::string text{std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
    EXPECT_EQ(catalog.view().spec_hash, rt::spec_hash(text)) << input;
  }
}

}  // namespace
}  // namespace oasis
