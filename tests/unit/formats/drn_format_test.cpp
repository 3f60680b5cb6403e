// Storm's DRN format: files laid out as Storm's exporter writes them are read with their
// labels, reward models and choice names; bad input gets a located error; read -> write ->
// read gives the same model and write -> read -> write the same bytes.

#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "../../support/scratch_directory.hpp"
#include "formats/drn_reader.hpp"
#include "formats/drn_writer.hpp"
#include "formats/model_file.hpp"
#include "prism/load_program.hpp"

namespace oasis::formats {
namespace {

using model::ExplicitModel;

struct Read {
  std::optional<ExplicitModel> model;
  std::string messages;
};

Read read_text(const std::string& text, const ReadOptions& options = {}) {
  SourceManager sources;
  std::ostringstream out;
  DiagnosticEngine diagnostics(sources, out);
  const FileId file = sources.add("x.drn", text);
  Read result;
  result.model = read_drn(file, diagnostics, options);
  result.messages = out.str();
  return result;
}

// Issue 41: '@nr_states' and '@nr_choices' beyond the memory budget are refused before the
// body is read, naming the option; --max-states, when given, names itself.
TEST(Drn, AHeaderBeyondTheMemoryBudgetIsRefusedBeforeTheBody) {
  ReadOptions options;
  options.memory_budget = std::uint64_t{1} << 30;
  const std::string header =
      "@type: MDP\n@value_type: double\n@nr_states\n1000000000\n@nr_choices\n4000000000\n"
      "@model\nstate 0\n\taction a\n\t\tx : 1\n";
  const Read read = read_text(header, options);
  EXPECT_FALSE(read.model);
  EXPECT_NE(read.messages.find("x.drn:4:1: error: the file declares 1000000000 states and "
                               "4000000000 choices: reading it takes at least 122.9 GiB, more "
                               "than the memory budget of 1.0 GiB (raise it with "
                               "--memory-budget)"),
            std::string::npos)
      << read.messages;
  EXPECT_EQ(read.messages.find("x.drn:10:"), std::string::npos) << read.messages;

  options.memory_budget = 0;
  options.max_states = 10;
  const Read capped = read_text(header, options);
  EXPECT_NE(capped.messages.find("x.drn:4:1: error: the file declares 1000000000 states, more "
                                 "than the limit of 10 (raise it with --max-states)"),
            std::string::npos)
      << capped.messages;
}

// An MDP with two reward models, labels (one with a blank), a named and an unlabelled choice,
// exact fractions and decimals, laid out as Storm writes it (its header comments, a blank
// @parameters line, a trailing blank after the reward model names).
constexpr const char* kMdp = R"(// Exported by storm
// Original model type: MDP
@type: MDP
@value_type: double
@parameters

@reward_models
time cost 
@nr_states
3
@nr_choices
4
@model
state 0 [1, 0] init start
	action go [0, 2.5]
		1 : 1/3
		2 : 2/3
	action __NOLABEL__ [0, 0]
		0 : 1
state 1 [0, 0] "the goal" start
	action stay [0, 0]
		1 : 1
state 2 [0, 1/4]
	action go [1, 0]
		0 : 0.75
		2 : .25
)";

std::map<std::string, Rational> distribution(const ExplicitModel& m, model::StateIndex s,
                                             const std::string& action) {
  std::map<std::string, Rational> result;
  const auto a = static_cast<model::ActionIndex>(
      std::find(m.actions.begin(), m.actions.end(), action) - m.actions.begin());
  if (a == m.num_actions()) {
    ADD_FAILURE() << "no action " << action;
    return result;
  }
  const model::TransitionMatrix& t = *m.contexts.at(0).transitions;
  for (auto e = t.edges_begin(s, a); e < t.edges_end(s, a); ++e)
    result[std::to_string(t.edge_target[e])] = m.values[t.edge_probability[e]];
  return result;
}

std::vector<std::string> labels_of(const ExplicitModel& m, model::StateIndex s) {
  std::vector<std::string> names;
  for (const std::uint32_t l : m.labels.of(s))
    names.push_back(m.labels.names[l]);
  std::sort(names.begin(), names.end());
  return names;
}

model::ActionIndex action_named(const ExplicitModel& m, const std::string& name) {
  return static_cast<model::ActionIndex>(std::find(m.actions.begin(), m.actions.end(), name) -
                                         m.actions.begin());
}

TEST(Drn, ReadsStormsLayoutWithLabelsRewardsAndChoiceNames) {
  const Read read = read_text(kMdp);
  ASSERT_TRUE(read.model) << read.messages;
  const ExplicitModel& m = *read.model;
  EXPECT_EQ(m.type, model::ModelType::kMdp);
  EXPECT_EQ(m.num_states(), 3U);
  EXPECT_EQ(m.actions, (std::vector<std::string>{"go", "[1]", "stay"}));
  EXPECT_EQ(m.states.initial, std::vector<model::StateIndex>{0});
  EXPECT_EQ(labels_of(m, 0), (std::vector<std::string>{"init", "start"}));
  EXPECT_EQ(labels_of(m, 1), (std::vector<std::string>{"start", "the goal"}));
  EXPECT_EQ(distribution(m, 0, "go"),
            (std::map<std::string, Rational>{{"1", Rational(1, 3)}, {"2", Rational(2, 3)}}));
  EXPECT_EQ(distribution(m, 2, "go"),
            (std::map<std::string, Rational>{{"0", Rational(3, 4)}, {"2", Rational(1, 4)}}));
  ASSERT_EQ(m.contexts.size(), 2U);
  EXPECT_EQ(m.contexts[0].name, "time");
  EXPECT_EQ(m.contexts[1].name, "cost");
  const model::ActionIndex go = action_named(m, "go");
  EXPECT_EQ(m.reward(0, 0, go), 1);               // state reward 1, choice 0
  EXPECT_EQ(m.reward(1, 0, go), Rational(5, 2));  // choice reward
  EXPECT_EQ(m.reward(0, 2, go), 1);               // choice reward
  EXPECT_EQ(m.reward(1, 2, go), Rational(1, 4));  // state reward
  EXPECT_EQ(m.contexts[0].transitions, m.contexts[1].transitions);
  EXPECT_FALSE(model::find_structural_problem(m));
}

TEST(Drn, AMarkovChainHasTheOneActionOfTheOtherReaders) {
  const Read read = read_text(
      "@type: DTMC\n@parameters\n\n@reward_models\n\n@nr_states\n2\n@nr_choices\n2\n@model\n"
      "state 0 init\n\taction 0\n\t\t0 : 0.5\n\t\t1 : 0.5\nstate 1 done\n\taction 0\n\t\t1 : 1\n");
  ASSERT_TRUE(read.model) << read.messages;
  EXPECT_EQ(read.model->type, model::ModelType::kDtmc);
  EXPECT_EQ(read.model->actions, std::vector<std::string>{"[0]"});
  ASSERT_EQ(read.model->contexts.size(), 1U);
  EXPECT_EQ(read.model->contexts[0].name, "default");
}

TEST(Drn, WithoutAnInitLabelStateZeroIsInitialWithAWarning) {
  const Read read =
      read_text("@type: DTMC\n@nr_states\n1\n@model\nstate 0\n\taction 0\n\t\t0 : 1\n");
  ASSERT_TRUE(read.model) << read.messages;
  EXPECT_EQ(read.model->states.initial, std::vector<model::StateIndex>{0});
  EXPECT_NE(read.messages.find("x.drn:4:1: warning: no state is labelled \"init\""),
            std::string::npos)
      << read.messages;
}

struct ErrorCase {
  const char* text;
  const char* expected;
};

class DrnError : public ::testing::TestWithParam<ErrorCase> {};

TEST_P(DrnError, IsReportedWhereItIs) {
  const Read read = read_text(GetParam().text);
  EXPECT_FALSE(read.model);
  EXPECT_NE(read.messages.find(GetParam().expected), std::string::npos) << read.messages;
}

#define HEAD "@type: MDP\n@reward_models\nr\n@nr_states\n2\n@model\n"

INSTANTIATE_TEST_SUITE_P(
    Errors, DrnError,
    ::testing::Values(
        ErrorCase{"", "x.drn:1:1: error: the file ends before '@model'"},
        ErrorCase{"@type: CTMC\n", "x.drn:1:1: error: a CTMC is not supported"},
        ErrorCase{"@type: XYZ\n", "x.drn:1:1: error: unknown model type 'XYZ'"},
        ErrorCase{"@type: MDP\n@type: MDP\n", "x.drn:2:1: error: the model type is given twice"},
        ErrorCase{"@value_type: parametric\n",
                  "x.drn:1:1: error: value type 'parametric' is not supported"},
        ErrorCase{"@parameters\np q\n", "x.drn:2:1: error: parametric models are not supported"},
        ErrorCase{"@placeholders\n", "x.drn:1:1: error: placeholders are not supported"},
        ErrorCase{"@nr_states\nmany\n", "x.drn:2:1: error: expected the number of states"},
        ErrorCase{"@nr_states\n0\n", "x.drn:2:1: error: the model has no states"},
        ErrorCase{"@reward_models\na a\n", "x.drn:2:3: error: reward model 'a' is named twice"},
        ErrorCase{"@bogus\n", "x.drn:1:1: error: unknown header line '@bogus'"},
        ErrorCase{"@nr_states\n1\n@model\n", "x.drn:3:1: error: '@type' must come before '@model'"},
        ErrorCase{HEAD "state 1\n", "x.drn:7:7: error: expected state 0, not 1"},
        ErrorCase{HEAD "state 0 [1, 2]\n",
                  "x.drn:7:9: error: 2 rewards here, but '@reward_models' names 1"},
        ErrorCase{HEAD "state 0 [x]\n", "x.drn:7:10: error: reward 'x' is not a number"},
        ErrorCase{HEAD "state 0 [1 2]\n",
                  "x.drn:7:12: error: expected ',' or ']' in the list of rewards"},
        ErrorCase{HEAD "state 0 \"open\n", "x.drn:7:9: error: label not closed by '\"'"},
        ErrorCase{HEAD "\taction a\n", "x.drn:7:2: error: an 'action' before the first 'state'"},
        ErrorCase{HEAD "state 0\n\t\t1 : 1\n",
                  "x.drn:8:3: error: a transition before the 'action' it belongs to"},
        ErrorCase{HEAD "state 0\n\taction a\n\t\t2 : 1\n",
                  "x.drn:9:3: error: state 2 is out of range: the model has 2 states"},
        ErrorCase{HEAD "state 0\n\taction a\n\t\t1 1\n",
                  "x.drn:9:5: error: expected ':' between the target state and its probability"},
        ErrorCase{HEAD "state 0\n\taction a\n\t\t1 : 0\n",
                  "x.drn:9:7: error: probability must be positive"},
        ErrorCase{HEAD "state 0\n\taction a\n\t\t1 : 1/2\n",
                  "x.drn:8:2: error: probabilities of state 0, choice 0 sum to 1/2 (0.5), not 1"},
        ErrorCase{HEAD "state 0\n\taction a\n",
                  "x.drn:8:2: error: state 0, choice 0 has no transitions"},
        ErrorCase{HEAD "state 0\n\taction a\n\t\t1 : 1\n\taction a\n\t\t0 : 1\nstate 1\n",
                  "x.drn:10:2: error: state 0 has two choices named 'a' (choices 0 and 1)"},
        ErrorCase{HEAD "state 0\n\taction a\n\t\t1 : 1\n",
                  "x.drn:6:1: error: '@nr_states' declares 2 states but the file lists 1"},
        ErrorCase{HEAD "state 0\nstate 1\nstate 2\n",
                  "x.drn:9:7: error: more states than '@nr_states' declares (2)"},
        ErrorCase{"@type: MDP\n@nr_states\n1\n@nr_choices\n3\n@model\nstate 0\n\taction a\n\t\t0 : "
                  "1\n",
                  "x.drn:5:1: error: '@nr_choices' declares 3 choices but the file has 1"},
        ErrorCase{"@type: DTMC\n@nr_states\n1\n@model\nstate 0\n\taction a\n\t\t0 : "
                  "1\n\taction b\n\t\t0 : 1\n",
                  "x.drn:8:2: error: state 0 has a second choice here, but a DTMC has one per "
                  "state"}));

#undef HEAD

// --- round trips -------------------------------------------------------------------------

class DrnFile : public ::testing::Test {
 protected:
  [[nodiscard]] std::string path(const std::string& name) const {
    return (scratch_.path() / name).string();
  }

