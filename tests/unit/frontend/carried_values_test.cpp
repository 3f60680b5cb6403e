// Numbers that are exact in a spec or model file but that a catalog's doubles cannot carry:
// `check` refuses them at their file:line:col (or warns, when they are only lossy), and
// `compile` agrees: it refuses the same files and writes nothing, and what it accepts loads.

#include <filesystem>
#include <fstream>
#include <string>

#include <gtest/gtest.h>

#include "../../support/run_oasisc.hpp"
#include "../../support/scratch_directory.hpp"
#include "oasis/rt/catalog_file.hpp"

namespace {

namespace fs = std::filesystem;
using oasis::test::run_oasisc;

std::string shipped_discrete_spec() {
  std::ifstream in(std::string(OASIS_SOURCE_DIR) + "/specs/discrete_tracking.oasis");
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

// The shipped discrete spec with one piece of text replaced.
std::string discrete_with(const std::string& from, const std::string& to) {
  std::string text = shipped_discrete_spec();
  const std::size_t at = text.find(from);
  EXPECT_NE(at, std::string::npos) << from;
  if (at != std::string::npos) text.replace(at, from.size(), to);
  return text;
}

// Where `needle` starts in `text`, plus `skip` characters, as "line:column" (1-based), for
// expected diagnostics.
std::string position_of(const std::string& text, const std::string& needle, std::size_t skip = 0) {
  const std::size_t at = text.find(needle) + skip;
  EXPECT_NE(at, std::string::npos) << needle;
  std::size_t line = 1;
  std::size_t line_start = 0;
  for (std::size_t i = 0; i < at; ++i) {
    if (text[i] == '\n') {
      ++line;
      line_start = i + 1;
    }
  }
  return std::to_string(line) + ":" + std::to_string(at - line_start + 1);
}

std::string zeros(std::size_t count) {
  return std::string(count, '0');
}

class CarriedValues : public ::testing::Test {
 protected:
  fs::path write(const std::string& name, const std::string& text) {
    const fs::path path = scratch_.path() / name;
    std::ofstream(path, std::ios::binary) << text;
    return path;
  }

  // `check` reports `message` as an error at `position` and exits 1; `compile` exits 1 too
  // and leaves no catalog behind.
  void expect_refused(const std::string& name, const std::string& text, const std::string& where,
                      const std::string& message) {
    const fs::path file = write(name, text);
    const auto checked = run_oasisc("check " + file.string());
    EXPECT_EQ(checked.status, 1) << checked.output;
    const std::string located = file.string() + ":" + where + ": error: ";
    EXPECT_NE(checked.output.find(located), std::string::npos)
        << "expected an error at " << where << ":\n"
        << checked.output;
    EXPECT_NE(checked.output.find(message), std::string::npos) << checked.output;
    const fs::path out = scratch_.path() / (name + ".out");
    const auto compiled = run_oasisc("compile " + file.string() + " -o " + out.string() +
                                     " --format bin,json,dot,cpp");
    EXPECT_EQ(compiled.status, 1) << compiled.output;
    EXPECT_TRUE(!fs::exists(out) || fs::is_empty(out)) << "compile wrote into " << out;
  }

  oasis::test::ScratchDirectory scratch_{"oasis_carried"};
};

TEST_F(CarriedValues, HugeRewardIsRefusedAtIt) {
  const std::string big = "1" + zeros(1000);
  const std::string text = discrete_with("reward s3 : 1;", "reward s3 : " + big + ";");
  expect_refused("huge_reward.oasis", text, position_of(text, big), "is beyond the largest double");
}

TEST_F(CarriedValues, ProbabilityThatRoundsToZeroIsRefusedAtIt) {
  const std::string tiny = "0." + zeros(999) + "1";
  const std::string text =
      discrete_with("s1, L -> s1;", "s1, L -> " + tiny + ": s2 + (1 - " + tiny + "): s1;");
  expect_refused("tiny_probability.oasis", text, position_of(text, tiny),
                 "below the smallest positive double");
}

TEST_F(CarriedValues, DiscountThatRoundsToZeroIsRefusedAtIt) {
  const std::string text = discrete_with("discount 0.9;", "discount 1e-400;");
  expect_refused("tiny_discount.oasis", text, position_of(text, "1e-400"),
                 "below the smallest positive double");
}

TEST_F(CarriedValues, DiscountThatRoundsToOneIsRefusedAtIt) {
  const std::string nines = "0." + std::string(100000, '9');
  const std::string text = discrete_with("discount 0.9;", "discount " + nines + ";");
  expect_refused("discount_near_one.oasis", text, position_of(text, nines),
                 "rounds to 1 in double precision");
}

TEST_F(CarriedValues, DiscountOneWithoutHorizonIsRefusedAtIt) {
  const std::string text = discrete_with("discount 0.9;", "discount 1;");
  expect_refused("discount_one.oasis", text, position_of(text, "discount 1;", 9),
                 "discount 1 over an infinite horizon");
}

TEST_F(CarriedValues, DiscountTooCloseToOneForValueIterationIsRefusedAtIt) {
  const std::string text = discrete_with("discount 0.9;", "discount 0.999999999;");
  expect_refused("slow_discount.oasis", text, position_of(text, "0.999999999"),
                 "more than its limit of 1000000");
}

TEST_F(CarriedValues, ValuesBeyondDoublesAreRefusedAtTheDiscount) {
  std::string text = shipped_discrete_spec();
  text.replace(text.find("reward s3 : 1;"), 14, "reward s3 : 1e308;");
  text.replace(text.find("discount 0.9;"), 13, "discount 0.99;");
  expect_refused("huge_values.oasis", text, position_of(text, "0.99;"), "give values up to");
}

TEST_F(CarriedValues, SwitchingProbabilityThatRoundsToZeroIsRefusedAtIt) {
  const std::string text = discrete_with("switching stay 0.8;", "switching stay 1 - 1e-400;");
  expect_refused("tiny_switch.oasis", text, position_of(text, "1 - 1e-400"),
                 "below the smallest positive double");
}

TEST_F(CarriedValues, StateDependentRewardIsRefusedWhereItIsWritten) {
  const std::string text =
      "mdp counter {\n"
      "  var x : [0 .. 3] init 0;\n"
      "  actions up;\n"
      "  [up] x < 3 -> (x' = x + 1);\n"
      "  [up] x == 3 -> true;\n"
      "  reward true : x * 1e200 * 1e200;\n"
      "}\n";
  expect_refused("state_reward.oasis", text, position_of(text, "x * 1e200"),
                 "is beyond the largest double");
}

TEST_F(CarriedValues, ImportedProbabilityThatRoundsToZeroIsRefusedAtIt) {
  const std::string fraction = "1/1" + zeros(1000);
  const std::string text = "des (0,2,2)\n(0,\"a\",1 " + fraction + " 0)\n(1,\"a\",0)\n";
  expect_refused("tiny.aut", text, position_of(text, fraction), "below the smallest positive");
}

TEST_F(CarriedValues, ImportedHugeRewardIsRefusedAtItsLabel) {
  const std::string text = "des (0,2,2)\n(0,\"a|reward(1" + zeros(400) + ")\",1)\n(1,\"a\",0)\n";
  expect_refused("huge.aut", text, position_of(text, "\"a|reward"), "beyond the largest double");
}

TEST_F(CarriedValues, ImportedPrismProbabilityThatRoundsToZeroIsRefusedAtIt) {
  const std::string text = "2 2 3\n0 0 1 1e-1000\n0 0 0 1\n1 0 1 1\n";
  // The first choice sums to 1 + 1e-1000 exactly; the range error comes first either way.
  const fs::path file = write("tiny.tra", text);
  const auto checked = run_oasisc("check " + file.string());
  EXPECT_EQ(checked.status, 1) << checked.output;
  EXPECT_NE(checked.output.find(file.string() + ":" + position_of(text, "1e-1000") + ": error: "),
            std::string::npos)
      << checked.output;
}

TEST_F(CarriedValues, SubnormalRewardIsAWarningAndItsCatalogLoads) {
  const std::string text = discrete_with("reward s3 : 1;", "reward s3 : 1e-310;");
  const fs::path file = write("subnormal.oasis", text);
  const auto checked = run_oasisc("check " + file.string());
  EXPECT_EQ(checked.status, 0) << checked.output;
  const std::string warning = file.string() + ":" + position_of(text, "1e-310") + ": warning: ";
  EXPECT_NE(checked.output.find(warning), std::string::npos) << checked.output;
  EXPECT_NE(checked.output.find("relative error of"), std::string::npos) << checked.output;
  // Once, not again for every state the exploration meets.
  EXPECT_EQ(checked.output.find(warning), checked.output.rfind(warning)) << checked.output;

  const fs::path out = scratch_.path() / "subnormal_out";
  const auto compiled = run_oasisc("compile " + file.string() + " -o " + out.string());
  ASSERT_EQ(compiled.status, 0) << compiled.output;
  const auto catalog =
      oasis::rt::LoadedCatalog::from_file((out / "discrete_tracking.bin").string());
  ASSERT_TRUE(catalog.ok()) << catalog.error();
  EXPECT_EQ(catalog.view().abstractions[0].block_reward[1], 1e-310);
}

TEST_F(CarriedValues, HugeButFiniteRewardsCompileToALoadableCatalog) {
  const std::string text = discrete_with("reward s3 : 1;", "reward s3 : 1e300;");
  const fs::path file = write("big.oasis", text);
  const fs::path out = scratch_.path() / "big_out";
  const auto compiled = run_oasisc("compile " + file.string() + " -o " + out.string());
  ASSERT_EQ(compiled.status, 0) << compiled.output;
  const auto catalog =
      oasis::rt::LoadedCatalog::from_file((out / "discrete_tracking.bin").string());
  ASSERT_TRUE(catalog.ok()) << catalog.error();
  const auto verified =
      run_oasisc("verify " + file.string() + " " + (out / "discrete_tracking.bin").string());
  EXPECT_EQ(verified.status, 0) << verified.output;
}

}  // namespace
