// verify's own check of a scheduler file (verify/scheduler_check.hpp) on a small MDP whose
// optima are known by hand: optimal schedulers accepted with their exact value, each way a
// scheduler can be wrong refused with the state and action it names (among them the Pmin
// trap that "no action does better" alone would pass), properties verify does not read
// refused, and the reader's answer to hostile JSON.

#include "verify/scheduler_check.hpp"

#include <sstream>
#include <string>
#include <utility>
#include <vector>

#include <gtest/gtest.h>

#include "prism/load_program.hpp"
#include "verify/scheduler_reader.hpp"

namespace oasis {
namespace {

using model::ExplicitModel;
using verify::SchedulerEntry;
using verify::SchedulerFile;

// From s=0, a reaches the goal with 1/2; b goes to s=3, which reaches it with 1/3 and
// otherwise goes on to s=4. In s=4, stay loops forever, go reaches the goal with 1/2.
//   Pmax: s4 = 1/2 (go), s3 = 1/3 + 2/3 * 1/2 = 2/3, s0 = max(1/2, 2/3) = 2/3 (b).
//   Pmin: s4 = 0 (stay), s3 = 1/3, s0 = min(1/2, 1/3) = 1/3 (b).
//   Pmax [!"trap" U "goal"]: s4 fails, s3 = 1/3, s0 = 1/2 (a).
// s=5 is reached by c from s0: both of its actions reach the goal surely (Pmin = 1 there).
constexpr const char* kProgram = R"(mdp
module m
  s : [0..5] init 0;
  [a] s=0 -> 1/2:(s'=1) + 1/2:(s'=2);
  [b] s=0 -> (s'=3);
  [c] s=0 -> (s'=5);
  [a] s=1 -> true;
  [a] s=2 -> true;
  [a] s=3 -> 1/3:(s'=1) + 2/3:(s'=4);
  [stay] s=4 -> true;
  [go] s=4 -> 1/2:(s'=1) + 1/2:(s'=2);
  [a] s=5 -> (s'=1);
  [b] s=5 -> 1/2:(s'=1) + 1/2:(s'=5);
endmodule
label "goal" = s=1;
label "trap" = s=4;
label "safe" = s=5;
)";

ExplicitModel load() {
  SourceManager sources;
  std::ostringstream messages;
  DiagnosticEngine diagnostics(sources, messages);
  auto model =
      prism::load_program_text(sources.add("choices.nm", kProgram), "choices", diagnostics, {});
  EXPECT_TRUE(model) << messages.str();
  return std::move(*model);
}

// Actions of s=0..5 in order ("" for null).
SchedulerEntry entry(const std::string& property, const std::vector<std::string>& actions) {
  SchedulerEntry result;
  result.property = property;
  for (std::size_t s = 0; s < actions.size(); ++s) {
    verify::StateChoice choice{"(s=" + std::to_string(s) + ")", std::nullopt};
    if (!actions[s].empty()) choice.action = actions[s];
    result.memoryless.push_back(std::move(choice));
  }
  return result;
}

verify::CatalogCheck check(const SchedulerEntry& scheduler) {
  const ExplicitModel model = load();
  const auto checks = verify::check_schedulers(model, SchedulerFile{{scheduler}});
  EXPECT_EQ(checks.size(), 1U);
  return checks.front();
}

void expect_ok(const SchedulerEntry& scheduler, const std::string& verdict) {
  const verify::CatalogCheck result = check(scheduler);
  EXPECT_TRUE(result.ok) << result.verdict;
  EXPECT_EQ(result.verdict, verdict);
}

void expect_failed(const SchedulerEntry& scheduler, const std::string& says) {
  const verify::CatalogCheck result = check(scheduler);
  EXPECT_FALSE(result.ok) << result.verdict;
  EXPECT_EQ(result.verdict.rfind("FAILED: ", 0), 0U) << result.verdict;
  EXPECT_NE(result.verdict.find(says), std::string::npos) << result.verdict;
}

void expect_not_checked(const SchedulerEntry& scheduler, const std::string& says) {
  const verify::CatalogCheck result = check(scheduler);
  EXPECT_FALSE(result.ok) << result.verdict;
  EXPECT_EQ(result.verdict.rfind("not checked: ", 0), 0U) << result.verdict;
  EXPECT_NE(result.verdict.find(says), std::string::npos) << result.verdict;
}

const std::string kMax = "Pmax=? [F \"goal\"]";
const std::string kMin = "Pmin=? [F \"goal\"]";

TEST(SchedulerCheck, OptimalSchedulersAreAcceptedWithTheirExactValue) {
  expect_ok(entry(kMax, {"c", "", "", "a", "go", "a"}), "optimal; value 1 in the initial state");
  expect_failed(entry(kMax, {"b", "", "", "a", "go", "a"}),
                "in state (s=0), action 'c' gives 1 > 2/3");
  // Without c the best is b: the same model read through a property that fails s=5.
  expect_ok(entry("Pmax=? [!\"safe\" U \"goal\"]", {"b", "", "", "a", "go", "a"}),
            "optimal; value 2/3 in the initial state");
  expect_ok(entry(kMin, {"b", "", "", "a", "stay", "b"}),
            "optimal; value 1/3 in the initial state");
  expect_ok(entry("Pmax=? [!\"trap\" & !\"safe\" U \"goal\"]", {"a", "", "", "a", "", ""}),
            "optimal; value 1/2 in the initial state");
  // Parentheses, |, repeated ! and no blanks.
  expect_ok(entry("Pmin=?[F(\"goal\"|\"trap\")&!!\"goal\"]", {"b", "", "", "a", "stay", "a"}),
            "optimal; value 1/3 in the initial state");
}

TEST(SchedulerCheck, ASuboptimalActionFailsNamingTheStateAndTheBetterAction) {
  expect_failed(entry("Pmax=? [!\"safe\" U \"goal\"]", {"a", "", "", "a", "go", ""}),
                "in state (s=0), action 'b' gives 2/3 > 1/2, the scheduler's value there");
  expect_failed(entry("Pmax=? [!\"safe\" U \"goal\"]", {"b", "", "", "a", "stay", ""}),
                "in state (s=4), action 'go' gives 1/2 > 0, the scheduler's value there");
  expect_failed(entry(kMin, {"a", "", "", "a", "stay", "a"}),
                "in state (s=0), action 'b' gives 1/3 < 1/2");
}

// Going with a from s=0 and with go from s=4: s0 = 1/2, s3 = 2/3, s4 = 1/2. In s=4 stay gives
// 1/2 too (it keeps the value), and in s=0 b and c give 2/3 and 1, so "no action does better
// than the scheduler's value" holds in every state; but stay avoids the goal forever, so Pmin
// is 0 in s=4 and 1/3 in s=0. Fixing the states of Pmin = 0 first is what makes the
// certificate sound.
TEST(SchedulerCheck, PminIsZeroWhereTheTargetCanBeAvoidedForever) {
  expect_failed(entry(kMin, {"a", "", "", "a", "go", "a"}),
                "in state (s=4), the scheduler's value is 1/2, but the minimum is 0: action "
                "'stay' never leaves");
}

// The same scheduler is optimal for Pmax and not for Pmin: the check is not vacuous.
TEST(SchedulerCheck, APmaxSchedulerIsRefusedAsPmin) {
  const std::vector<std::string> best{"c", "", "", "a", "go", "a"};
  expect_ok(entry(kMax, best), "optimal; value 1 in the initial state");
  expect_failed(entry(kMin, best), "FAILED: in state (s=");
}

TEST(SchedulerCheck, NullIsAcceptedOnlyWhereTheChoiceCannotMatter) {
  // s=1 a target, s=2 one action, s=5 Pmin = 1 under both actions: null is fine.
  expect_ok(entry(kMin, {"b", "", "", "a", "stay", ""}), "optimal; value 1/3 in the initial state");
  expect_failed(entry(kMin, {"", "", "", "a", "stay", ""}),
                "in state (s=0), the file leaves the action open (null), but the choice matters");
  expect_failed(entry(kMax, {"c", "", "", "a", "", ""}),
                "in state (s=4), the file leaves the action open (null)");
  // Where no path reaches the target, any action gives 0.
  expect_ok(entry("Pmax=? [F \"trap\" & \"goal\"]", {"", "", "", "", "", ""}),
            "optimal; value 0 in the initial state");
}

TEST(SchedulerCheck, EveryStateOnceWithAnEnabledActionOfTheModel) {
  SchedulerEntry missing = entry(kMin, {"b", "", "", "a", "stay", ""});
  missing.memoryless.erase(missing.memoryless.begin() + 3);
  missing.memoryless.pop_back();
  expect_failed(missing, "state (s=3) is not in the file (nor 1 more)");
  SchedulerEntry twice = entry(kMin, {"b", "", "", "a", "stay", ""});
  twice.memoryless.push_back(twice.memoryless.front());
  expect_failed(twice, "state (s=0) is listed twice");
  SchedulerEntry unknown = entry(kMin, {"b", "", "", "a", "stay", ""});
  unknown.memoryless[2].state = "(s=9)";
  expect_failed(unknown, "the model has no state '(s=9)'");
  expect_failed(entry(kMin, {"b", "", "", "a", "leave", ""}),
                "in state (s=4), the model has no action 'leave'");
  expect_failed(entry(kMin, {"b", "", "", "go", "stay", ""}),
                "in state (s=3), action 'go' is not enabled");
}

TEST(SchedulerCheck, PropertiesVerifyDoesNotReadAreRefusedAsNotChecked) {
  const std::vector<std::string> actions{"b", "", "", "a", "stay", ""};
  for (const std::string& property :
       {std::string("P=? [F \"goal\"]"), std::string("Pmax=? [F<=3 \"goal\"]"),
        std::string("Pmax=? [X \"goal\"]"), std::string("Pmax=? [F s=1]"),
        std::string("R{\"r\"}min=? [F \"goal\"]"), std::string("Pmax>=0.5 [F \"goal\"]"),
        std::string("Pmax=? [F \"goal\"] extra"), std::string("Pmax=? [F \"goal]"),
        std::string("Pmax=? [F (\"goal\"]"), std::string("Pmax=? [G \"goal\"]")}) {
    SCOPED_TRACE(property);
    expect_not_checked(entry(property, actions), "'oasisc query' answers other properties");
  }
  expect_not_checked(entry("Pmax=? [F \"nowhere\"]", actions),
                     "the model has no label \"nowhere\"");
  const std::string deep =
      "Pmax=? [F " + std::string(300, '(') + "\"goal\"" + std::string(300, ')') + "]";
  expect_not_checked(entry(deep, actions), "parentheses nested deeper than 200");
  expect_not_checked(entry("Pmax=? [F \"goal\"" + std::string(20000, ' ') + "]", actions),
                     "longer than the 10000 verify reads");
  SchedulerEntry bounded = entry(kMax, {});
  bounded.step_bounded = true;
  expect_not_checked(bounded, "a step-bounded scheduler");
}

TEST(SchedulerCheck, TheReaderChecksEveryTypeAndKey) {
  const std::vector<std::pair<std::string, std::string>> cases = {
      {"", "not valid JSON"},
      {"{\"schedulers\": [", "not valid JSON"},
      {"[]", "the file is not a JSON object"},
      {"{}", "no \"schedulers\" key"},
      {"{\"schedulers\": 3}", "\"schedulers\" is number, not an array"},
      {"{\"schedulers\": []}", "\"schedulers\" is empty"},
      {"{\"schedulers\": [1]}", "schedulers[0] is number, not an object"},
      {"{\"schedulers\": [{\"memoryless\": []}]}", "schedulers[0] has no \"property\""},
      {"{\"schedulers\": [{\"property\": [], \"memoryless\": []}]}",
       "schedulers[0]: \"property\" is array, not a string"},
      {"{\"schedulers\": [{\"property\": \"p\", \"name\": 1, \"memoryless\": []}]}",
       "\"name\" is number, not a string"},
      {"{\"schedulers\": [{\"property\": \"p\"}]}", "has neither \"memoryless\" nor \"by_step\""},
      {"{\"schedulers\": [{\"property\": \"p\", \"memoryless\": [], \"by_step\": []}]}",
       "has both"},
      {"{\"schedulers\": [{\"property\": \"p\", \"memoryless\": {}}]}",
       "\"memoryless\" is object, not an array"},
      {"{\"schedulers\": [{\"property\": \"p\", \"memoryless\": [[]]}]}",
       "schedulers[0].memoryless[0] is array, not an object"},
      {"{\"schedulers\": [{\"property\": \"p\", \"memoryless\": [{\"state\": 0, \"action\": "
       "null}]}]}",
       "schedulers[0].memoryless[0]: \"state\" is number, not a string"},
      {"{\"schedulers\": [{\"property\": \"p\", \"memoryless\": [{\"state\": \"x\"}]}]}",
       "has no \"action\""},
      {"{\"schedulers\": [{\"property\": \"p\", \"memoryless\": [{\"state\": \"x\", \"action\": "
       "true}]}]}",
       "\"action\" is boolean, not a name or null"},
      // Deep nesting is neither a crash nor a message of megabytes.
      {"{\"schedulers\": [{\"property\": \"p\", \"memoryless\": [" + std::string(1000000, '[') +
           std::string(1000000, ']') + "]}]}",
       "schedulers[0].memoryless[0] is array, not an object"},
  };
  for (const auto& [text, says] : cases) {
    SCOPED_TRACE(text.substr(0, 200));
    std::string error;
    EXPECT_FALSE(verify::parse_scheduler_file(text, error));
    EXPECT_NE(error.find(says), std::string::npos) << error;
    EXPECT_LT(error.size(), 1000U);
  }
  std::string error;
  const auto file = verify::parse_scheduler_file(
      "{\"schedulers\": [{\"property\": \"p\", \"name\": \"n\", \"memoryless\": [{\"state\": "
      "\"(s=0)\", \"action\": null}, {\"state\": \"(s=1)\", \"action\": \"a\"}]}, {\"property\": "
      "\"q\", \"by_step\": [[]]}]}",
      error);
  ASSERT_TRUE(file) << error;
  ASSERT_EQ(file->schedulers.size(), 2U);
  EXPECT_EQ(file->schedulers[0].name, "n");
  EXPECT_FALSE(file->schedulers[0].memoryless[0].action);
  EXPECT_EQ(file->schedulers[0].memoryless[1].action, "a");
  EXPECT_TRUE(file->schedulers[1].step_bounded);
}

}  // namespace
}  // namespace oasis
