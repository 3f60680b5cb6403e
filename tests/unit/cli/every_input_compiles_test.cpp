// Every shipped spec (but the objectives of specs/arch/, which tests/arch/ compiles and
// verifies) and every model under tests/data/ compiles into every catalog format (DOT
// for explicit models, SVG for continuous ones), and the catalog loads in the runtime, passes
// `oasisc verify` in full, parses as JSON, and its C++ tables compile against the runtime
// headers. Found on the disk at run time, so a file added to
// specs/ or tests/data/ is covered without an edit here.

#include <algorithm>
#include <cctype>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "../../support/run_oasisc.hpp"
#include "../../support/scratch_directory.hpp"
#include "oasis/rt/catalog_file.hpp"
#include "oasis/rt/catalog_validation.hpp"

namespace {

namespace fs = std::filesystem;
using oasis::test::run_oasisc;

std::vector<std::string> shipped_inputs() {
  std::vector<std::string> inputs;
  const fs::path root(OASIS_SOURCE_DIR);
  for (const fs::path& folder : {root / "specs", root / "tests" / "data"}) {
    for (auto it = fs::recursive_directory_iterator(folder);
         it != fs::recursive_directory_iterator(); ++it) {
      const fs::directory_entry& entry = *it;
      // specs/arch/ holds models with an objective: no catalog, no formats, and full-size
      // compiles that are benchmarks; tests/arch/ compiles and verifies each at a small grid.
      if (entry.is_directory() && entry.path() == root / "specs" / "arch") {
        it.disable_recursion_pending();
        continue;
      }
      const std::string extension = entry.path().extension().string();
      if (extension == ".oasis" || extension == ".aut" || extension == ".tra")
        inputs.push_back(fs::relative(entry.path(), root).string());
    }
  }
  std::sort(inputs.begin(), inputs.end());
  return inputs;
}

// Test names may hold only letters, digits and underscores.
std::string test_name(const ::testing::TestParamInfo<std::string>& info) {
  std::string name = info.param;
  std::replace_if(
      name.begin(), name.end(), [](char c) { return !std::isalnum(c); }, '_');
  return name;
}

bool is_continuous(const std::string& input) {
  const auto checked = run_oasisc("check " + input);
  return checked.output.find("(continuous)") != std::string::npos;
}

class EveryInput : public ::testing::TestWithParam<std::string> {
 protected:
  oasis::test::ScratchDirectory scratch_{"oasis_every_input"};
};

TEST(EveryInputList, FindsTheShippedFiles) {
  const std::vector<std::string> inputs = shipped_inputs();
  for (const char* expected : {"specs/discrete_tracking.oasis", "tests/data/formats/coin.aut",
                               "tests/data/formats/robot.tra"}) {
    EXPECT_NE(std::find(inputs.begin(), inputs.end(), expected), inputs.end()) << expected;
  }
}

TEST_P(EveryInput, CompilesToEveryFormatAndVerifies) {
  const std::string input = std::string(OASIS_SOURCE_DIR) + "/" + GetParam();
  const fs::path out = scratch_.path() / "catalog";
  // Continuous specs draw their abstractions as SVG; explicit ones as DOT.
  const bool continuous = is_continuous(input);
  // Continuous catalogs carry their transition rows only on request; verify needs them.
  const std::string formats =
      continuous ? "bin,json,svg,cpp --with-transitions" : "bin,json,dot,cpp";
  const auto compiled = run_oasisc("compile " + input + " -o " + out.string() + " --format " +
                                   formats + " --epsilon 0.3");
  ASSERT_EQ(compiled.status, 0) << compiled.output;

  std::vector<fs::path> binaries;
  std::vector<fs::path> sources;
  std::size_t dots = 0;
  for (const auto& entry : fs::directory_iterator(out)) {
    const std::string extension = entry.path().extension().string();
    if (extension == ".bin") binaries.push_back(entry.path());
    if (extension == ".cpp") sources.push_back(entry.path());
    if (extension == ".dot" || extension == ".svg") ++dots;
    if (extension == ".json") {
      std::ifstream in(entry.path());
      EXPECT_TRUE(nlohmann::json::accept(in)) << entry.path();
    }
  }
  ASSERT_EQ(binaries.size(), 1U);
  ASSERT_EQ(sources.size(), 1U);
  const auto catalog = oasis::rt::LoadedCatalog::from_file(binaries[0].string());
  ASSERT_TRUE(catalog.ok()) << catalog.error();
  EXPECT_EQ(dots, catalog.view().num_abstractions);

  std::string why;
  EXPECT_TRUE(oasis::rt::validate(catalog.view(), &why)) << why;
  const auto verified = run_oasisc("verify " + input + " " + binaries[0].string());
  EXPECT_EQ(verified.status, 0) << verified.output;
  EXPECT_EQ(verified.output.find("not checked"), std::string::npos) << verified.output;

  // The generated tables are valid C++17 against the runtime headers alone.
  const std::string syntax_check = std::string(OASIS_CXX_COMPILER) +
                                   " -std=c++17 -fsyntax-only -Wall -Wextra -Werror -I " +
                                   OASIS_SOURCE_DIR + "/runtime/include -I " + out.string() + " " +
                                   sources[0].string() + " 2>&1";
  EXPECT_EQ(std::system(syntax_check.c_str()), 0) << syntax_check;
}

INSTANTIATE_TEST_SUITE_P(Shipped, EveryInput, ::testing::ValuesIn(shipped_inputs()), test_name);

}  // namespace
