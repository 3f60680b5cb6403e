// A catalog built on a PRISM program (`import "f.nm" { ... }` with `context c = rewards "r";`):
// the shipped example gives the same catalog as the spec it translates, the spec's constants
// reach the program and --const overrides them, and mistakes on either side are located
// errors. The grammar's own errors are golden files (tests/specs/bad/import_*.oasis).

#include <filesystem>
#include <fstream>
#include <map>
#include <set>
#include <string>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "../../support/run_oasisc.hpp"
#include "../../support/scratch_directory.hpp"

namespace {

using Result = oasis::test::CommandResult;
using nlohmann::json;

std::string shipped(const std::string& name) {
  return std::string(OASIS_SOURCE_DIR) + "/specs/" + name;
}

// A walk along 0..N that a constant sizes, with two reward structures.
constexpr const char* kWalk = R"(mdp
const int N;
const double p;
module walk
  x : [0..N] init 0;
  [fwd] x < N -> p : (x'=x+1) + 1-p : (x'=x);
  [fwd] x = N -> (x'=x);
  [back] x > 0 -> (x'=x-1);
  [back] x = 0 -> (x'=x);
endmodule
rewards "far"
  x = N : 1;
endrewards
rewards "home"
  x = 0 : 1;
endrewards
)";

class ImportedCatalog : public ::testing::Test {
 protected:
  std::filesystem::path write(const std::string& name, const std::string& text) const {
    const auto path = scratch_.path() / name;
    std::ofstream(path) << text;
    return path;
  }

  static Result run(const std::string& arguments) { return oasis::test::run_oasisc(arguments); }

  // `compile SPEC --format json` into the scratch folder; the catalog's JSON.
  json compile(const std::string& spec, const std::string& folder) const {
    const auto out = scratch_.path() / folder;
    const Result result =
        run("compile " + spec + " --format json -o " + out.string() + " --progress never");
    EXPECT_EQ(result.status, 0) << result.output;
    for (const auto& entry : std::filesystem::directory_iterator(out)) {
      if (entry.path().extension() == ".json") return json::parse(std::ifstream(entry.path()));
    }
    ADD_FAILURE() << "no JSON catalog in " << out;
    return json::object();
  }

  oasis::test::ScratchDirectory scratch_{"oasis_imported_catalog_test"};
};

// context -> (member -> the block's action and value), members named s1, s2, s3 on both sides.
std::map<std::string, std::map<std::string, std::string>> policies(const json& catalog) {
  std::map<std::string, std::map<std::string, std::string>> result;
  for (const auto& abstraction : catalog["abstractions"]) {
    auto& policy = result[abstraction["context"].get<std::string>()];
    for (const auto& block : abstraction["blocks"]) {
      std::set<std::string> names;
      for (const auto& member : block["members"]) {
        std::string name = member.get<std::string>();
        if (name.starts_with("(s=")) name = "s" + name.substr(3, name.size() - 4);
        names.insert(name);
      }
      std::string members;
      for (const std::string& name : names)
        members += name + " ";
      for (const std::string& name : names) {
        policy[name] = "{" + members + "} " + block["action"].get<std::string>() + " " +
                       std::to_string(block["value"].get<double>());
      }
    }
  }
  return result;
}

TEST_F(ImportedCatalog, ShippedExampleEqualsTheSpecItTranslates) {
  const json written = compile(shipped("discrete_tracking.oasis"), "written");
  const json imported = compile(shipped("discrete_tracking_prism.oasis"), "imported");
  EXPECT_EQ(policies(imported), policies(written));
  EXPECT_EQ(policies(imported).size(), 2U);
  EXPECT_EQ(imported["switching"], written["switching"]);
  EXPECT_EQ(imported["prior"], written["prior"]);
  EXPECT_EQ(imported["observation"], written["observation"]);
  EXPECT_EQ(imported["actions"], written["actions"]);
}

TEST_F(ImportedCatalog, InfoNamesTheContextsAndTheKind) {
  const Result result = run("info --json " + shipped("discrete_tracking_prism.oasis"));
  ASSERT_EQ(result.status, 0) << result.output;
  const json info = json::parse(result.output);
  EXPECT_EQ(info["kind"], "prism");
  EXPECT_EQ(info["states"], 3);
  ASSERT_EQ(info["contexts"].size(), 2U);
  EXPECT_EQ(info["contexts"][0]["name"], "object_at_s3");
  EXPECT_EQ(info["contexts"][1]["name"], "object_at_s1");
}

TEST_F(ImportedCatalog, SpecConstantsReachTheProgramAndConstOverridesThem) {
  write("walk.nm", kWalk);
  const auto spec = write("walk.oasis", R"(import "walk.nm" { const N = 4; const p = 1/3; }
catalog {
  context go = rewards "far";
  context stay = rewards "home";
  context idle = base;
  switching stay 0.9;
}
)");
  Result result = run("info --json " + spec.string());
  ASSERT_EQ(result.status, 0) << result.output;
  EXPECT_EQ(json::parse(result.output)["states"], 5);
  EXPECT_EQ(json::parse(result.output)["contexts"].size(), 3U);

  result = run("info --json " + spec.string() + " --const N=7");
  ASSERT_EQ(result.status, 0) << result.output;
  EXPECT_EQ(json::parse(result.output)["states"], 8);

  // The reward structures land in the contexts that name them; `base` has none.
  const json catalog = compile(spec.string(), "walk");
  const auto reward_of = [&](const std::string& context, const std::string& state) {
    for (const auto& abstraction : catalog["abstractions"]) {
      if (abstraction["context"] != context) continue;
      for (const auto& block : abstraction["blocks"]) {
        for (const auto& member : block["members"]) {
          if (member == state) return block["reward"].get<double>();
        }
      }
    }
    ADD_FAILURE() << "no state " << state << " in context " << context;
    return -1.0;
  };
  EXPECT_EQ(reward_of("go", "(x=4)"), 1.0);
  EXPECT_EQ(reward_of("go", "(x=0)"), 0.0);
  EXPECT_EQ(reward_of("stay", "(x=0)"), 1.0);
  EXPECT_EQ(reward_of("idle", "(x=4)"), 0.0);
  EXPECT_EQ(reward_of("idle", "(x=0)"), 0.0);
}

TEST_F(ImportedCatalog, MistakesAboutTheProgramAreLocatedInTheSpec) {
  write("walk.nm", kWalk);
  const auto spec = write("bad.oasis", R"(import "walk.nm" { const N = 1/2; const M = 3; }
catalog {
  context go = rewards "faraway";
  context stay = rewards "home";
  switching stay 0.9;
}
)");
  const Result result = run("check " + spec.string());
  EXPECT_EQ(result.status, 1) << result.output;
  const std::string file = spec.string();
  EXPECT_NE(result.output.find(file + ":1:20: error: constant 'N' is an int"), std::string::npos)
      << result.output;
  EXPECT_NE(result.output.find(file + ":1:35: error: the program has no constant 'M'"),
            std::string::npos)
      << result.output;
  EXPECT_NE(result.output.find(file + ":3:24: error: the program has no reward structure "
                                      "'faraway' (it has 'far', 'home')"),
            std::string::npos)
      << result.output;
}

TEST_F(ImportedCatalog, AFileThatCannotBeImportedIsAnErrorAtItsName) {
  const auto missing = write("missing.oasis", "import \"nowhere.nm\";\n");
  Result result = run("check " + missing.string());
  EXPECT_EQ(result.status, 1) << result.output;
  EXPECT_NE(
      result.output.find(missing.string() + ":1:8: error: cannot read the imported program: "),
      std::string::npos)
      << result.output;

  write("model.aut", "des (0, 1, 2)\n(0, \"a\", 1)\n");
  const auto other = write("other.oasis", "import \"model.aut\";\n");
  result = run("check " + other.string());
  EXPECT_EQ(result.status, 1) << result.output;
  EXPECT_NE(result.output.find(other.string() +
                               ":1:8: error: can import a PRISM program (.pm, .nm or .prism), "
                               "not 'model.aut'"),
            std::string::npos)
      << result.output;
}

TEST_F(ImportedCatalog, ACatalogIsStaleWhenTheProgramChanges) {
  const auto program = write("walk.nm", kWalk);
  const auto spec = write("walk.oasis", "import \"walk.nm\" { const N = 3; const p = 0.5; }\n");
  const auto out = scratch_.path() / "out";
  Result result = run("compile " + spec.string() + " -o " + out.string() + " --progress never");
  ASSERT_EQ(result.status, 0) << result.output;
  const std::string catalog = (out / "walk.bin").string();
  result = run("verify " + spec.string() + " " + catalog);
  EXPECT_EQ(result.status, 0) << result.output;

  std::string changed = kWalk;
  changed.replace(changed.find("x = N : 1"), 9, "x = N : 2");
  std::ofstream(program) << changed;
  result = run("verify " + spec.string() + " " + catalog);
  EXPECT_NE(result.status, 0) << result.output;
}

}  // namespace
