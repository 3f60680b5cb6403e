// Labels as atomic propositions: bisimulation keeps apart states whose respected labels differ
// (model/state_labels.hpp), as Storm does, and the verifier checks the same relation.
//
// The model is Knuth and Yao's die as a Markov chain, written here from its description (a fair
// coin, flipped until it picks one of six faces): states 0..6 flip, state 7 + k - 1 shows face
// k. Storm's own test of it (DeterministicModelBisimulationDecompositionTest, Die) expects 13
// blocks when every label is respected and 5 when only "one" is.
#include <algorithm>
#include <sstream>

#include <gtest/gtest.h>

#include "../../support/scratch_directory.hpp"
#include "bisim/refinement.hpp"
#include "formats/explicit_reader.hpp"
#include "formats/explicit_writer.hpp"
#include "formats/model_file.hpp"
#include "model/state_labels.hpp"
#include "verify/verifier.hpp"

namespace oasis {
namespace {

constexpr const char* kDieTransitions =
    "13 20\n"
    "0 1 0.5\n0 2 0.5\n1 3 0.5\n1 4 0.5\n2 5 0.5\n2 6 0.5\n3 1 0.5\n3 7 0.5\n"
    "4 8 0.5\n4 9 0.5\n5 10 0.5\n5 11 0.5\n6 2 0.5\n6 12 0.5\n"
    "7 7 1\n8 8 1\n9 9 1\n10 10 1\n11 11 1\n12 12 1\n";
constexpr const char* kDieLabels =
    "0=\"init\" 1=\"one\" 2=\"two\" 3=\"three\" 4=\"four\" 5=\"five\" 6=\"six\" 7=\"done\"\n"
    "0: 0\n7: 1 7\n8: 2 7\n9: 3 7\n10: 4 7\n11: 5 7\n12: 6 7\n";

class LabelBisimulation : public ::testing::Test {
 protected:
  model::ExplicitModel die() {
    formats::PrismFiles files;
    files.transitions = sources_.add("die.tra", kDieTransitions);
    files.labels = sources_.add("die.lab", kDieLabels);
    std::optional<model::ExplicitModel> model = formats::read_prism(files, diagnostics_, {});
    EXPECT_TRUE(model) << out_.str();
    return std::move(*model);
  }

  static std::vector<std::uint32_t> classes(const model::ExplicitModel& model,
                                            const std::string& selection) {
    return model::label_classes(model.labels, model.num_states(),
                                *model::LabelSelection::parse(selection));
  }

  static model::Partition quotient(const model::ExplicitModel& model,
                                   const std::string& selection) {
    bisim::RefinementOptions options;
    options.label_class = classes(model, selection);
    return bisim::coarsest_bisimulation(model, 0, options);
  }

