// `oasisc verify MODEL SCHEDULERS.json` end to end: the schedulers `oasisc query --scheduler`
// writes on PRISM's two dice, consensus and leader election verify (Pmax and Pmin, nulls
// where the choice is moot), and edits of them fail with the state and action they name: a
// worse action swapped in, a missing state, an unknown or disabled action, a null where the
// choice matters, a Pmax scheduler checked as Pmin; a property verify does not read is not
// checked; malformed JSON is one error. Exit status 0 only when every scheduler holds.

#include <fstream>
#include <iterator>
#include <string>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "../../support/run_oasisc.hpp"
#include "../../support/scratch_directory.hpp"

namespace oasis {
namespace {

using nlohmann::json;
using test::run_oasisc;

const std::string kPrism = std::string(OASIS_SOURCE_DIR) + "/tests/data/prism/";
const std::string kDice = kPrism + "two_dice.nm";
const std::string kConsensus = kPrism + "consensus2.nm --const K=2";
const std::string kLeader = kPrism + "leader_async3.nm";

json read_json(const std::string& path) {
  std::ifstream in(path);
  return json::parse(std::string((std::istreambuf_iterator<char>(in)), {}));
}

void write_json(const std::string& path, const json& document) {
  std::ofstream(path) << document.dump(1);
}

// Writes the schedulers of `properties` on `model` with oasisc query.
void query(const std::string& model, const std::string& properties, const std::string& path) {
  const auto result = run_oasisc("query " + model + " " + properties + " --scheduler " + path);
  ASSERT_EQ(result.status, 0) << result.output;
}

int count(const std::string& text, const std::string& what) {
  int n = 0;
  for (std::size_t at = text.find(what); at != std::string::npos; at = text.find(what, at + 1))
    ++n;
  return n;
}

class VerifyScheduler : public ::testing::Test {
 protected:
  std::string path(const std::string& name) const { return (dir_.path() / name).string(); }
  test::ScratchDirectory dir_{"verify_scheduler_test"};
};

TEST_F(VerifyScheduler, QuerysSchedulersVerify) {
  query(kDice,
        "--prop 'Pmax=? [F \"seven\"]' --prop 'Pmin=? [F \"two\"]' "
        "--prop 'Pmax=? [!\"done\" U \"twelve\" | \"two\"]'",
        path("dice.json"));
  auto result = run_oasisc("verify " + kDice + " " + path("dice.json"));
  EXPECT_EQ(result.status, 0) << result.output;
  EXPECT_NE(result.output.find(
                "scheduler for 'Pmax=? [F \"seven\"]': optimal; value 1/6 in the initial state\n"),
            std::string::npos)
      << result.output;
  EXPECT_NE(result.output.find("scheduler for 'Pmin=? [F \"two\"]': optimal; value 1/36"),
            std::string::npos)
      << result.output;
  EXPECT_NE(result.output.find("U \"twelve\" | \"two\"]': optimal; value 1/18"), std::string::npos)
      << result.output;
  EXPECT_EQ(count(result.output, "\n"), 3) << result.output;

  query(kConsensus,
        "--prop 'Pmax=? [F \"finished\" & \"all_coins_equal_1\"]' "
        "--prop 'Pmin=? [F \"finished\" & \"all_coins_equal_1\"]'",
        path("consensus.json"));
  result = run_oasisc("verify " + kConsensus + " " + path("consensus.json"));
  EXPECT_EQ(result.status, 0) << result.output;
  EXPECT_NE(result.output.find("\"all_coins_equal_1\"]': optimal; value 5/9 in the initial"),
            std::string::npos)
      << result.output;
  EXPECT_NE(result.output.find("\"all_coins_equal_1\"]': optimal; value 49/128 in the initial"),
            std::string::npos)
      << result.output;

  // Pmin = 1 everywhere: every state is null.
  query(kLeader, "--prop 'Pmin=? [F \"elected\"]' --prop 'Pmax=? [F \"elected\"]'",
        path("leader.json"));
  result = run_oasisc("verify " + kLeader + " " + path("leader.json"));
  EXPECT_EQ(result.status, 0) << result.output;
  EXPECT_EQ(count(result.output, "optimal; value 1 in the initial state"), 2) << result.output;
}

// Each one-state swap to another enabled action of consensus' Pmax scheduler: a swap that
// keeps the value passes (ties), any other fails, and names a state and an action; the
// first such swap below names the very state and the action it replaced.
TEST_F(VerifyScheduler, AWorseActionSwappedInFails) {
  query(kConsensus, "--prop 'Pmax=? [F \"finished\" & \"all_coins_equal_1\"]'", path("c.json"));
  const json original = read_json(path("c.json"));
  const std::string state = "(counter=9,pc1=2,coin1=0,pc2=0,coin2=0)";
  json edited = original;
  std::string replaced;
  for (json& choice : edited["schedulers"][0]["memoryless"]) {
    if (choice["state"] != state) continue;
    ASSERT_TRUE(choice["action"].is_string());
    replaced = choice["action"];
    choice["action"] = replaced == "[0]" ? "[1]" : "[0]";
  }
  ASSERT_FALSE(replaced.empty());
  write_json(path("swapped.json"), edited);
  const auto result = run_oasisc("verify " + kConsensus + " " + path("swapped.json"));
  EXPECT_EQ(result.status, 1) << result.output;
  EXPECT_NE(result.output.find("FAILED: in state " + state + ", action '" + replaced + "' gives "),
            std::string::npos)
      << result.output;
  EXPECT_NE(result.output.find(", the scheduler's value there"), std::string::npos)
      << result.output;
}

TEST_F(VerifyScheduler, EditedFilesFailNamingWhatIsWrong) {
  query(kConsensus,
        "--prop 'Pmax=? [F \"finished\" & \"all_coins_equal_1\"]' "
        "--prop 'Pmin=? [F \"finished\" & \"all_coins_equal_1\"]'",
        path("c.json"));
  const json original = read_json(path("c.json"));
  const json& max_choices = original.at("schedulers").at(0).at("memoryless");
  // The first state with an action of its own, and the first null.
  std::size_t chosen = 0;
  while (max_choices.at(chosen).at("action").is_null())
    ++chosen;
  const std::string chosen_state = max_choices.at(chosen).at("state");
  const auto verify_edit = [&](const std::string& name, const auto& edit) {
    json edited = original;
    edit(edited["schedulers"][0]["memoryless"]);
    write_json(path(name), edited);
    return run_oasisc("verify " + kConsensus + " " + path(name));
  };

  auto result = verify_edit("missing.json", [&](json& list) { list.erase(list.begin() + 5); });
  EXPECT_EQ(result.status, 1) << result.output;
  EXPECT_NE(result.output.find("FAILED: state " + max_choices.at(5).at("state").get<std::string>() +
                               " is not in the file"),
            std::string::npos)
      << result.output;
  // The other scheduler of the file is still checked.
  EXPECT_NE(result.output.find("optimal; value 49/128"), std::string::npos) << result.output;

  result = verify_edit("unknown.json", [&](json& list) { list[chosen]["action"] = "flip"; });
  EXPECT_EQ(result.status, 1) << result.output;
  EXPECT_NE(
      result.output.find("FAILED: in state " + chosen_state + ", the model has no action 'flip'"),
      std::string::npos)
      << result.output;

  // "done" is enabled only once both processes have finished.
  result = verify_edit("disabled.json", [&](json& list) { list[0]["action"] = "done"; });
  EXPECT_EQ(result.status, 1) << result.output;
  EXPECT_NE(
      result.output.find("FAILED: in state " + max_choices.at(0).at("state").get<std::string>() +
                         ", action 'done' is not enabled"),
      std::string::npos)
      << result.output;

  // The initial state has two actions, reaches the target and may miss it.
  result = verify_edit("null.json", [&](json& list) { list[0]["action"] = nullptr; });
  EXPECT_EQ(result.status, 1) << result.output;
  EXPECT_NE(result.output.find("the file leaves the action open (null), but the choice matters"),
            std::string::npos)
      << result.output;
}

// Pmax (5/9) and Pmin (49/128) differ on consensus: the Pmax scheduler, read as a Pmin one,
// fails; so the check says something about the property it is given.
TEST_F(VerifyScheduler, APmaxSchedulerIsRefusedAsPmin) {
  query(kConsensus, "--prop 'Pmax=? [F \"finished\" & \"all_coins_equal_1\"]'", path("c.json"));
  json edited = read_json(path("c.json"));
  edited["schedulers"][0]["property"] = "Pmin=? [F \"finished\" & \"all_coins_equal_1\"]";
  write_json(path("as_min.json"), edited);
  const auto result = run_oasisc("verify " + kConsensus + " " + path("as_min.json"));
  EXPECT_EQ(result.status, 1) << result.output;
  EXPECT_NE(result.output.find("scheduler for 'Pmin=? [F \"finished\" & \"all_coins_equal_1\"]': "
                               "FAILED: in state "),
            std::string::npos)
      << result.output;
}

TEST_F(VerifyScheduler, OtherPropertiesAreNotCheckedAndBadFilesAreOneError) {
  query(kDice, "--prop 'Pmax=? [F \"seven\"]'", path("d.json"));
  json edited = read_json(path("d.json"));
  edited["schedulers"][0]["property"] = "Pmax=? [F<=10 \"seven\"]";
  write_json(path("bounded.json"), edited);
  auto result = run_oasisc("verify " + kDice + " " + path("bounded.json"));
  EXPECT_EQ(result.status, 1) << result.output;
  EXPECT_NE(result.output.find("scheduler for 'Pmax=? [F<=10 \"seven\"]': not checked: "),
            std::string::npos)
      << result.output;
  EXPECT_NE(result.output.find("'oasisc query' answers other properties"), std::string::npos)
      << result.output;

  std::ofstream(path("broken.json")) << "{\"schedulers\": [{\"property\": ";
  result = run_oasisc("verify " + kDice + " " + path("broken.json"));
  EXPECT_EQ(result.status, 1) << result.output;
  EXPECT_NE(result.output.find("error: not valid JSON"), std::string::npos) << result.output;
  EXPECT_EQ(count(result.output, "error:"), 1) << result.output;

  std::ofstream(path("typed.json")) << "{\"schedulers\": [{\"property\": 7, \"memoryless\": []}]}";
  result = run_oasisc("verify " + kDice + " " + path("typed.json"));
  EXPECT_EQ(result.status, 1) << result.output;
  EXPECT_NE(result.output.find("typed.json: error: schedulers[0]: \"property\" is number"),
            std::string::npos)
      << result.output;

  result = run_oasisc("verify " + kDice + " " + path("d.json") + " --max-input-size 10");
  EXPECT_EQ(result.status, 1) << result.output;

  result = run_oasisc("verify " + kDice);
  EXPECT_EQ(result.status, 2) << result.output;
}

TEST_F(VerifyScheduler, TheHelpShowsTheSchedulerForm) {
  const auto result = run_oasisc("verify --help");
  EXPECT_EQ(result.status, 0) << result.output;
  EXPECT_NE(result.output.find("oasisc verify two_dice.nm s.json"), std::string::npos)
      << result.output;
}

}  // namespace
}  // namespace oasis
