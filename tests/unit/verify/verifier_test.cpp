// Hand-made cases for the verifier (compiler/verify) and `oasisc verify`: the paper's example,
// chains, a symmetric grid, rewards split between state and action, disabled actions, and
// each kind of violation with the states, action and blocks it must name.

#include "verify/verifier.hpp"

#include <array>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <initializer_list>
#include <sstream>
#include <string>
#include <vector>

#include <gtest/gtest.h>
#include <sys/wait.h>
#include <unistd.h>

#include "../../support/naive_bisimulation.hpp"
#include "../../support/scratch_directory.hpp"
#include "../../support/spec_models.hpp"
#include "bisim/refinement.hpp"
#include "frontend/load_spec.hpp"
#include "model/explorer.hpp"

namespace oasis {
namespace {

using model::ExplicitModel;
using model::Partition;
using test::explore_spec_text;
using verify::ViolationKind;

ExplicitModel discrete_tracking() {
  return test::explore_spec_file(std::string(OASIS_SOURCE_DIR) + "/specs/discrete_tracking.oasis");
}

std::size_t context_index(const ExplicitModel& model, const std::string& name) {
  for (std::size_t c = 0; c < model.contexts.size(); ++c) {
    if (model.contexts[c].name == name) return c;
  }
  ADD_FAILURE() << "no context " << name;
  return 0;
}

model::StateIndex state(const ExplicitModel& model, const std::string& name) {
  for (model::StateIndex s = 0; s < model.num_states(); ++s) {
    if (model.states.name(s) == name) return s;
  }
  ADD_FAILURE() << "no state " << name;
  return 0;
}

// Blocks numbered in the order given; every state must be listed.
Partition partition_of(const ExplicitModel& model,
                       std::initializer_list<std::vector<std::string>> blocks) {
  Partition partition;
  partition.block_of.assign(model.num_states(), 0);
  for (const auto& block : blocks) {
    for (const std::string& name : block)
      partition.block_of[state(model, name)] = partition.num_blocks;
    ++partition.num_blocks;
  }
  return partition;
}

verify::Violation expect_violation(const ExplicitModel& model, std::size_t context,
                                   const Partition& partition, ViolationKind kind) {
  const verify::VerificationResult result = verify::verify_partition(model, context, partition);
  EXPECT_FALSE(result.ok());
  if (result.ok()) return {};
  EXPECT_EQ(result.violation->kind, kind)
      << verify::kind_name(result.violation->kind) << ": " << result.violation->message;
  return *result.violation;
}

void expect_accepted(const ExplicitModel& model, std::size_t context, const Partition& partition) {
  const verify::VerificationResult result = verify::verify_partition(model, context, partition);
  EXPECT_TRUE(result.ok()) << result.violation->message;
  // Hand-made answers agree with both engines, so the cases below test what they claim.
  const Partition canonical =
      model::canonical_partition({partition.block_of.begin(), partition.block_of.end()});
  EXPECT_EQ(test::naive_bisimulation(model, context).block_of, canonical.block_of);
  EXPECT_EQ(bisim::coarsest_bisimulation(model, context).block_of, canonical.block_of);
}

// --- The paper's example -------------------------------------------------------------------

TEST(Verifier, DiscreteTrackingAnswersAreAccepted) {
  const ExplicitModel model = discrete_tracking();
  expect_accepted(model, context_index(model, "object_at_s3"),
                  partition_of(model, {{"s1", "s2"}, {"s3"}}));
  expect_accepted(model, context_index(model, "object_at_s1"),
                  partition_of(model, {{"s1"}, {"s2", "s3"}}));
  // Block numbering does not matter.
  expect_accepted(model, context_index(model, "object_at_s3"),
                  partition_of(model, {{"s3"}, {"s1", "s2"}}));
}

TEST(Verifier, DiscreteTrackingSwappedAnswersBreakRewards) {
  const ExplicitModel model = discrete_tracking();
  const std::size_t at_s3 = context_index(model, "object_at_s3");
  const verify::Violation v = expect_violation(
      model, at_s3, partition_of(model, {{"s1"}, {"s2", "s3"}}), ViolationKind::RewardDiffers);
  EXPECT_EQ(v.state, state(model, "s2"));
  EXPECT_EQ(v.other_state, state(model, "s3"));
  EXPECT_EQ(v.block, 1U);
  EXPECT_EQ(v.action, 0U);  // L: the first action shows it
  EXPECT_EQ(v.message, "s2 and s3 are both in block 1 {s2, s3}, but R(s2, L) = 0 and R(s3, L) = 1");

  const std::size_t at_s1 = context_index(model, "object_at_s1");
  expect_violation(model, at_s1, partition_of(model, {{"s1", "s2"}, {"s3"}}),
                   ViolationKind::RewardDiffers);
  expect_violation(model, at_s1, partition_of(model, {{"s1", "s2", "s3"}}),
                   ViolationKind::RewardDiffers);
}

TEST(Verifier, DiscreteTrackingSingletonsAreNotCoarsest) {
  const ExplicitModel model = discrete_tracking();
  const verify::Violation v = expect_violation(model, context_index(model, "object_at_s3"),
                                               partition_of(model, {{"s1"}, {"s2"}, {"s3"}}),
                                               ViolationKind::BlocksCouldMerge);
  EXPECT_EQ(v.block, 0U);
  EXPECT_EQ(v.other_block, 1U);
  EXPECT_EQ(v.state, state(model, "s1"));
  EXPECT_EQ(v.other_state, state(model, "s2"));
  EXPECT_NE(v.message.find("block 0 {s1} and block 1 {s2} are bisimilar"), std::string::npos)
      << v.message;
}

TEST(Verifier, MalformedPartitionsHaveShapeViolations) {
  const ExplicitModel model = discrete_tracking();
  Partition shorter = partition_of(model, {{"s1", "s2"}, {"s3"}});
  shorter.block_of.pop_back();
  EXPECT_EQ(expect_violation(model, 0, shorter, ViolationKind::PartitionShape).message,
            "the partition has 2 states but the model has 3");

  Partition out_of_range = partition_of(model, {{"s1", "s2"}, {"s3"}});
  out_of_range.block_of[state(model, "s3")] = 5;
  EXPECT_EQ(expect_violation(model, 0, out_of_range, ViolationKind::PartitionShape).message,
            "state s3 is in block 5 but the partition has only 2 blocks");

  Partition empty_block = partition_of(model, {{"s1", "s2"}, {"s3"}});
  empty_block.num_blocks = 3;
  EXPECT_EQ(expect_violation(model, 0, empty_block, ViolationKind::PartitionShape).message,
            "block 2 of 3 has no states");
}

// --- Chains -------------------------------------------------------------------------------

const char* kChain = R"(
mdp chain {
  states c0, c1, c2, c3, c4;
  actions go;
  c0, go -> c1;
  c1, go -> c2;
  c2, go -> c3;
  c3, go -> c4;
  c4, go -> c4;
  reward c4 : 1;
}
)";

TEST(Verifier, ChainStatesAreAllDistinguished) {
  const ExplicitModel model = explore_spec_text(kChain);
  expect_accepted(model, 0, partition_of(model, {{"c0"}, {"c1"}, {"c2"}, {"c3"}, {"c4"}}));
  // c0 and c1 agree on rewards but are different distances from the reward.
  const verify::Violation v =
      expect_violation(model, 0, partition_of(model, {{"c0", "c1"}, {"c2"}, {"c3"}, {"c4"}}),
                       ViolationKind::BlockProbabilityDiffers);
  EXPECT_EQ(v.state, state(model, "c0"));
  EXPECT_EQ(v.other_state, state(model, "c1"));
  EXPECT_EQ(v.action, 0U);
  EXPECT_EQ(v.block, 0U);
  EXPECT_EQ(v.other_block, 0U);  // the first block they disagree on: c0 stays, c1 leaves
  EXPECT_EQ(v.message,
            "c0 and c1 are both in block 0 {c0, c1}, but under action go, c0 reaches block 0 "
            "{c0, c1} with probability 1 and c1 with probability 0");
}

TEST(Verifier, RewardlessChainIsOneBlock) {
  const ExplicitModel model = explore_spec_text(R"(
mdp chain {
  states c0, c1, c2, c3;
  actions go;
  c0, go -> c1;
  c1, go -> 1/3: c2 + 2/3: c3;
  c2, go -> c3;
  c3, go -> c0;
}
)");
  expect_accepted(model, 0, partition_of(model, {{"c0", "c1", "c2", "c3"}}));
  // Singletons are always a bisimulation; here not the coarsest.
  expect_violation(model, 0, partition_of(model, {{"c0"}, {"c1"}, {"c2"}, {"c3"}}),
                   ViolationKind::BlocksCouldMerge);
  // A split that is no bisimulation: c1 reaches {c0, c2} with 1/3, c3 with 1.
  expect_violation(model, 0, partition_of(model, {{"c0", "c2"}, {"c1", "c3"}}),
                   ViolationKind::BlockProbabilityDiffers);
}

TEST(Verifier, ProbabilitiesAreComparedPerBlockNotPerState) {
  // a reaches b1 and b2 with 1/2 each, a2 reaches b1 with 1: equal once b1 ~ b2.
  const ExplicitModel model = explore_spec_text(R"(
mdp split {
  states a, a2, b1, b2, goal;
  actions go;
  a, go -> 1/2: b1 + 1/2: b2;
  a2, go -> b1;
  b1, go -> 1/3: goal + 2/3: b1;
  b2, go -> 1/3: goal + 2/3: b2;
  goal, go -> goal;
  reward goal : 1;
}
)");
  expect_accepted(model, 0, partition_of(model, {{"a", "a2"}, {"b1", "b2"}, {"goal"}}));
  const verify::Violation v =
      expect_violation(model, 0, partition_of(model, {{"a", "a2"}, {"b1"}, {"b2"}, {"goal"}}),
                       ViolationKind::BlockProbabilityDiffers);
  EXPECT_EQ(v.other_block, 1U);
  EXPECT_NE(v.message.find("reaches block 1 {b1} with probability 1/2 (0.5) and a2 with "
                           "probability 1"),
            std::string::npos)
      << v.message;
}

// --- A symmetric grid ------------------------------------------------------------------------

TEST(Verifier, SymmetricGridHasCornersEdgesAndCentre) {
  // A random walk on a 3x3 grid, rewarded in the centre: by symmetry the corners are
  // equivalent, and so are the edge midpoints.
  const ExplicitModel model = explore_spec_text(R"(
mdp grid {
  var x : [0 .. 2] init 0;
  var y : [0 .. 2] init 0;
  actions step;
  [step] true -> 1/4: (x' = max(x - 1, 0)) + 1/4: (x' = min(x + 1, 2))
              + 1/4: (y' = max(y - 1, 0)) + 1/4: (y' = min(y + 1, 2));
  reward x == 1 & y == 1 : 1;
}
)");
  ASSERT_EQ(model.num_states(), 9U);
  const Partition expected =
      partition_of(model, {{"(x=0,y=0)", "(x=0,y=2)", "(x=2,y=0)", "(x=2,y=2)"},
                           {"(x=0,y=1)", "(x=1,y=0)", "(x=1,y=2)", "(x=2,y=1)"},
                           {"(x=1,y=1)"}});
  expect_accepted(model, 0, expected);
  // A corner with the edges: it reaches the centre with probability 0, an edge with 1/4.
  expect_violation(model, 0,
                   partition_of(model, {{"(x=0,y=0)", "(x=0,y=2)", "(x=2,y=0)", "(x=2,y=2)",
                                         "(x=0,y=1)", "(x=1,y=0)", "(x=1,y=2)", "(x=2,y=1)"},
                                        {"(x=1,y=1)"}}),
                   ViolationKind::BlockProbabilityDiffers);
  // Corners split by diagonal: every edge midpoint touches one corner of each diagonal, and
  // a corner stays put with 1/2, so this is still a bisimulation, but not the coarsest.
  expect_violation(model, 0,
                   partition_of(model, {{"(x=0,y=0)", "(x=2,y=2)"},
                                        {"(x=0,y=2)", "(x=2,y=0)"},
                                        {"(x=0,y=1)", "(x=1,y=0)", "(x=1,y=2)", "(x=2,y=1)"},
                                        {"(x=1,y=1)"}}),
                   ViolationKind::BlocksCouldMerge);
  // Corners split by row: an edge midpoint on the bottom row reaches the bottom corners
  // with 1/2, one on a side with 1/4. No bisimulation.
  expect_violation(model, 0,
                   partition_of(model, {{"(x=0,y=0)", "(x=2,y=0)"},
                                        {"(x=0,y=2)", "(x=2,y=2)"},
                                        {"(x=0,y=1)", "(x=1,y=0)", "(x=1,y=2)", "(x=2,y=1)"},
                                        {"(x=1,y=1)"}}),
                   ViolationKind::BlockProbabilityDiffers);
}

// --- Rewards and enabled actions ------------------------------------------------------------

TEST(Verifier, RewardIsStatePlusChoiceReward) {
  // R(p, a) = 1, R(p, b) = 0 from choice rewards alone; q gets the same from a state reward
  // of 1 and a choice reward of -1 on b. r differs on b.
  const ExplicitModel model = explore_spec_text(R"(
mdp labelled {
  states p, q, r, sink;
  actions a, b;
  p, a -> sink;    p, b -> sink;
  q, a -> sink;    q, b -> sink;
  r, a -> sink;    r, b -> sink;
  sink, a -> sink; sink, b -> sink;
  reward [a] p : 1;
  reward q : 1;
  reward [b] q : -1;
  reward [a] r : 1;
  reward [b] r : 1/2;
}
)");
  expect_accepted(model, 0, partition_of(model, {{"p", "q"}, {"r"}, {"sink"}}));
  const verify::Violation v = expect_violation(
      model, 0, partition_of(model, {{"p", "q", "r"}, {"sink"}}), ViolationKind::RewardDiffers);
  EXPECT_EQ(v.state, state(model, "p"));
  EXPECT_EQ(v.other_state, state(model, "r"));
  EXPECT_EQ(v.action, 1U);
  EXPECT_EQ(v.message,
            "p and r are both in block 0 {p, q, r}, but R(p, b) = 0 and R(r, b) = 1/2 (0.5)");
}

const char* kDisabled = R"(
mdp disabled {
  states u, v, w, sink;
  actions a, b;
  default disabled;
  u, a -> sink;
  v, a -> sink;
  v, b -> sink;
  w, a -> sink;
  sink, a -> sink;
  reward [b] u : 5;   // b is disabled in u: this reward belongs to no choice
}
)";

