// A spec's stated properties end to end (docs/spec-language.md, "Properties"): `compile`
// answers each in each context, under the policy and at the optimum, into every carrier;
// `verify` recomputes them and refuses a catalog whose stated value was changed (checksum
// recomputed, so that only the verifier can tell); bad properties get errors placed in the
// spec.

#include <cmath>
#include <cstring>
#include <string>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "../../support/catalog_bytes.hpp"
#include "../../support/run_oasisc.hpp"
#include "../../support/scratch_directory.hpp"
#include "oasis/rt/catalog_file.hpp"

namespace oasis {
namespace {

using test::run_oasisc;

const std::string kCorridor =
    std::string(OASIS_SOURCE_DIR) + "/tests/data/properties/corridor_guarantees.oasis";

class StatedProperties : public ::testing::Test {
 protected:
  test::ScratchDirectory scratch_{"oasis_stated_properties"};

  std::filesystem::path compiled() {
    const auto dir = scratch_.path() / "out";
    const auto result = run_oasisc("compile " + kCorridor + " -o " + dir.string());
    EXPECT_EQ(result.status, 0) << result.output;
    return dir;
  }

  // `command` (check or compile) on a small spec whose catalog ends with `catalog_items`, from
  // line 9 of the file on.
  test::CommandResult spec_with(const std::string& command, const std::string& catalog_items) {
    const auto path = scratch_.path() / "bad.oasis";
    std::ofstream(path) << "mdp m {\n  var x : [0 .. 2];\n  actions a;\n  [a] x < 2 -> (x' = x + "
                           "1);\n  [a] x == 2 -> true;\n}\ncatalog {\n  context c { reward x == 2 "
                           ": 1; }\n"
                        << catalog_items << "}\n";
    return run_oasisc(command + " " + path.string() + " -o " + (scratch_.path() / "out").string());
  }
};

TEST_F(StatedProperties, CompileStatesThePolicysValueAndTheOptimum) {
  const auto dir = scratch_.path() / "out";
  const auto result = run_oasisc("compile " + kCorridor + " -o " + dir.string());
  ASSERT_EQ(result.status, 0) << result.output;
  // treat_right's policy walks right, so it never reaches x=0; the optimum does surely.
  EXPECT_NE(result.output.find("context treat_right: reach_left = 0 under its policy, 1 at the "
                               "optimum"),
            std::string::npos)
      << result.output;
  // Four steps, each moving left with probability 4/5: 1 - P(fewer than 2 moves in 4).
  EXPECT_NE(result.output.find("context treat_left: left_soon = 608/625 under its policy"),
            std::string::npos)
      << result.output;
  const rt::LoadedCatalog catalog = rt::LoadedCatalog::from_file((dir / "corridor.bin").string());
  ASSERT_TRUE(catalog.ok()) << catalog.error();
  const rt::CatalogView& view = catalog.view();
  ASSERT_EQ(view.properties.count, 5u);
  EXPECT_STREQ(view.properties.names[0], "reach_left");
  EXPECT_STREQ(view.properties.texts[0], "Pmax=? [F x=0]");
  const double* right = view.abstractions[1].guarantee;
  EXPECT_EQ(right[rt::kPolicyLower], 0.0);
  EXPECT_EQ(right[rt::kPolicyUpper], 0.0);
  EXPECT_EQ(right[rt::kOptimumLower], 1.0);
  // 608/625 is no double: the two doubles around it.
  const double* left_soon = view.abstractions[0].guarantee + rt::kGuaranteeFields;
  EXPECT_LE(left_soon[rt::kPolicyLower], 608.0 / 625);
  EXPECT_GE(left_soon[rt::kPolicyUpper], 608.0 / 625);
  EXPECT_LT(left_soon[rt::kPolicyLower], left_soon[rt::kPolicyUpper]);
  EXPECT_LT(left_soon[rt::kPolicyUpper] - left_soon[rt::kPolicyLower], 1e-15);
  // An infinite expected reward is stated as such, and the loader's validation takes it.
  const double* never = view.abstractions[0].guarantee + 3 * rt::kGuaranteeFields;
  EXPECT_EQ(never[rt::kPolicyLower], HUGE_VAL);
  EXPECT_EQ(never[rt::kOptimumUpper], HUGE_VAL);
  const nlohmann::json json = nlohmann::json::parse(test::read_bytes(dir / "corridor.json"));
  EXPECT_EQ(json.at("abstractions").at(0).at("guarantees").at(1).at("policy").at("exact"),
            "608/625");
  EXPECT_EQ(json.at("abstractions").at(0).at("guarantees").at(3).at("optimum").at("upper"),
            "infinity");
}

TEST_F(StatedProperties, VerifyRecomputesThemAndRefusesAChangedValue) {
  const auto dir = compiled();
  const auto catalog = dir / "corridor.bin";
  auto result = run_oasisc("verify " + kCorridor + " " + catalog.string());
  EXPECT_EQ(result.status, 0) << result.output;
  EXPECT_NE(result.output.find("properties: the spec's 5, by name and text"), std::string::npos)
      << result.output;
  EXPECT_NE(result.output.find("property 'reach_left' in context 'treat_right': policy 0, "
                               "optimum 1, recomputed on the model's own states"),
            std::string::npos)
      << result.output;

  // treat_right's policy claimed to reach x=0 surely: a well-formed, resealed file.
  std::string bytes = test::read_bytes(catalog);
  const std::uint64_t offset = test::section_offset(bytes, rt::Section::kGuarantee, 1);
  ASSERT_NE(offset, 0u);
  const double claimed[2] = {1.0, 1.0};
  std::memcpy(bytes.data() + offset + rt::kPolicyLower * sizeof(double), claimed, sizeof claimed);
  test::fix_checksum(bytes);
  test::write_bytes(dir / "claimed.bin", bytes);
  result = run_oasisc("verify " + kCorridor + " " + (dir / "claimed.bin").string());
  EXPECT_EQ(result.status, 1) << result.output;
  EXPECT_NE(result.output.find("property 'reach_left' in context 'treat_right': under the policy "
                               "it states 1, but the value is 0"),
            std::string::npos)
      << result.output;

  // A stated interval widened to hide a value is refused too.
  bytes = test::read_bytes(catalog);
  const double widened[2] = {0.0, 1.0};
  std::memcpy(bytes.data() + offset + rt::kOptimumLower * sizeof(double), widened, sizeof widened);
  test::fix_checksum(bytes);
  test::write_bytes(dir / "widened.bin", bytes);
  result = run_oasisc("verify " + kCorridor + " " + (dir / "widened.bin").string());
  EXPECT_EQ(result.status, 1) << result.output;
  EXPECT_NE(result.output.find("wider than 1e-6"), std::string::npos) << result.output;
}

TEST_F(StatedProperties, InfoListsThem) {
  const auto result = run_oasisc("info " + kCorridor);
  EXPECT_EQ(result.status, 0) << result.output;
  EXPECT_NE(result.output.find("  property left_soon = Pmax=? [F<=4 x=0]\n"), std::string::npos)
      << result.output;
  const auto json = run_oasisc("info --json " + kCorridor);
  EXPECT_EQ(nlohmann::json::parse(json.output).at("properties").at(2).at("name"), "treats")
      << json.output;
}

TEST_F(StatedProperties, AGeneratedHeaderNamesThem) {
  const auto dir = scratch_.path() / "cpp";
  const auto result = run_oasisc("compile " + kCorridor + " --format cpp -o " + dir.string());
  ASSERT_EQ(result.status, 0) << result.output;
  const std::string header = test::read_bytes(dir / "corridor_catalog.hpp");
  EXPECT_NE(header.find("inline constexpr std::uint32_t kNumProperties = 5;"), std::string::npos)
      << header;
  EXPECT_NE(header.find("inline constexpr std::uint32_t reach_left = 0;  // Pmax=? [F x=0]"),
            std::string::npos)
      << header;
  EXPECT_NE(header.find("kGuarantees[kNumAbstractions][kNumProperties]"), std::string::npos);
}

TEST_F(StatedProperties, BadPropertiesAreErrorsPlacedInTheSpec) {
  struct Case {
    std::string items;
    std::string message;
  };
  // `check` reads each property; `compile` also answers it, and finds what only the model can
  // tell (a label it does not have).
  const Case cases[] = {
      {"  property p = Pmax=? [F \"goal\"];\n",
       "bad.oasis:9:26: error: unknown label \"goal\" (the model has no labels; its variables say "
       "which states, as in x=0)"},
      {"  property p = Pmax=? [F x=];\n", "bad.oasis:9:28: error: expected an expression"},
      {"  property p = Pmax=? [F x=2];\n  property p = Pmin=? [F x=2];\n",
       "bad.oasis:10:12: error: duplicate property 'p'"},
      {"  property p = Pmax=? [F x=2]\n", "error: expected ';' after the property"},
      {"  property p = ;\n", "error: expected a PRISM property such as"},
      {"  property p = Pmax=? [F x=1] Pmin=? [F x=2];\n",
       "bad.oasis:9:16: error: a catalog property is one property"},
  };
  for (const Case& c : cases) {
    const auto result = spec_with("compile", c.items);
    EXPECT_EQ(result.status, 1) << c.items << result.output;
    EXPECT_NE(result.output.find(c.message), std::string::npos) << c.items << result.output;
  }
}

TEST_F(StatedProperties, ABoundIsNotAValueToState) {
  const auto path = scratch_.path() / "bound.oasis";
  std::ofstream(path) << "mdp m {\n  var x : [0 .. 2];\n  actions a;\n  [a] x < 2 -> (x' = x + 1);"
                         "\n  [a] x == 2 -> true;\n}\ncatalog {\n  context c { reward x == 2 : 1; "
                         "}\n  property p = P>=0.5 [F x=2];\n}\n";
  const auto result =
      run_oasisc("compile " + path.string() + " -o " + (scratch_.path() / "out").string());
  EXPECT_EQ(result.status, 1) << result.output;
  EXPECT_NE(result.output.find("bound.oasis:9:16: error: a catalog states a number for each "
                               "property"),
            std::string::npos)
      << result.output;
}

TEST_F(StatedProperties, AContinuousSpecCannotStateOne) {
  const auto path = scratch_.path() / "continuous.oasis";
  std::ofstream(path) << "mdp m {\n  continuous x : [0 .. 1];\n  actions a;\n  dynamics [a] { }\n"
                         "  region r = x <= 0.5;\n  reward r : 1;\n}\ncatalog {\n  context c = "
                         "base;\n  property p = Pmax=? [F x=0];\n}\n";
  const auto result = run_oasisc("check " + path.string());
  EXPECT_EQ(result.status, 1) << result.output;
  EXPECT_NE(result.output.find("continuous.oasis:10:12: error: properties are stated for discrete "
                               "models"),
            std::string::npos)
      << result.output;
}

}  // namespace
}  // namespace oasis
