// `oasisc verify SPEC NAME.json` checks the cells a continuous catalog's JSON states (each
// cell's A x <= b, which tools outside the project read) against the partition the runtime
// uses: overlapping, moved or degenerate cells are caught, untouched files pass, and JSON that
// is not a catalog gets a sentence, not nlohmann's exception text (issue 28).

#include <filesystem>
#include <fstream>
#include <functional>
#include <string>
#include <utility>
#include <vector>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "../../support/run_oasisc.hpp"
#include "../../support/scratch_directory.hpp"
#include "../../support/spec_models.hpp"

namespace oasis {
namespace {

using Edit = std::function<void(nlohmann::json&)>;

// Two cells given the same A and b: cell 1 claims cell 0's part of the domain.
void cell_one_copies_cell_zero(nlohmann::json& document) {
  auto& cells = document["abstractions"][0]["cells"];
  cells[1]["A"] = cells[0]["A"];
  cells[1]["b"] = cells[0]["b"];
}

struct Compiled {
  std::string spec;
  nlohmann::json document;
};

// Compiles tests/data/SPEC_NAME.oasis to JSON and reads it (named after the spec's model).
Compiled compile_to_json(const test::ScratchDirectory& scratch, const std::string& spec_name,
                         const std::string& model_name) {
  const std::string spec = std::string(OASIS_SOURCE_DIR) + "/tests/data/" + spec_name + ".oasis";
  const std::string out = (scratch.path() / "out").string();
  const auto compiled =
      test::run_oasisc("compile '" + spec + "' -o '" + out + "' --format json --progress never");
  EXPECT_EQ(compiled.status, 0) << compiled.output;
  Compiled result{spec,
                  nlohmann::json::parse(test::read_text_file(out + "/" + model_name + ".json"))};
  return result;
}

test::CommandResult verify_edited(const test::ScratchDirectory& scratch, const Compiled& compiled,
                                  const Edit& edit) {
  nlohmann::json document = compiled.document;
  edit(document);
  const std::string path = (scratch.path() / "edited.json").string();
  std::ofstream(path) << document.dump();
  return test::run_oasisc("verify '" + compiled.spec + "' '" + path + "'");
}

void expect_caught(const test::ScratchDirectory& scratch, const Compiled& compiled,
                   const Edit& edit, const std::string& message) {
  const auto verified = verify_edited(scratch, compiled, edit);
  EXPECT_EQ(verified.status, 1) << verified.output;
  EXPECT_NE(verified.output.find(message), std::string::npos) << verified.output;
}

TEST(StatedCells, GridCellsThatOverlapOrAreDegenerateAreCaught) {
  const test::ScratchDirectory scratch("stated_grid");
  const Compiled compiled = compile_to_json(scratch, "deterministic_line", "deterministic_line");
  const auto untouched = verify_edited(scratch, compiled, [](nlohmann::json&) {});
  ASSERT_EQ(untouched.status, 0) << untouched.output;
  EXPECT_NE(untouched.output.find("states exactly the faces of its box"), std::string::npos)
      << untouched.output;

  ASSERT_GE(compiled.document.at("abstractions").at(0).at("cells").size(), 2U);
  // Two cells given the same A and b: cell 1 now claims cell 0's interval.
  expect_caught(scratch, compiled, cell_one_copies_cell_zero, "cell 1 states");
  // A cell moved over its neighbours: its upper bound pushed to the domain's end.
  expect_caught(
      scratch, compiled, [](nlohmann::json& j) { j["abstractions"][0]["cells"][0]["b"][0] = 1e6; },
      "which is none of the cell's own faces");
  // A = 0.
  expect_caught(
      scratch, compiled,
      [](nlohmann::json& j) {
        for (auto& row : j["abstractions"][0]["cells"][0]["A"])
          for (auto& a : row)
            a = 0.0;
      },
      "has every coefficient 0");
  // A face left out: the polytope is no longer bounded by the box.
  expect_caught(
      scratch, compiled,
      [](nlohmann::json& j) {
        j["abstractions"][0]["cells"][0]["A"].erase(0);
        j["abstractions"][0]["cells"][0]["b"].erase(0);
      },
      "does not state a face of its box");
  expect_caught(
      scratch, compiled, [](nlohmann::json& j) { j["abstractions"][0]["cells"][0]["b"].erase(0); },
      "rows of A and");
}

TEST(StatedCells, PolytopeCellsThatOverlapAreCaught) {
  const test::ScratchDirectory scratch("stated_polytope");
  const Compiled compiled = compile_to_json(scratch, "triangle_reward", "triangle");
  const auto untouched = verify_edited(scratch, compiled, [](nlohmann::json&) {});
  ASSERT_EQ(untouched.status, 0) << untouched.output;
  EXPECT_NE(untouched.output.find("covers exactly the cell's area"), std::string::npos)
      << untouched.output;

  // Two cells given the same A and b.
  expect_caught(scratch, compiled, cell_one_copies_cell_zero, "cell 1 states");
  // A face between two cells dropped (not one of the domain's [0, 2] x [0, 2]): the stated
  // polygon grows over the neighbour.
  bool dropped_one = false;
  const auto dropped = verify_edited(scratch, compiled, [&dropped_one](nlohmann::json& j) {
    for (auto& cell : j["abstractions"][0]["cells"]) {
      for (std::size_t r = 0; r < cell["A"].size(); ++r) {
        const double a0 = cell["A"][r][0];
        const double a1 = cell["A"][r][1];
        const double b = cell["b"][r];
        const double along = a0 != 0 ? a0 : a1;
        const bool domain_face = (a0 == 0) != (a1 == 0) && (b == 0 || b / along == 2);
        if (domain_face) continue;
        cell["A"].erase(r);
        cell["b"].erase(r);
        dropped_one = true;
        return;
      }
    }
  });
  ASSERT_TRUE(dropped_one);
  EXPECT_EQ(dropped.status, 1) << dropped.output;
  EXPECT_NE(dropped.output.find("stated polytope covers"), std::string::npos) << dropped.output;
  expect_caught(
      scratch, compiled,
      [](nlohmann::json& j) {
        j["abstractions"][0]["cells"][2]["A"][0] = {0.0, 0.0};
      },
      "has every coefficient 0");
}

TEST(StatedCells, JsonThatIsNoCatalogGetsASentence) {
  const test::ScratchDirectory scratch("stated_not_json");
  const std::string spec = std::string(OASIS_SOURCE_DIR) + "/tests/data/deterministic_line.oasis";
  const std::vector<std::pair<std::string, std::string>> cases{
      {"[]", "the document is array, not an object"},
      {"{\"format\": 2, \"name\": ", "parse error at line 1"},
      {"{}", "key 'format' not found"}};
  for (const auto& [text, message] : cases) {
    const std::string path = (scratch.path() / "bad.json").string();
    std::ofstream(path) << text;
    const auto verified = test::run_oasisc("verify '" + spec + "' '" + path + "'");
    EXPECT_EQ(verified.status, 1) << verified.output;
    EXPECT_NE(verified.output.find(message), std::string::npos) << verified.output;
    EXPECT_EQ(verified.output.find("json.exception"), std::string::npos) << verified.output;
  }
}

}  // namespace
}  // namespace oasis