TEST(Verifier, EnabledActionsMustAgree) {
  const ExplicitModel model = explore_spec_text(kDisabled);
  const verify::Violation v =
      expect_violation(model, 0, partition_of(model, {{"u", "v", "w"}, {"sink"}}),
                       ViolationKind::EnabledActionsDiffer);
  EXPECT_EQ(v.state, state(model, "u"));
  EXPECT_EQ(v.other_state, state(model, "v"));
  EXPECT_EQ(v.action, 1U);
  EXPECT_EQ(v.message,
            "u and v are both in block 0 {u, v, w}, but action b is enabled in v and not in u");
}

TEST(Verifier, RewardsOfDisabledActionsAreIgnored) {
  const ExplicitModel model = explore_spec_text(kDisabled);
  expect_accepted(model, 0, partition_of(model, {{"u", "w", "sink"}, {"v"}}));
}

TEST(Verifier, StatesWithoutActionsAreToldApartByTheirStateReward) {
  // No enabled action, so no R(s, a): the state reward R(s), the reward for being in s,
  // separates such states instead (d1 earns 1, d2 and d3 earn 0).
  const ExplicitModel model = explore_spec_text(R"(
mdp stuck {
  states start, d1, d2, d3;
  actions go;
  default disabled;
  start, go -> 1/2: d1 + 1/4: d2 + 1/4: d3;
  reward d1 : 1;
}
)");
  expect_accepted(model, 0, partition_of(model, {{"start"}, {"d1"}, {"d2", "d3"}}));
  const verify::VerificationResult merged =
      verify::verify_partition(model, 0, partition_of(model, {{"start"}, {"d1", "d2", "d3"}}));
  ASSERT_FALSE(merged.ok());
  EXPECT_EQ(merged.violation->kind, ViolationKind::RewardDiffers);
  EXPECT_FALSE(merged.violation->action.has_value());
  EXPECT_NE(merged.violation->message.find("neither has an enabled action"), std::string::npos)
      << merged.violation->message;
}

