// Storm's explicit files (issue 39): a .tra that starts with its model type (`dtmc`, `mdp`)
// and has no header, and a .lab in the #DECLARATION ... #END form. Knuth and Yao's die, laid
// out as Storm's die files are, gives Storm's counts; PRISM's header after a type line
// is read too; bad files get located errors.

#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "../../support/scratch_directory.hpp"
#include "formats/model_file.hpp"

namespace oasis::formats {
namespace {

using model::ExplicitModel;

// The die of Knuth and Yao: s0 flips to s1/s2, ..., states 7..12 are the faces.
constexpr const char* kDieTra = R"(dtmc
0 1 0.5
0 2 0.5
1 3 0.5
1 4 0.5
2 5 0.5
2 6 0.5
3 1 0.5
3 7 0.5
4 8 0.5
4 9 0.5
5 10 0.5
5 11 0.5
6 2 0.5
6 12 0.5
7 7 1
8 8 1
9 9 1
10 10 1
11 11 1
12 12 1
)";

constexpr const char* kDieLab = R"(#DECLARATION
init deadlock one two three
four five six done
#END
0 init
7 one done
8 two done
9 three done
10 four done
11 five done
12 six done
)";

class StormExplicit : public ::testing::Test {
 protected:
  struct Read {
    std::optional<ExplicitModel> model;
    std::string messages;
  };

  Read read(const std::string& tra, const std::string& lab = "") {
    const auto base = scratch_.path() / "x";
    std::ofstream(base.string() + ".tra") << tra;
    std::filesystem::remove(base.string() + ".lab");
    if (!lab.empty()) std::ofstream(base.string() + ".lab") << lab;
    SourceManager sources;
    std::ostringstream out;
    DiagnosticEngine diagnostics(sources, out);
    Read result;
    result.model = read_model_file(base.string() + ".tra", sources, diagnostics, {});
    result.messages = out.str();
    // Paths are the scratch directory's: keep the file names only.
    const std::string prefix = scratch_.path().string() + "/";
    for (std::size_t at = result.messages.find(prefix); at != std::string::npos;
         at = result.messages.find(prefix))
      result.messages.erase(at, prefix.size());
    return result;
  }

  oasis::test::ScratchDirectory scratch_{"oasis_storm_explicit_test"};
};

TEST_F(StormExplicit, TheDieHasStormsCountsLabelsAndInitialState) {
  const Read r = read(kDieTra, kDieLab);
  ASSERT_TRUE(r.model) << r.messages;
  const ExplicitModel& m = *r.model;
  EXPECT_EQ(m.type, model::ModelType::kDtmc);
  EXPECT_EQ(m.num_states(), 13U);
  EXPECT_EQ(m.contexts[0].transitions->num_edges(), 20U);
  EXPECT_EQ(m.actions, std::vector<std::string>{"[0]"});
  EXPECT_EQ(m.states.initial, std::vector<model::StateIndex>{0});
  EXPECT_EQ(m.labels.names.size(), 9U);
  const auto done = m.labels.find("done");
  ASSERT_TRUE(done);
  for (model::StateIndex s = 0; s < 13; ++s) {
    const auto held = m.labels.of(s);
    EXPECT_EQ(std::find(held.begin(), held.end(), *done) != held.end(), s >= 7) << s;
  }
  EXPECT_FALSE(model::find_structural_problem(m));
}

TEST_F(StormExplicit, AnMdpHasAChoiceColumnAndNoActions) {
  const Read r = read("mdp\n0 0 1 0.5\n0 0 0 0.5\n0 1 1 1\n1 0 1 1\n");
  ASSERT_TRUE(r.model) << r.messages;
  EXPECT_EQ(r.model->type, model::ModelType::kMdp);
  EXPECT_EQ(r.model->num_states(), 2U);
  EXPECT_EQ(r.model->actions, (std::vector<std::string>{"[0]", "[1]"}));
  EXPECT_EQ(r.model->contexts[0].transitions->num_enabled_choices(), 3U);
}

TEST_F(StormExplicit, PrismsHeaderMayFollowTheTypeLine) {
  const Read r = read("MDP\n2 2 3\n0 0 1 0.5\n0 0 0 0.5\n1 0 1 1\n");
  ASSERT_TRUE(r.model) << r.messages;
  EXPECT_EQ(r.model->num_states(), 2U);
  const Read chain = read("dtmc\n2 2\n0 1 1\n1 1 1\n");
  ASSERT_TRUE(chain.model) << chain.messages;
  EXPECT_EQ(chain.model->type, model::ModelType::kDtmc);
}

struct ErrorCase {
  const char* tra;
  const char* lab;
  const char* expected;
};

class StormExplicitError : public StormExplicit, public ::testing::WithParamInterface<ErrorCase> {};

TEST_P(StormExplicitError, IsReportedWhereItIs) {
  const Read r = read(GetParam().tra, GetParam().lab);
  EXPECT_FALSE(r.model);
  EXPECT_NE(r.messages.find(GetParam().expected), std::string::npos) << r.messages;
}

constexpr const char* kTwo = "dtmc\n0 1 1\n1 0 1\n";

INSTANTIATE_TEST_SUITE_P(
    Errors, StormExplicitError,
    ::testing::Values(
        ErrorCase{"ctmc\n0 1 2\n", "",
                  "x.tra:1:1: error: Storm's explicit ctmc files are not supported"},
        ErrorCase{"chain\n0 1 1\n", "", "x.tra:1:1: error: expected the model type 'dtmc' or"},
        ErrorCase{"dtmc\n", "", "error: no transitions after the model type"},
        // A type line decides the form: "2 2 3" is a chain's row (one number more than its
        // header), from state 2 to state 2 with probability 3.
        ErrorCase{"dtmc\n2 2 3\n", "",
                  "x.tra:2:1: error: probabilities of state 2, choice 0 sum to 3"},
        ErrorCase{"dtmc\n0 1 0.5\n1 0 1\n", "",
                  "x.tra:2:1: error: probabilities of state 0, choice 0 sum to 1/2"},
        ErrorCase{"mdp\n0 0 1 1\n0 1 x 1\n", "", "x.tra:3:5: error: expected the target state"},
        ErrorCase{kTwo, "#DECLARATION\ninit\n",
                  "x.lab:1:1: error: '#DECLARATION' without its '#END'"},
        ErrorCase{kTwo, "#DECLARATION\ninit\n#END\n0 init goal\n",
                  "x.lab:4:8: error: label 'goal' is not declared between #DECLARATION and #END"},
        ErrorCase{kTwo, "#DECLARATION\ninit a\n#END\n1 a\n0 init\n",
                  "x.lab:5:1: error: state 0 after state 1"},
        ErrorCase{kTwo, "#DECLARATION\ninit init\n#END\n",
                  "x.lab:2:6: error: label 'init' is declared twice"},
        ErrorCase{kTwo, "#DECLARATION\ninit\n#END\n2 init\n",
                  "x.lab:4:1: error: state 2 is out of range"},
        // Found by the lab_reader fuzzer: PRISM's form and properties could not name it.
        ErrorCase{kTwo, "#DECLARATION\ninit say\"hi\"\n#END\n",
                  "x.lab:2:9: error: a label name cannot hold '\"'"}));

}  // namespace
}  // namespace oasis::formats
