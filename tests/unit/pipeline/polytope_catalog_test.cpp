// The polytope path through the whole compile: a spec the grid refuses (a triangular reward,
// a drift that mixes the axes) becomes a catalog with a BSP; the binary file round-trips it,
// the runtime's locator agrees with the compiler's exact location, the JSON cells contain
// their points, and `verify` passes an untouched catalog and catches each changed item.

#include <filesystem>
#include <fstream>
#include <functional>
#include <random>
#include <string>
#include <utility>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "../../support/run_oasisc.hpp"
#include "../../support/scratch_directory.hpp"
#include "../../support/spec_models.hpp"
#include "codegen/binary_catalog.hpp"
#include "codegen/continuous_json.hpp"
#include "geom/polytope_partition.hpp"
#include "geom/relevance.hpp"
#include "oasis/rt/attention_filter.hpp"
#include "oasis/rt/catalog_file.hpp"
#include "pipeline/continuous_catalog.hpp"
#include "pipeline/continuous_catalog_data.hpp"
#include "verify/continuous_check.hpp"

namespace oasis {
namespace {

const model::ModelIR& triangle_ir() {
  static const model::ModelIR ir =
      test::load_spec_ir(std::string(OASIS_SOURCE_DIR) + "/tests/data/triangle_reward.oasis");
  return ir;
}

const pipeline::ContinuousCatalog& triangle_catalog() {
  static const pipeline::ContinuousCatalog catalog = [] {
    pipeline::ContinuousCatalogOptions options;
    options.abstraction.target.epsilon = 0.3;
    std::string error;
    auto built = pipeline::build_continuous_catalog(triangle_ir(), 11, options, error);
    EXPECT_TRUE(built) << error;
    return std::move(*built);
  }();
  return catalog;
}

// The exact BSP of a context, made again by the geometry layer with the options the pipeline
// used: the catalog holds only its rounded arrays and cells (pipeline/cell_partition.hpp).
const geom::BspTree& exact_tree(std::size_t context) {
  static const std::vector<geom::BspTree> trees = [] {
    std::vector<geom::BspTree> made;
    for (std::size_t c = 0; c < triangle_ir().contexts.size(); ++c) {
      std::string error;
      const auto geometry = geom::polytope_geometry(
          triangle_ir(), c, geom::analyse_relevance(triangle_ir(), c), error);
      EXPECT_TRUE(geometry) << error;
      geom::PolytopePartitionOptions target;
      target.epsilon = Rational(0.3);
      target.max_cells = pipeline::kDefaultPolytopeCells;
      auto partition = geom::partition_polytopes(*geometry, target, error);
      EXPECT_TRUE(partition) << error;
      made.push_back(std::move(partition->tree));
    }
    return made;
  }();
  const geom::BspTree& tree = trees.at(context);
  EXPECT_EQ(tree.num_cells(), triangle_catalog().abstractions[context].num_cells());
  return tree;
}

std::string first_failure(const model::CatalogData& catalog) {
  const std::string bytes = codegen::binary_catalog(catalog);
  const rt::LoadedCatalog loaded = rt::LoadedCatalog::from_bytes(bytes.data(), bytes.size());
  if (!loaded.ok()) return "the changed catalog no longer loads: " + loaded.error();
  for (const verify::CatalogCheck& check :
       verify::check_continuous_catalog(triangle_ir(), loaded.view()))
    if (!check.ok) return check.item + ": " + check.verdict;
  return "";
}

TEST(PolytopeCatalog, TheGridRefusesTheSpecAndThePolytopePathTakesIt) {
  const pipeline::ContinuousCatalog& catalog = triangle_catalog();
  ASSERT_EQ(catalog.abstractions.size(), 2U);
  for (const pipeline::ContinuousAbstraction& abstraction : catalog.abstractions) {
    ASSERT_TRUE(abstraction.cells.bsp);
    EXPECT_TRUE(abstraction.met);
    EXPECT_LE(abstraction.epsilon, Rational(3, 10));
    for (const std::vector<double>& axis : abstraction.cells.breaks)
      EXPECT_EQ(axis.size(), 2U);  // the grid is the domain box, one cell
    EXPECT_GT(abstraction.num_cells(), 10U);
    EXPECT_EQ(abstraction.cell_block.size(), abstraction.num_cells());
  }
}

TEST(PolytopeCatalog, LoadedLocatorAgreesWithExactLocation) {
  const pipeline::ContinuousCatalog& catalog = triangle_catalog();
  const model::CatalogData data = pipeline::continuous_catalog_data(catalog, false);
  const std::string bytes = codegen::binary_catalog(data);
  const rt::LoadedCatalog loaded = rt::LoadedCatalog::from_bytes(bytes.data(), bytes.size());
  ASSERT_TRUE(loaded.ok()) << loaded.error();
  std::mt19937_64 random(3);
  std::uniform_real_distribution<double> coordinate(-0.2, 2.2);
  for (std::uint32_t i = 0; i < 2; ++i) {
    const rt::AbstractionView& abs = loaded.view().abstractions[i];
    const geom::BspTree& tree = exact_tree(i);
    for (int k = 0; k < 20000; ++k) {
      const double x[2] = {coordinate(random), coordinate(random)};
      const auto exact = tree.locate({Rational(x[0]), Rational(x[1])});
      const std::uint32_t located = rt::locate_partition_cell(abs.grid, abs.bsp, x, 2);
      ASSERT_EQ(located, exact ? static_cast<std::uint32_t>(*exact) : rt::kOutsideCell)
          << "at (" << x[0] << ", " << x[1] << ")";
    }
  }
  // The filter runs on it, block by block as located.
  std::vector<double> workspace(rt::AttentionFilter::workspace_size(loaded.view(), {}));
  rt::AttentionFilter filter(loaded.view(), {}, workspace.data(), workspace.size());
  ASSERT_TRUE(filter.ok());
  const double start[2] = {0.5, 0.3};
  EXPECT_EQ(filter.start(start, 2), rt::StepStatus::kOk);
  EXPECT_NE(filter.action(), rt::kNoAction);
}

TEST(PolytopeCatalog, JsonCellsHoldTheirRepresentativePoints) {
  const pipeline::ContinuousCatalog& catalog = triangle_catalog();
  const nlohmann::json json =
      nlohmann::json::parse(codegen::continuous_catalog_json(catalog, false));
  const auto& abstraction = json["abstractions"][0];
  const geom::BspTree& tree = exact_tree(0);
  ASSERT_EQ(abstraction["cells"].size(), tree.num_cells());
  for (std::size_t c = 0; c < tree.num_cells(); ++c) {
    const auto& cell = abstraction["cells"][c];
    const geom::Point& point = tree.cells()[c].representative;
    for (std::size_t r = 0; r < cell["A"].size(); ++r) {
      const double lhs = cell["A"][r][0].get<double>() * to_double(point[0]) +
                         cell["A"][r][1].get<double>() * to_double(point[1]);
      EXPECT_LE(lhs, cell["b"][r].get<double>() + 1e-12) << "cell " << c << " row " << r;
    }
    EXPECT_EQ(cell["block"].get<std::uint32_t>(), catalog.abstractions[0].cell_block[c]);
  }
}

TEST(PolytopeCatalog, VerifyPassesTheCatalogAndCatchesEveryChange) {
  const model::CatalogData sound = pipeline::continuous_catalog_data(triangle_catalog(), true);
  EXPECT_EQ(first_failure(sound), "");
  struct Change {
    const char* name;
    std::function<void(model::CatalogData&)> apply;
    const char* expected;
  };
  const std::vector<Change> changes = {
      {"a rewarded cell in an unrewarded block",
       [](auto& c) {
         auto& a = c.abstractions[0];
         std::size_t rewarded = 0;
         while (a.block_reward[a.cell_block[rewarded]] == 0)
           ++rewarded;
         std::size_t plain = 0;
         while (a.block_reward[a.cell_block[plain]] != 0)
           ++plain;
         std::swap(a.cell_block[rewarded], a.cell_block[plain]);
       },
       "reward"},
      {"a splitting hyperplane moved", [](auto& c) { c.abstractions[0].bsp_bound[0] += 0.05; },
       "reward"},
      {"a row's probabilities",
       [](auto& c) {
         auto& abstraction = c.abstractions[1];
         auto& q = abstraction.quotient;
         for (auto e = q.choice_begin[0]; e < q.choice_begin[1]; ++e)
           q.target[e] = (q.target[e] + abstraction.num_blocks / 2) % abstraction.num_blocks;
       },
       "total variation"},
      {"an understated epsilon", [](auto& c) { c.abstractions[1].epsilon /= 10; },
       "more than epsilon"},
      {"the policy", [](auto& c) { c.abstractions[0].policy[3] = 1 - c.abstractions[0].policy[3]; },
       "not optimal"},
  };
  for (const Change& change : changes) {
    model::CatalogData bad = sound;
    change.apply(bad);
    const std::string failure = first_failure(bad);
    EXPECT_NE(failure, "") << change.name << " was not caught";
    EXPECT_NE(failure.find(change.expected), std::string::npos) << change.name << ": " << failure;
  }
}

// `verify SPEC NAME.json` reads the JSON back (BSP included) and checks it like the binary
// file: the untouched JSON passes, one with a changed value is refused.
TEST(PolytopeCatalog, VerifyChecksTheJsonToo) {
  const test::ScratchDirectory scratch("oasis_polytope_json");
  const std::string spec = std::string(OASIS_SOURCE_DIR) + "/tests/data/triangle_reward.oasis";
  const auto out = scratch.path() / "triangle";
  const auto compiled = test::run_oasisc("compile " + spec + " -o " + out.string() +
                                         " --format json --with-transitions");
  ASSERT_EQ(compiled.status, 0) << compiled.output;
  const std::string json_path = (out / "triangle.json").string();
  const auto verified = test::run_oasisc("verify " + spec + " " + json_path);
  EXPECT_EQ(verified.status, 0) << verified.output;
  EXPECT_NE(verified.output.find("polytope cells"), std::string::npos) << verified.output;

  nlohmann::json document = nlohmann::json::parse(test::read_text_file(json_path));
  document["abstractions"][1]["blocks"][2]["value"] = 1000.0;
  const std::string changed = (scratch.path() / "changed.json").string();
  std::ofstream(changed) << document.dump();
  const auto refused = test::run_oasisc("verify " + spec + " " + changed);
  EXPECT_EQ(refused.status, 1) << refused.output;
  EXPECT_NE(refused.output.find("value[2]"), std::string::npos) << refused.output;
}

// What neither path takes (a slanted reward with a Gaussian disturbance) is refused with
// both reasons, the context named once, and no output.
TEST(PolytopeCatalog, WhatNeitherPathTakesIsRefusedWithBothReasons) {
  const test::ScratchDirectory scratch("oasis_polytope_refused");
  std::string spec =
      test::read_text_file(std::string(OASIS_SOURCE_DIR) + "/tests/data/triangle_reward.oasis");
  const std::string uniform = "disturbance y in [-0.5 .. 0.5];";
  spec.replace(spec.find(uniform), uniform.size(), "disturbance y ~ gaussian(0, 0.2);");
  const auto path = scratch.path() / "gaussian_triangle.oasis";
  std::ofstream(path) << spec;
  const auto out = scratch.path() / "out";
  const auto result = test::run_oasisc("compile " + path.string() + " -o " + out.string());
  EXPECT_EQ(result.status, 1) << result.output;
  EXPECT_NE(result.output.find("which the grid cannot follow"), std::string::npos) << result.output;
  EXPECT_NE(result.output.find("the polytope path handles uniform boxes only"), std::string::npos)
      << result.output;
  const std::string named = "context 'at_goal'";
  const auto first = result.output.find(named);
  ASSERT_NE(first, std::string::npos) << result.output;
  EXPECT_EQ(result.output.find(named, first + 1), std::string::npos) << result.output;
  EXPECT_FALSE(std::filesystem::exists(out / "triangle.bin"));
}

}  // namespace
}  // namespace oasis