// --- oasisc verify ----------------------------------------------------------------------------

struct CommandOutput {
  int status = -1;
  std::string output;  // stdout and stderr together
};

CommandOutput run_oasisc(const std::string& arguments) {
  const std::string command = std::string(OASISC_PATH) + " " + arguments + " 2>&1";
  CommandOutput result;
  FILE* pipe = ::popen(command.c_str(), "r");
  if (pipe == nullptr) return result;
  std::array<char, 4096> buffer{};
  std::size_t count = 0;
  while ((count = std::fread(buffer.data(), 1, buffer.size(), pipe)) > 0) {
    result.output.append(buffer.data(), count);
  }
  const int status = ::pclose(pipe);
  result.status = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  return result;
}

const std::string kTracking = std::string(OASIS_SOURCE_DIR) + "/specs/discrete_tracking.oasis";

// Each test's files go in its own scratch directory (named after the process, so concurrent
// default and asan runs never share one), removed when the test ends.
class VerifyCommand : public ::testing::Test {
 protected:
  [[nodiscard]] std::string write_temp(const std::string& name, const std::string& text) const {
    const auto path = scratch_.path() / name;
    std::ofstream(path) << text;
    return path.string();
  }

  [[nodiscard]] CommandOutput verify_tracking(const std::string& name,
                                              const std::string& result_json) const {
    return run_oasisc("verify " + kTracking + " " + write_temp(name, result_json));
  }