  SourceManager sources_;
  std::ostringstream out_;
  DiagnosticEngine diagnostics_{sources_, out_};
};

TEST_F(LabelBisimulation, EveryLabelOfTheLabFileIsKept) {
  const model::ExplicitModel model = die();
  EXPECT_EQ(model.labels.names.size(), 8U);
  EXPECT_EQ(model.labels.names[7], "done");
  ASSERT_EQ(model.labels.of(8).size(), 2U);
  EXPECT_EQ(model.labels.names[model.labels.of(8)[0]], "two");
  EXPECT_TRUE(model.labels.of(3).empty());
  EXPECT_EQ(model.states.initial, (std::vector<model::StateIndex>{0}));
}

TEST_F(LabelBisimulation, TheDieHasStormsBlockCounts) {
  const model::ExplicitModel model = die();
  EXPECT_EQ(quotient(model, "all").num_blocks, 13U);  // Storm: 13 states
  const model::Partition one = quotient(model, "one");
  EXPECT_EQ(one.num_blocks, 5U);  // Storm: 5 states
  // Faces two to six and the flips that can no longer give one are one block.
  EXPECT_EQ(one.block_of[2], one.block_of[12]);
  EXPECT_NE(one.block_of[7], one.block_of[8]);
  // No labels and no rewards: every state surely stays among states like itself.
  EXPECT_EQ(quotient(model, "none").num_blocks, 1U);
}

TEST_F(LabelBisimulation, TheVerifierAcceptsEachQuotientUnderItsOwnLabels) {
  const model::ExplicitModel model = die();
  for (const std::string selection : {"all", "one", "none", "done,six"}) {
    SCOPED_TRACE(selection);
    const verify::VerificationResult verdict =
        verify::verify_partition(model, 0, quotient(model, selection), classes(model, selection));
    EXPECT_TRUE(verdict.ok()) << verdict.violation->message;
  }
}

TEST_F(LabelBisimulation, TheVerifierRefusesABlockThatMixesRespectedLabels) {
  const model::ExplicitModel model = die();
  // The quotient without labels merges every face; under "one" that is wrong.
  const verify::VerificationResult verdict =
      verify::verify_partition(model, 0, quotient(model, "none"), classes(model, "one"));
  ASSERT_FALSE(verdict.ok());
  EXPECT_EQ(verdict.violation->kind, verify::ViolationKind::LabelsDiffer);
  EXPECT_NE(verdict.violation->message.find("\"one\""), std::string::npos)
      << verdict.violation->message;
}

TEST_F(LabelBisimulation, TheVerifierFindsAQuotientTooFineForItsLabels) {
  const model::ExplicitModel model = die();
  // Computed under every label, checked under "one" only: a bisimulation, but not the coarsest.
  const verify::VerificationResult verdict =
      verify::verify_partition(model, 0, quotient(model, "all"), classes(model, "one"));
  ASSERT_FALSE(verdict.ok());
  EXPECT_EQ(verdict.violation->kind, verify::ViolationKind::BlocksCouldMerge);
}

TEST_F(LabelBisimulation, ExportWritesTheLabelsBackAndTheyReadTheSame) {
  const model::ExplicitModel model = die();
  const test::ScratchDirectory scratch("oasis_label_die");
  const std::string base = (scratch.path() / "die").string();
  std::string error;
  ASSERT_TRUE(formats::write_prism(model, 0, base, error)) << error;
  std::optional<model::ExplicitModel> again =
      formats::read_model_file(base + ".tra", sources_, diagnostics_, {});
  ASSERT_TRUE(again) << out_.str();
  // "deadlock" is written too (PRISM writes it); the die has no dead end, so it holds nowhere.
  for (const std::string name : {"init", "one", "six", "done"}) {
    SCOPED_TRACE(name);
    const auto before = model.labels.find(name);
    const auto after = again->labels.find(name);
    ASSERT_TRUE(before && after);
    for (model::StateIndex s = 0; s < model.num_states(); ++s) {
      const auto holds = [s](const model::StateLabels& labels, std::uint32_t label) {
        const auto held = labels.of(s);
        return std::find(held.begin(), held.end(), label) != held.end();
      };
      EXPECT_EQ(holds(model.labels, *before), holds(again->labels, *after)) << "state " << s;
    }
  }
  EXPECT_EQ(quotient(*again, "one").num_blocks, 5U);
}

TEST(LabelSelection, ParsesAllNoneAndNames) {
  EXPECT_EQ(model::LabelSelection::parse("all")->kind, model::LabelSelection::Kind::kAll);
  EXPECT_EQ(model::LabelSelection::parse("none")->kind, model::LabelSelection::Kind::kNone);
  const auto named = model::LabelSelection::parse("one,done");
  ASSERT_TRUE(named);
  EXPECT_EQ(named->names, (std::vector<std::string>{"one", "done"}));
  EXPECT_EQ(named->describe(), "one,done");
  EXPECT_FALSE(model::LabelSelection::parse("one,,done"));
  EXPECT_FALSE(model::LabelSelection::parse(""));
}

TEST(LabelClasses, AnUnknownLabelIsNamedWithThoseTheModelHas) {
  model::StateLabelsBuilder builder({"a", "b"});
  builder.add(0, 1);
  const model::StateLabels labels = builder.finish(2);
  try {
    model::label_classes(labels, 2, *model::LabelSelection::parse("c"));
    FAIL() << "no error";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("no label \"c\" in the model (it has: a, b)"),
              std::string::npos)
        << e.what();
  }
  // "a" holds nowhere: one class; "b" holds in state 0 only: two.
  EXPECT_EQ(model::label_classes(labels, 2, *model::LabelSelection::parse("a")),
            (std::vector<std::uint32_t>{0, 0}));
  EXPECT_EQ(model::label_classes(labels, 2, *model::LabelSelection::parse("b")),
            (std::vector<std::uint32_t>{0, 1}));
  EXPECT_TRUE(model::label_classes(labels, 2, *model::LabelSelection::parse("none")).empty());
}

}  // namespace
}  // namespace oasis
