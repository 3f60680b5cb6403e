// `oasisc export --format umb` end to end: the .umb a model is exported to gives `info` and
// `quotient` the counts of the model itself (states, choices, transitions, reward ranges,
// labels, blocks of every context), and exporting that .umb again gives the same bytes.

#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "../../support/run_oasisc.hpp"
#include "../../support/scratch_directory.hpp"

namespace {

using nlohmann::json;

class UmbExport : public ::testing::Test {
 protected:
  [[nodiscard]] std::string path(const std::string& name) const {
    return (scratch_.path() / name).string();
  }

  json run_json(const std::string& arguments) const {
    const oasis::test::CommandResult result = oasis::test::run_oasisc(arguments);
    EXPECT_EQ(result.status, 0) << arguments << "\n" << result.output;
    return json::parse(result.output, nullptr, false);
  }

  json quotient(const std::string& file, const std::string& options) const {
    const std::string out = path("q.json");
    const oasis::test::CommandResult result =
        oasis::test::run_oasisc("quotient " + file + options + " --format json -o " + out);
    EXPECT_EQ(result.status, 0) << result.output;
    std::ifstream in(out);
    return json::parse(in, nullptr, false);
  }

  static std::string bytes_of(const std::string& file) {
    std::ifstream in(file, std::ios::binary);
    return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
  }

  oasis::test::ScratchDirectory scratch_{"oasis_umb_export_test"};
};

// What `info --json` says of each context, without the file's own name.
json contexts_of(const json& info) {
  json result = info.at("contexts");
  for (json& context : result)
    context.erase("name");
  return result;
}

TEST_F(UmbExport, InfoAndQuotientOfTheUmbGiveTheSourcesCounts) {
  const std::string data = std::string(OASIS_SOURCE_DIR) + "/tests/data/";
  const std::vector<std::pair<std::string, std::string>> sources = {
      {data + "prism/two_dice.nm", " --rewards all"},
      {data + "prism/crowds5.pm", " --rewards all --const TotalRuns=5"},
      {data + "formats/robot.tra", ""},
      {data + "formats/coin.aut", ""},
  };
  for (const auto& [source, options] : sources) {
    SCOPED_TRACE(source);
    const std::string umb = path("model.umb");
    const oasis::test::CommandResult exported =
        oasis::test::run_oasisc("export " + source + options + " --format umb -o " + umb);
    ASSERT_EQ(exported.status, 0) << exported.output;
    const json from_source = run_json("info --json " + source + options);
    const json from_umb = run_json("info --json " + umb);
    EXPECT_EQ(from_umb.at("states"), from_source.at("states"));
    EXPECT_EQ(from_umb.at("actions"), from_source.at("actions"));
    EXPECT_EQ(contexts_of(from_umb), contexts_of(from_source));

    const json blocks_source = quotient(source, options);
    const json blocks_umb = quotient(umb, "");
    ASSERT_EQ(blocks_umb.at("contexts").size(), blocks_source.at("contexts").size());
    for (std::size_t c = 0; c < blocks_umb.at("contexts").size(); ++c) {
      EXPECT_EQ(blocks_umb["contexts"][c].at("blocks"), blocks_source["contexts"][c].at("blocks"));
      EXPECT_EQ(blocks_umb["contexts"][c].at("name"), blocks_source["contexts"][c].at("name"));
    }

    const std::string again = path("again.umb");
    const oasis::test::CommandResult second =
        oasis::test::run_oasisc("export " + umb + " --format umb -o " + again);
    ASSERT_EQ(second.status, 0) << second.output;
    EXPECT_EQ(bytes_of(again), bytes_of(umb));
  }
}

// The variables travel as state valuations, so a property over them has the same answer.
TEST_F(UmbExport, QueriesOverVariablesGiveTheProgramsAnswers) {
  const std::string die = std::string(OASIS_SOURCE_DIR) + "/tests/data/prism/knuth_die.pm";
  const std::string umb = path("die.umb");
  ASSERT_EQ(oasis::test::run_oasisc("export " + die + " --format umb -o " + umb).status, 0);
  const std::string property = " --prop 'P=? [F face=1]'";
  const oasis::test::CommandResult from_program =
      oasis::test::run_oasisc("query " + die + property);
  const oasis::test::CommandResult from_umb = oasis::test::run_oasisc("query " + umb + property);
  EXPECT_EQ(from_umb.status, 0) << from_umb.output;
  EXPECT_NE(from_umb.output.find("= 1/6 "), std::string::npos) << from_umb.output;
  EXPECT_EQ(from_umb.output, from_program.output);
}

TEST_F(UmbExport, ABadUmbIsAnInputErrorNamingTheFile) {
  const std::string bad = path("bad.umb");
  std::ofstream(bad) << "not an archive";
  const oasis::test::CommandResult result = oasis::test::run_oasisc("info " + bad);
  EXPECT_EQ(result.status, 1);
  EXPECT_NE(result.output.find(bad + ": error: not a UMB file"), std::string::npos)
      << result.output;
}

}  // namespace