  test::ScratchDirectory scratch_{"oasis_verifier_test"};
};

bool contains(const CommandOutput& run, const std::string& text) {
  return run.output.find(text) != std::string::npos;
}

TEST_F(VerifyCommand, AcceptsTheRightPartitions) {
  const CommandOutput run = verify_tracking("ok.json", R"({"contexts": [
    {"name": "object_at_s3", "states": 3, "blocks": 2, "partition": [["s1", "s2"], ["s3"]]},
    {"name": "object_at_s1", "partition": [["s1"], ["s2", "s3"]]}]})");
  EXPECT_EQ(run.status, 0) << run.output;
  EXPECT_TRUE(contains(run, "context object_at_s3: bisimulation and coarsest (2 blocks)\n"))
      << run.output;
  EXPECT_TRUE(contains(run, "context object_at_s1: bisimulation and coarsest (2 blocks)\n"))
      << run.output;
}

TEST_F(VerifyCommand, ChecksWhatQuotientWrites) {
  const std::string result = write_temp("quotient.json", "");
  const CommandOutput quotient =
      run_oasisc("quotient " + kTracking + " --format json --partition -o " + result);
  ASSERT_EQ(quotient.status, 0) << quotient.output;
  const CommandOutput run = run_oasisc("verify " + kTracking + " " + result);
  EXPECT_EQ(run.status, 0) << run.output;
  EXPECT_TRUE(contains(run, "object_at_s1: bisimulation and coarsest")) << run.output;
}

