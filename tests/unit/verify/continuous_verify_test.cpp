// `oasisc verify` on continuous catalogs: an untouched Go1 catalog passes; a wrong cell, a
// wrong probability, an understated epsilon, a wrong reward, policy or grid is caught, in a
// file that is otherwise sound (it loads).

#include <functional>
#include <string>
#include <utility>
#include <vector>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "../../support/run_oasisc.hpp"
#include "../../support/scratch_directory.hpp"
#include "../../support/spec_models.hpp"
#include "codegen/binary_catalog.hpp"
#include "oasis/rt/catalog_file.hpp"
#include "oasis/rt/catalog_validation.hpp"
#include "pipeline/continuous_catalog.hpp"
#include "pipeline/continuous_catalog_data.hpp"
#include "verify/continuous_check.hpp"
#include "verify/continuous_json_reader.hpp"

namespace oasis {
namespace {

const model::ModelIR& go1_ir() {
  static const model::ModelIR ir = test::shipped_go1_spec();
  return ir;
}

// The Go1 catalog at a coarse epsilon with its transition rows, built once.
const model::CatalogData& go1_catalog() {
  static const model::CatalogData data = [] {
    pipeline::ContinuousCatalogOptions options;
    options.abstraction.target.epsilon = 0.3;
    std::string error;
    const auto catalog = pipeline::build_continuous_catalog(go1_ir(), 3, options, error);
    EXPECT_TRUE(catalog) << error;
    return pipeline::continuous_catalog_data(*catalog, true);
  }();
  return data;
}

std::string first_failure(model::CatalogData& catalog) {
  const std::string bytes = codegen::binary_catalog(catalog);
  const rt::LoadedCatalog loaded = rt::LoadedCatalog::from_bytes(bytes.data(), bytes.size());
  if (!loaded.ok()) return "the changed catalog no longer loads: " + loaded.error();
  for (const verify::CatalogCheck& check :
       verify::check_continuous_catalog(go1_ir(), loaded.view()))
    if (!check.ok) return check.item + ": " + check.verdict;
  return "";
}

TEST(ContinuousVerify, AnUntouchedCatalogPasses) {
  model::CatalogData catalog = go1_catalog();
  EXPECT_EQ(first_failure(catalog), "");
}

TEST(ContinuousVerify, EveryChangedItemIsCaught) {
  struct Change {
    const char* name;
    std::function<void(model::CatalogData&)> apply;
    const char* expected;
  };
  const std::vector<Change> changes = {
      {"a cell in another block",
       [](auto& c) {  // two far-apart cells swap blocks: every block still holds a cell
         auto& cells = c.abstractions[0].cell_block;
         std::swap(cells[0], cells[cells.size() / 2]);
       },
       "cell 0"},
      {"a row's probabilities",
       [](auto& c) {  // the first row's mass sent to blocks half the grid away
         auto& abstraction = c.abstractions[0];
         auto& q = abstraction.quotient;
         for (auto e = q.choice_begin[0]; e < q.choice_begin[1]; ++e)
           q.target[e] = (q.target[e] + abstraction.num_blocks / 2) % abstraction.num_blocks;
       },
       "total variation"},
      {"an understated epsilon", [](auto& c) { c.abstractions[1].epsilon = 0.01; },
       "more than epsilon"},
      {"a block reward",
       [](auto& c) {
         auto& r = c.abstractions[0].block_reward;
         r[c.abstractions[0].cell_block[0]] = 1.0;
       },
       "has reward"},
      {"the policy",
       [](auto& c) { c.abstractions[1].policy[5] = (c.abstractions[1].policy[5] + 3) % 6; },
       "not optimal"},
      {"a value", [](auto& c) { c.abstractions[1].value[7] += 0.5; }, "value[7]"},
      {"a grid breakpoint",
       [](auto& c) { c.abstractions[0].grid_breaks[0] = -0.5; },  // x1's domain starts at 0
       "domain"},
      {"the grid's variables",
       [](auto& c) {
         c.abstractions[1].grid_axes = {0, 1};
       },
       "attends to"},
      {"the switching model",
       [](auto& c) {
         c.switching[0] = 0.7;
         c.switching[1] = 0.3;
       },
       "switching"},
  };
  for (const Change& change : changes) {
    model::CatalogData bad = go1_catalog();
    change.apply(bad);
    const std::string failure = first_failure(bad);
    EXPECT_NE(failure, "") << change.name << " was not caught";
    EXPECT_NE(failure.find(change.expected), std::string::npos) << change.name << ": " << failure;
  }
}

TEST(ContinuousVerify, TheCommandLineVerifiesACompiledCatalog) {
  const test::ScratchDirectory scratch("oasis_continuous_verify");
  const std::string spec = std::string(OASIS_SOURCE_DIR) + "/specs/go1_treat.oasis";
  const auto out = scratch.path() / "go1";
  const auto compiled = test::run_oasisc("compile " + spec + " -o " + out.string() +
                                         " --format bin --epsilon 0.3 --with-transitions");
  ASSERT_EQ(compiled.status, 0) << compiled.output;
  const auto verified = test::run_oasisc("verify " + spec + " " + (out / "go1_treat.bin").string());
  EXPECT_EQ(verified.status, 0) << verified.output;
  EXPECT_NE(verified.output.find("rows within epsilon"), std::string::npos) << verified.output;
}

// Without a disturbance a corner's image is one point, which may sit on the face of another
// cell while the rest of the cell's image lies elsewhere: verify once failed such a catalog
// ("differs from the catalog's row by 1") by checking rows at the corners themselves.
TEST(ContinuousVerify, DynamicsWithoutADisturbanceVerify) {
  const test::ScratchDirectory scratch("oasis_continuous_verify");
  const std::string spec = std::string(OASIS_SOURCE_DIR) + "/tests/data/deterministic_line.oasis";
  const auto out = scratch.path() / "line";
  const auto compiled = test::run_oasisc("compile " + spec + " -o " + out.string() +
                                         " --format bin --with-transitions");
  ASSERT_EQ(compiled.status, 0) << compiled.output;
  const auto verified =
      test::run_oasisc("verify " + spec + " " + (out / "deterministic_line.bin").string());
  EXPECT_EQ(verified.status, 0) << verified.output;
  EXPECT_NE(verified.output.find("rows within epsilon"), std::string::npos) << verified.output;
}

// The JSON reader (`oasisc verify SPEC NAME.json`) refuses arrays whose lengths disagree, as the
// binary loader does (the runtime's view trusts them), and indices that are not integers of 32
// bits. Found by the continuous_json fuzz target: a grid of 3 cells listing 2 made
// rt::validate read past cell_block, and "format": 4e90 was converted with undefined behaviour.
TEST(ContinuousVerify, JsonThatWouldMisleadTheRuntimeIsRefused) {
  const nlohmann::json good = nlohmann::json::parse(test::read_text_file(
      std::string(OASIS_SOURCE_DIR) +
      "/tests/fuzz/corpus/continuous_json/deterministic_line_transitions.json"));
  std::string error;
  auto catalog = verify::parse_continuous_catalog_json(good.dump(), error);
  ASSERT_TRUE(catalog) << error;
  EXPECT_TRUE(rt::validate(catalog->view(), &error)) << error;

  const std::vector<std::pair<std::function<void(nlohmann::json&)>, std::string>> cases{
      {[](nlohmann::json& j) { j["abstractions"][0]["cells"].erase(0); },
       "abstraction 'to_dock' lists 2 cells for a grid of 3"},
      {[](nlohmann::json& j) { j["abstractions"][1]["grid"].clear(); },
       "the grid lists 0 axes for 1 relevant variables"},
      {[](nlohmann::json& j) { j["prior"].erase(1); },
       "switching and prior must be 2 x 2 and 2 numbers for the 2 abstractions"},
      {[](nlohmann::json& j) { j["switching"][1].erase(0); }, "switching and prior must be 2 x 2"},
      {[](nlohmann::json& j) { j["abstractions"][0]["num_blocks"] = 1.5; },
       "num_blocks must be an integer in 0..4294967295, not 1.5"},
      {[](nlohmann::json& j) { j["abstractions"][0]["cells"][0]["block"] = 4294967296U; },
       "a cell's block must be an integer in 0..4294967295, not 4294967296"}};
  for (const auto& [edit, message] : cases) {
    nlohmann::json bad = good;
    edit(bad);
    error.clear();
    EXPECT_FALSE(verify::parse_continuous_catalog_json(bad.dump(), error)) << message;
    EXPECT_NE(error.find(message), std::string::npos) << error;
  }
}

}  // namespace
}  // namespace oasis
