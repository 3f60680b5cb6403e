// Round trips spec -> explicit model -> .aut / PRISM files -> explicit model: every context
// of every discrete spec comes back with the same states, the same exact distributions and
// the same rewards R(s, a). Actions are compared by name (.aut numbers them by appearance).

#include <algorithm>
#include <filesystem>
#include <sstream>
#include <string>

#include <gtest/gtest.h>

#include "../../support/scratch_directory.hpp"
#include "../../support/spec_models.hpp"
#include "bisim/refinement.hpp"
#include "formats/aut_writer.hpp"
#include "formats/explicit_writer.hpp"
#include "formats/model_file.hpp"
#include "frontend/load_spec.hpp"
#include "model/explorer.hpp"
#include "prism/load_program.hpp"

namespace oasis {
namespace {

using model::ExplicitModel;

const char* kFactoredSpec = R"(
mdp walk {
  var x : [0 .. 6] init 3;
  var y : [0 .. 2];
  actions left, right, toss;
  default disabled;
  [left]  x > 0 -> 2/3: (x' = x - 1) + 1/3: true;
  [right] x < 6 -> 0.25: (x' = x + 1) & (y' = mod(y + 1, 3)) + 0.75: true;
  [toss]  y == 0 -> x/6: (y' = 1) + (6 - x)/6: (y' = 2);
  reward x == 6 : 1;
  reward [toss] true : -1/7;
}
catalog {
  context plain = base;
  context sticky { [left] x > 0 -> (x' = 0); reward x == 0 : 3; }
  switching stay 0.9;
}
)";

ExplicitModel read_back(const std::string& path) {
  SourceManager sources;
  std::ostringstream messages;
  DiagnosticEngine diagnostics(sources, messages);
  auto model = formats::read_model_file(path, sources, diagnostics, {});
  EXPECT_TRUE(model) << messages.str();
  EXPECT_FALSE(model::find_structural_problem(*model)) << *model::find_structural_problem(*model);
  return std::move(*model);
}

// Context `c` of `original` and the only context of `copy` describe the same MDP.
void expect_same_context(const ExplicitModel& original, std::size_t c, const ExplicitModel& copy) {
  ASSERT_EQ(copy.num_states(), original.num_states());
  ASSERT_EQ(copy.contexts.size(), 1U);
  const auto& a = *original.contexts[c].transitions;
  const auto& b = *copy.contexts[0].transitions;
  for (model::ActionIndex action = 0; action < original.num_actions(); ++action) {
    // .aut only lists actions that occur; an action never enabled cannot come back.
    const auto found =
        std::find(copy.actions.begin(), copy.actions.end(), original.actions[action]);
    const bool ever_enabled = [&] {
      for (model::StateIndex s = 0; s < original.num_states(); ++s) {
        if (a.enabled(s, action)) return true;
      }
      return false;
    }();
    if (!ever_enabled && found == copy.actions.end()) continue;
    ASSERT_NE(found, copy.actions.end()) << original.actions[action];
    const auto other = static_cast<model::ActionIndex>(found - copy.actions.begin());
    for (model::StateIndex s = 0; s < original.num_states(); ++s) {
      ASSERT_EQ(a.enabled(s, action), b.enabled(s, other)) << "state " << s;
      if (!a.enabled(s, action)) continue;
      ASSERT_EQ(a.edges_end(s, action) - a.edges_begin(s, action),
                b.edges_end(s, other) - b.edges_begin(s, other));
      for (auto e = a.edges_begin(s, action), f = b.edges_begin(s, other);
           e < a.edges_end(s, action); ++e, ++f) {
        EXPECT_EQ(a.edge_target[e], b.edge_target[f]);
        EXPECT_EQ(original.values[a.edge_probability[e]], copy.values[b.edge_probability[f]]);
      }
      EXPECT_EQ(original.reward(c, s, action), copy.reward(0, s, other))
          << "state " << s << " action " << original.actions[action];
    }
  }
}

class RoundTrip : public ::testing::Test {
 protected:
  test::ScratchDirectory scratch_{"oasis_roundtrip"};
  const std::filesystem::path& directory_ = scratch_.path();

  void check_all_contexts(const ExplicitModel& model) {
    ASSERT_FALSE(model::find_structural_problem(model));
    for (std::size_t c = 0; c < model.contexts.size(); ++c) {
      std::string error;
      const std::string aut = (directory_ / ("c" + std::to_string(c) + ".aut")).string();
      ASSERT_TRUE(formats::write_aut_file(model, c, aut, error)) << error;
      expect_same_context(model, c, read_back(aut));

      const std::string prism = (directory_ / ("c" + std::to_string(c))).string();
      ASSERT_TRUE(formats::write_prism(model, c, prism, error)) << error;
      const ExplicitModel from_prism = read_back(prism + ".tra");
      expect_same_context(model, c, from_prism);
      EXPECT_EQ(from_prism.states.initial, model.states.initial);
      EXPECT_EQ(from_prism.states.variables, model.states.variables);
      EXPECT_EQ(from_prism.states.valuations, model.states.valuations);
    }
  }
};

TEST_F(RoundTrip, DiscreteTrackingSpec) {
  const ExplicitModel model =
      test::explore_spec_file(std::string(OASIS_SOURCE_DIR) + "/specs/discrete_tracking.oasis");
  ASSERT_EQ(model.contexts.size(), 2U);
  check_all_contexts(model);
}

TEST_F(RoundTrip, FactoredSpecWithDisabledActionsAndActionRewards) {
  const ExplicitModel model = test::explore_spec_text(kFactoredSpec, "walk.oasis");
  ASSERT_EQ(model.contexts.size(), 2U);
  ASSERT_GT(model.num_states(), 10U);
  check_all_contexts(model);
}

// A PRISM program whose state (x=2) has no enabled command: the explorer gives it a self-loop
// and the label "deadlock", as PRISM does. Respecting all labels, (x=2) is a block of its own.
const char* kProgramWithADeadlock = R"(
mdp
module m
  x : [0..3] init 0;
  [] x = 0 -> 1/2 : (x'=2) + 1/2 : (x'=3);
  [] x = 3 -> (x'=3);
  [] x = 1 -> true;
endmodule
label "far" = x >= 2;
)";

ExplicitModel load_program(const char* text) {
  SourceManager sources;
  std::ostringstream messages;
  DiagnosticEngine diagnostics(sources, messages);
  auto model =
      prism::load_program_text(sources.add("deadlock.pm", text), "deadlock", diagnostics, {});
  EXPECT_TRUE(model) << messages.str();
  return std::move(*model);
}

model::Partition quotient_respecting_all_labels(const ExplicitModel& model) {
  bisim::RefinementOptions options;
  options.label_class = model::label_classes(model.labels, model.num_states(), {});
  return bisim::coarsest_bisimulation(model, 0, options);
}

// `export --format prism` used to drop the model's "deadlock" label (it wrote the states with
// no enabled choice, and the explorer's deadlocked states have a self-loop): the program had 3
// blocks and its export 2. The export now carries the model's labels, all of them.
TEST_F(RoundTrip, AProgramsExportHasItsLabelsAndItsQuotient) {
  const ExplicitModel program = load_program(kProgramWithADeadlock);
  const std::string base = (directory_ / "deadlock").string();
  std::string error;
  ASSERT_TRUE(formats::write_prism(program, 0, base, error)) << error;
  const ExplicitModel exported = read_back(base + ".tra");
  expect_same_context(program, 0, exported);

  const auto names = [](const ExplicitModel& m) {
    std::vector<std::string> sorted = m.labels.names;
    std::sort(sorted.begin(), sorted.end());
    return sorted;
  };
  ASSERT_EQ(names(program), names(exported));
  for (const std::string& name : program.labels.names) {
    const std::uint32_t a = *program.labels.find(name);
    const std::uint32_t b = *exported.labels.find(name);
    for (model::StateIndex s = 0; s < program.num_states(); ++s) {
      const auto in_a = program.labels.of(s);
      const auto in_b = exported.labels.of(s);
      EXPECT_EQ(std::find(in_a.begin(), in_a.end(), a) != in_a.end(),
                std::find(in_b.begin(), in_b.end(), b) != in_b.end())
          << "label " << name << ", state " << program.states.name(s);
    }
  }
  const model::Partition original = quotient_respecting_all_labels(program);
  EXPECT_EQ(original.num_blocks, 3U);
  EXPECT_EQ(quotient_respecting_all_labels(exported).block_of, original.block_of);
}

}  // namespace
}  // namespace oasis