TEST_F(VerifyCommand, ImportedModelsUseStateIndices) {
  const std::string aut = write_temp("tracking.aut", "");
  const CommandOutput exported =
      run_oasisc("export " + kTracking + " --context object_at_s3 --format aut -o " + aut);
  ASSERT_EQ(exported.status, 0) << exported.output;
  // Find where s3 went by asking quotient, then write the answer by index.
  const std::string result = write_temp("aut_quotient.json", "");
  const CommandOutput quotient =
      run_oasisc("quotient " + aut + " --format json --partition -o " + result);
  ASSERT_EQ(quotient.status, 0) << quotient.output;
  const CommandOutput run = run_oasisc("verify " + aut + " " + result);
  EXPECT_EQ(run.status, 0) << run.output;
  EXPECT_TRUE(contains(run, "bisimulation and coarsest (2 blocks)")) << run.output;
  const CommandOutput singletons = run_oasisc(
      "verify " + aut + " " +
      write_temp("aut_singletons.json",
                 R"({"contexts": [{"name": "default", "partition": [[0], [1], [2]]}]})"));
  EXPECT_EQ(singletons.status, 1) << singletons.output;
  EXPECT_TRUE(contains(singletons, "FAILED (blocks could merge)")) << singletons.output;
}

TEST_F(VerifyCommand, ReportsAWrongPartition) {
  const CommandOutput run = verify_tracking("wrong.json", R"({"contexts": [
    {"name": "object_at_s3", "partition": [["s1"], ["s2", "s3"]]}]})");
  EXPECT_EQ(run.status, 1) << run.output;
  EXPECT_TRUE(contains(run,
                       "context object_at_s3: FAILED (reward differs): s2 and s3 are both "
                       "in block 1 {s2, s3}, but R(s2, L) = 0 and R(s3, L) = 1"))
      << run.output;
  EXPECT_TRUE(contains(run, "context object_at_s1: not in RESULT, not checked")) << run.output;
}

TEST_F(VerifyCommand, ReportsABisimulationThatIsNotCoarsest) {
  const CommandOutput run = verify_tracking("fine.json", R"({"contexts": [
    {"name": "object_at_s1", "partition": [["s1"], ["s2"], ["s3"]]}]})");
  EXPECT_EQ(run.status, 1) << run.output;
  EXPECT_TRUE(contains(run, "FAILED (blocks could merge)")) << run.output;
  EXPECT_TRUE(contains(run, "block 1 {s2} and block 2 {s3} are bisimilar")) << run.output;
}