  std::string write(const ExplicitModel& m, const std::string& name) {
    std::vector<std::size_t> contexts;
    for (std::size_t c = 0; c < m.contexts.size(); ++c)
      contexts.push_back(c);
    std::string error;
    EXPECT_TRUE(write_drn_file(m, contexts, path(name), error)) << error;
    std::ifstream in(path(name));
    return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
  }

  ExplicitModel read(const std::string& name) {
    SourceManager sources;
    std::ostringstream messages;
    DiagnosticEngine diagnostics(sources, messages);
    std::optional<ExplicitModel> m = read_model_file(path(name), sources, diagnostics, {});
    EXPECT_TRUE(m) << messages.str();
    return m ? std::move(*m) : ExplicitModel{};
  }

  oasis::test::ScratchDirectory scratch_{"oasis_drn_test"};
};

// Same states, initial states, actions by name, exact distributions, labels by name and
// R(s, a) of every context.
void expect_same_model(const ExplicitModel& x, const ExplicitModel& y) {
  ASSERT_EQ(x.num_states(), y.num_states());
  EXPECT_EQ(x.type, y.type);
  EXPECT_EQ(x.states.initial, y.states.initial);
  ASSERT_EQ(x.contexts.size(), y.contexts.size());
  for (model::StateIndex s = 0; s < x.num_states(); ++s) {
    EXPECT_EQ(labels_of(x, s), labels_of(y, s)) << "state " << s;
    for (model::ActionIndex a = 0; a < x.num_actions(); ++a) {
      const model::ActionIndex b = action_named(y, x.actions[a]);
      const bool enabled = x.contexts[0].transitions->enabled(s, a);
      if (b == y.num_actions()) {
        EXPECT_FALSE(enabled) << x.actions[a];
        continue;
      }
      EXPECT_EQ(distribution(x, s, x.actions[a]), distribution(y, s, x.actions[a]));
      if (!enabled) continue;
      for (std::size_t c = 0; c < x.contexts.size(); ++c) {
        EXPECT_EQ(x.contexts[c].name, y.contexts[c].name);
        EXPECT_EQ(x.reward(c, s, a), y.reward(c, s, b)) << "state " << s << " " << x.actions[a];
      }
    }
  }
}

TEST_F(DrnFile, ReadWriteReadKeepsTheModelAndWriteReadWriteTheBytes) {
  const Read first = read_text(kMdp);
  ASSERT_TRUE(first.model) << first.messages;
  const std::string bytes = write(*first.model, "a.drn");
  const ExplicitModel second = read("a.drn");
  expect_same_model(*first.model, second);
  EXPECT_EQ(write(second, "b.drn"), bytes);
  // The unlabelled choice is written as Storm writes it, and the label with a blank quoted.
  EXPECT_NE(bytes.find("\taction __NOLABEL__ [0, 0]\n"), std::string::npos) << bytes;
  EXPECT_NE(bytes.find("state 1 [0, 0] start \"the goal\"\n"), std::string::npos) << bytes;
  EXPECT_NE(bytes.find("@reward_models\ntime cost\n"), std::string::npos) << bytes;
}

TEST_F(DrnFile, PrismProgramsRoundTripWithTheirRewardStructures) {
  for (const char* name : {"knuth_die.pm", "two_dice.nm", "crowds5.pm"}) {
    SourceManager sources;
    std::ostringstream messages;
    DiagnosticEngine diagnostics(sources, messages);
    prism::LoadOptions options;
    options.rewards = model::LabelSelection{};  // every reward structure a context
    if (std::string(name) == "crowds5.pm") options.constants = "TotalRuns=5";
    const std::optional<ExplicitModel> program = prism::load_program(
        std::string(OASIS_SOURCE_DIR) + "/tests/data/prism/" + name, sources, diagnostics, options);
    ASSERT_TRUE(program) << messages.str();
    const std::string bytes = write(*program, "p.drn");
    const ExplicitModel back = read("p.drn");
    expect_same_model(*program, back);
    EXPECT_EQ(write(back, "q.drn"), bytes) << name;
  }
}

TEST_F(DrnFile, WhatDrnCannotCarryIsRefusedBeforeWriting) {
  Read read = read_text(kMdp);
  ASSERT_TRUE(read.model);
  read.model->actions[0] = "two words";
  std::string error;
  const std::vector<std::size_t> all = {0, 1};
  EXPECT_FALSE(write_drn_file(*read.model, all, path("bad.drn"), error));
  EXPECT_NE(error.find("action name 'two words' has blanks"), std::string::npos) << error;
  EXPECT_FALSE(std::filesystem::exists(path("bad.drn")));
}

}  // namespace
}  // namespace oasis::formats