TEST_F(VerifyCommand, MalformedResultsAreErrors) {
  struct Case {
    const char* name;
    const char* json;
    const char* message;
  };
  const Case cases[] = {
      {"truncated", R"({"contexts": [{"name": "object_at_s3", "partition": [["s1")",
       "error: not valid JSON: "},
      // Found by the partition_json fuzz target: nlohmann throws out_of_range, not parse_error.
      {"number_overflow", R"({"contexts": [1e400]})",
       "error: not valid JSON: number overflow parsing '1e400'"},
      {"no_contexts", R"({"blocks": 2})", "error: no \"contexts\" key"},
      {"empty", R"({"contexts": []})", "error: \"contexts\" is empty"},
      {"no_partition", R"({"contexts": [{"name": "object_at_s3", "blocks": 2}]})",
       "error: context 'object_at_s3' has no \"partition\""},
      {"unknown_context", R"({"contexts": [{"name": "object_at_s9", "partition": [["s1"]]}]})",
       "error: the model has no context 'object_at_s9' (it has: object_at_s3, object_at_s1)"},
      {"unknown_state",
       R"({"contexts": [{"name": "object_at_s3", "partition": [["s1", "s2"], ["s9"]]}]})",
       "error: context 'object_at_s3': block 1: the model has no state \"s9\""},
      {"twice",
       R"({"contexts": [{"name": "object_at_s3", "partition": [["s1", "s2"], ["s2", "s3"]]}]})",
       "error: context 'object_at_s3': state s2 is in block 0 and in block 1"},
      {"missing", R"({"contexts": [{"name": "object_at_s3", "partition": [["s1", "s2"]]}]})",
       "error: context 'object_at_s3': state s3 is in no block"},
      {"empty_block",
       R"({"contexts": [{"name": "object_at_s3", "partition": [["s1", "s2"], [], ["s3"]]}]})",
       "error: context 'object_at_s3': block 1 is empty"},
      {"bad_state",
       R"({"contexts": [{"name": "object_at_s3", "partition": [["s1", "s2"], [true]]}]})",
       "true is neither a state name nor a state index"},
      {"index_range",
       R"({"contexts": [{"name": "object_at_s3", "partition": [["s1", "s2"], [3]]}]})",
       "state index 3 is out of range (the model has 3 states)"},
      {"block_count",
       R"({"contexts": [{"name": "object_at_s3", "blocks": 3, "partition": [["s1", "s2"], ["s3"]]}]})",
       "\"blocks\" is 3 but \"partition\" lists 2 blocks"},
      {"state_count",
       R"({"contexts": [{"name": "object_at_s3", "states": 4, "partition": [["s1", "s2"], ["s3"]]}]})",
       "\"states\" is 4 but the model has 3 states"},
      {"listed_twice",
       R"({"contexts": [{"name": "object_at_s3", "partition": [["s1", "s2"], ["s3"]]},
                        {"name": "object_at_s3", "partition": [["s1", "s2"], ["s3"]]}]})",
       "context 'object_at_s3' is listed twice"},
  };
  for (const Case& c : cases) {
    const CommandOutput run = verify_tracking(std::string(c.name) + ".json", c.json);
    EXPECT_EQ(run.status, 1) << c.name << ": " << run.output;
    EXPECT_TRUE(contains(run, c.message)) << c.name << ": " << run.output;
    EXPECT_FALSE(contains(run, "bisimulation and coarsest")) << c.name << ": " << run.output;
  }
}

TEST_F(VerifyCommand, MissingResultFile) {
  const CommandOutput run = run_oasisc("verify " + kTracking + " /nonexistent/result.json");
  EXPECT_EQ(run.status, 1) << run.output;
  EXPECT_TRUE(
      contains(run, "/nonexistent/result.json: error: cannot read: no such file or directory"))
      << run.output;
}

TEST_F(VerifyCommand, HelpTeachesWithAnExample) {
  const CommandOutput run = run_oasisc("verify --help");
  EXPECT_EQ(run.status, 0) << run.output;
  EXPECT_TRUE(contains(run, "oasisc verify specs/discrete_tracking.oasis")) << run.output;
  EXPECT_TRUE(contains(run, "coarsest")) << run.output;
}

}  // namespace
}  // namespace oasis
