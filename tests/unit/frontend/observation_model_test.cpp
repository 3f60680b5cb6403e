// Observation models in the spec (issue 12): the `observation` block of a catalog is parsed
// and checked (every diagnostic with its exact message and place), compiled into every
// carrier (binary file, C++ tables, JSON) and read back equal, and `--robust P` overrides it.

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <optional>
#include <sstream>
#include <string>
#include <vector>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "../../support/run_oasisc.hpp"
#include "../../support/scratch_directory.hpp"
#include "../../support/spec_models.hpp"
#include "codegen/binary_catalog.hpp"
#include "frontend/load_spec.hpp"
#include "oasis/rt/catalog_file.hpp"
#include "oasis/rt/catalog_validation.hpp"
#include "pipeline/discrete_catalog.hpp"

namespace oasis {
namespace {

using model::ObservationSpec;

// A three-state ring with a full confusion matrix and a reward read off the observed state.
const char* kMatrixSpec = R"(mdp ring {
  states a, b, c;
  actions go, wait;
  a, go -> b;
  b, go -> 1/2: c + 1/2: a;
  c, go -> a;
  a, wait -> a;
  b, wait -> b;
  c, wait -> c;
}
catalog {
  context at_a { reward a : 1; }
  context at_c { reward c : 1; }
  switching stay 0.9;
  observation {
    state confusion {
      a -> 0.8: a + 0.2: b;
      b -> 0.1: a + 0.8: b + 0.1: c;
      c -> c;
    }
    reward follows observed;
  }
}
)";

std::vector<std::string> errors_of(const std::string& source) {
  return test::spec_errors(source);
}

// A two-state explicit model whose catalog ends with `observation` (one or more lines).
std::string explicit_spec(const std::string& observation) {
  return "mdp m {\n"
         "  states s1, s2;\n"
         "  actions a;\n"
         "  s1, a -> s2;\n"
         "  s2, a -> s1;\n"
         "}\n"
         "catalog {\n"
         "  context c1 { reward s1 : 1; }\n"
         "  context c2 { reward s2 : 1; }\n"
         "  switching stay 0.8;\n" +
         observation + "}\n";
}

TEST(ObservationSyntax, ParserErrorsSayWhatWasExpected) {
  EXPECT_EQ(errors_of(explicit_spec("  observation { state noise 0.1; }\n"
                                    "  observation { state noise 0.2; }\n")),
            std::vector<std::string>{"12:3: the catalog already has an observation model"});
  EXPECT_EQ(errors_of(explicit_spec("  observation { state fuzz 0.1; }\n")),
            std::vector<std::string>{"11:23: expected 'noise' or 'confusion' after 'state', "
                                     "found 'fuzz'"});
  EXPECT_EQ(errors_of(explicit_spec("  observation { state noise 0.1; state noise 0.2; }\n")),
            std::vector<std::string>{"11:34: the observation model already has a state model"});
  EXPECT_EQ(errors_of(explicit_spec("  observation { state noise 0.1; reward follows maybe; }\n")),
            std::vector<std::string>{
                "11:49: expected 'true' or 'observed' after 'reward follows', found 'maybe'"});
  EXPECT_EQ(errors_of(explicit_spec("  observation { state noise 0.1; reward is true; }\n")),
            std::vector<std::string>{"11:41: expected 'follows' after 'reward', found 'is'"});
  EXPECT_EQ(errors_of(explicit_spec(
                "  observation { state noise 0.1; reward follows true; reward follows true; }\n")),
            std::vector<std::string>{
                "11:55: the observation model already says what the reward follows"});
  EXPECT_EQ(errors_of(explicit_spec("  observation { noise 0.1; }\n")),
            std::vector<std::string>{"11:17: expected 'state noise', 'state confusion', 'object' "
                                     "or 'reward follows' in an observation model, found "
                                     "'noise'"});
}

TEST(ObservationSyntax, CheckerErrorsAreExactAndPlaced) {
  EXPECT_EQ(errors_of(explicit_spec("  observation { state noise 1; }\n")),
            std::vector<std::string>{"11:29: state noise is the probability that the observed "
                                     "state is wrong: it must be in [0, 1), not 1"});
  EXPECT_EQ(errors_of(explicit_spec("  observation { state noise -0.25; }\n")),
            std::vector<std::string>{"11:29: state noise is the probability that the observed "
                                     "state is wrong: it must be in [0, 1), not -1/4 (-0.25)"});
  EXPECT_EQ(errors_of(explicit_spec("  observation { reward follows observed; }\n")),
            std::vector<std::string>{"11:3: the observation model has no state model: add "
                                     "'state noise p;' or 'state confusion { ... }'"});
  EXPECT_EQ(errors_of(explicit_spec("  observation {\n"
                                    "    state confusion {\n"
                                    "      s1 -> 0.5: s1 + 0.4: s2;\n"
                                    "      s1 -> s1;\n"
                                    "      s3 -> s3;\n"
                                    "      s2 -> 3/2: s2 + -1/2: s1;\n"
                                    "    }\n"
                                    "  }\n")),
            (std::vector<std::string>{
                "13:13: probabilities sum to 9/10 (0.9), not 1",
                "14:7: state 's1' already has a row",
                "15:7: unknown state 's3'",
                "16:13: probability 3/2 (1.5) is greater than 1",
                "16:23: probability -1/2 (-0.5) is negative",
            }));
  EXPECT_EQ(errors_of(explicit_spec("  observation {\n"
                                    "    state confusion { s1 -> s1 + s2; }\n"
                                    "  }\n")),
            (std::vector<std::string>{
                "12:29: probabilities sum to 2, not 1",
                "12:5: the confusion matrix has no row for state 's2'",
            }));
  EXPECT_EQ(errors_of(explicit_spec("  observation { state confusion { s1 -> s1; s2 -> a; } }\n")),
            std::vector<std::string>{"11:51: unknown state 'a'"});
}

TEST(ObservationSyntax, EachKindOfModelHasItsOwnSensor) {
  const std::string one_state =
      "mdp m { states s; actions a; s, a -> s; }\n"
      "catalog { context c = base; observation { state noise 0.1; } }\n";
  EXPECT_EQ(errors_of(one_state),
            std::vector<std::string>{"2:55: with a single state the observed state cannot be "
                                     "wrong: the state noise must be 0"});
  const std::string factored =
      "mdp m { var x : [0 .. 2]; actions a; [a] true -> (x' = mod(x + 1, 3)); }\n"
      "catalog {\n"
      "  context c { reward x == 2 : 1; }\n"
      "  observation { state confusion { s -> s; } }\n"
      "}\n";
  EXPECT_EQ(errors_of(factored),
            std::vector<std::string>{"4:17: a confusion matrix names states, so it needs an "
                                     "explicit model ('states ...'); write 'state noise p;' "
                                     "for this model"});
  const std::string continuous =
      "mdp m {\n"
      "  continuous x : [0 .. 1];\n"
      "  actions go;\n"
      "  dynamics [go] { }\n"
      "  region r = x <= 0.5;\n"
      "}\n"
      "catalog { context c { reward r : 1; } observation { state noise 0.1; } }\n";
  EXPECT_EQ(errors_of(continuous),
            (std::vector<std::string>{
                "7:65: a continuous model's sensor is described per object: 'object NAME (x, y) "
                "{ noise a + b * d + c * d * d; detection p; }'",
                "7:39: the observation model has no objects: add 'object NAME (x, y) { noise "
                "sigma; }' for the variables the sensor measures"}));
  EXPECT_EQ(errors_of(explicit_spec("  observation { object o (s1) { detection 0.5; } }\n")),
            std::vector<std::string>{"11:17: objects measure continuous variables; a discrete "
                                     "model's sensor is 'state noise p;' or 'state confusion { "
                                     "... }'"});
}

TEST(ObservationSyntax, TheWordsAreContextual) {
  // States and actions may be called like the block's words.
  const model::ModelIR ir = test::check_spec_text_ir(
      "mdp m {\n"
      "  states observation, state, noise, confusion, follows, observed;\n"
      "  actions state;\n"
      "  default self;\n"
      "  observation, state -> noise;\n"
      "}\n"
      "catalog {\n"
      "  context c { reward observed : 1; }\n"
      "  observation { state noise 1/3; }\n"
      "}\n");
  EXPECT_EQ(ir.state_names.size(), 6U);
  EXPECT_EQ(ir.observation.kind, ObservationSpec::Kind::kSymmetric);
  EXPECT_EQ(ir.observation.noise, Rational(1, 3));
  EXPECT_FALSE(ir.observation.reward_follows_observed);
}

TEST(ObservationSyntax, SoundBlocksBecomeTheModel) {
  const model::ModelIR matrix = test::check_spec_text_ir(kMatrixSpec);
  ASSERT_EQ(matrix.observation.kind, ObservationSpec::Kind::kMatrix);
  const std::vector<Rational> expected = {Rational(4, 5),  Rational(1, 5), Rational(0),
                                          Rational(1, 10), Rational(4, 5), Rational(1, 10),
                                          Rational(0),     Rational(0),    Rational(1)};
  EXPECT_EQ(matrix.observation.confusion, expected);
  EXPECT_TRUE(matrix.observation.reward_follows_observed);

  const model::ExplicitModel shipped =
      test::explore_spec_file(std::string(OASIS_SOURCE_DIR) + "/specs/discrete_tracking.oasis");
  EXPECT_EQ(shipped.observation.kind, ObservationSpec::Kind::kSymmetric);
  EXPECT_EQ(shipped.observation.noise, Rational(7, 10));
  EXPECT_FALSE(shipped.observation.reward_follows_observed);

  const model::ModelIR none = test::check_spec_text_ir(explicit_spec(""));
  EXPECT_EQ(none.observation.kind, ObservationSpec::Kind::kNone);
}

// ---- carriers -----------------------------------------------------------------------------

TEST(ObservationCatalog, TheBinaryFileCarriesEveryKind) {
  model::CatalogData matrix = test::compiled_catalog(test::explore_spec_text(kMatrixSpec));
  ASSERT_EQ(matrix.observation, rt::ObservationKind::kMatrix);
  EXPECT_EQ(matrix.confusion, (std::vector<double>{0.8, 0.2, 0.0, 0.1, 0.8, 0.1, 0.0, 0.0, 1.0}));
  EXPECT_EQ(matrix.reward_source, rt::RewardSource::kObservedState);
  const std::string bytes = codegen::binary_catalog(matrix);
  const rt::LoadedCatalog loaded = rt::LoadedCatalog::from_bytes(bytes.data(), bytes.size());
  ASSERT_TRUE(loaded.ok()) << loaded.error();
  const rt::ObservationModel& obs = loaded.view().observation;
  EXPECT_EQ(obs.kind, rt::ObservationKind::kMatrix);
  ASSERT_NE(obs.confusion, nullptr);
  EXPECT_EQ(std::vector<double>(obs.confusion, obs.confusion + 9), matrix.confusion);
  EXPECT_EQ(obs.reward_source, rt::RewardSource::kObservedState);
  EXPECT_NE(loaded.view().abstractions[1].state_transitions.choice_begin, nullptr);

  // The shipped spec: symmetric, p_correct 1 - 0.7.
  model::CatalogData shipped = test::compiled_catalog(
      test::explore_spec_file(std::string(OASIS_SOURCE_DIR) + "/specs/discrete_tracking.oasis"));
  const std::string shipped_bytes = codegen::binary_catalog(shipped);
  const rt::LoadedCatalog symmetric =
      rt::LoadedCatalog::from_bytes(shipped_bytes.data(), shipped_bytes.size());
  ASSERT_TRUE(symmetric.ok()) << symmetric.error();
  EXPECT_EQ(symmetric.view().observation.kind, rt::ObservationKind::kSymmetric);
  EXPECT_EQ(symmetric.view().observation.p_correct, 0.3);
  EXPECT_EQ(symmetric.view().observation.confusion, nullptr);
  EXPECT_EQ(symmetric.view().observation.reward_source, rt::RewardSource::kTrueState);

  // No observation block: no robust section, no observation sections.
  model::CatalogData none = test::compiled_catalog(test::explore_spec_text(explicit_spec("")));
  const std::string none_bytes = codegen::binary_catalog(none);
  EXPECT_EQ(none_bytes.find("\x08\x00\x00\x00\xff\xff\xff\xff", 0, 8), std::string::npos);
  const rt::LoadedCatalog plain =
      rt::LoadedCatalog::from_bytes(none_bytes.data(), none_bytes.size());
  ASSERT_TRUE(plain.ok()) << plain.error();
  EXPECT_FALSE(plain.view().has_robust_section());
}

TEST(ObservationCatalog, RobustOnTheCommandLineOverridesTheSpecsNoise) {
  model::CatalogData matrix = test::compiled_catalog(test::explore_spec_text(kMatrixSpec), 0.6);
  EXPECT_EQ(matrix.observation, rt::ObservationKind::kSymmetric);
  EXPECT_EQ(matrix.p_correct, 0.6);
  EXPECT_TRUE(matrix.confusion.empty());
  EXPECT_EQ(matrix.reward_source, rt::RewardSource::kObservedState) << "the spec's stays";
  std::string why;
  EXPECT_TRUE(rt::validate(matrix.view(), &why)) << why;
}

TEST(ObservationCatalog, AFactoredModelWithOneStateCannotBeNoisy) {
  const model::ExplicitModel model = test::explore_spec_text(
      "mdp m { var x : [0 .. 0]; actions a; [a] true -> true; }\n"
      "catalog { context c { reward x == 0 : 1; } observation { state noise 0.5; } }\n");
  std::string error;
  EXPECT_FALSE(pipeline::build_catalog(model, 1, {}, error));
  EXPECT_NE(error.find("single state"), std::string::npos) << error;
}

// The spec compiled by oasisc into all three carriers: the binary file, the JSON and the C++
// tables (compiled and linked into a program that compares them with the loaded file).
TEST(ObservationCatalog, EveryCarrierCarriesTheSameModel) {
  const test::ScratchDirectory scratch("oasis_observation");
  const std::filesystem::path spec = scratch.path() / "ring.oasis";
  std::ofstream(spec) << kMatrixSpec;
  const std::filesystem::path out = scratch.path() / "out";
  const auto compiled = test::run_oasisc("compile " + spec.string() + " -o " + out.string() +
                                         " --format bin,json,cpp --progress never");
  ASSERT_EQ(compiled.status, 0) << compiled.output;

  std::ifstream json_file(out / "ring.json");
  const nlohmann::json json = nlohmann::json::parse(json_file);
  const nlohmann::json& observation = json["observation"];
  EXPECT_EQ(observation["kind"], "matrix");
  EXPECT_EQ(observation["reward_follows"], "observed");
  EXPECT_EQ(observation["confusion"],
            nlohmann::json::parse("[[0.8, 0.2, 0.0], [0.1, 0.8, 0.1], [0.0, 0.0, 1.0]]"));

  const std::filesystem::path program = scratch.path() / "compare.cpp";
  std::ofstream(program) << R"(#include <cstdio>
#include <string>
#include "oasis/rt/catalog_file.hpp"
#include "ring_catalog.hpp"
int main(int, char** argv) {
  const oasis::rt::LoadedCatalog file = oasis::rt::LoadedCatalog::from_file(argv[1]);
  if (!file.ok()) { std::puts(file.error().c_str()); return 1; }
  const oasis::rt::ObservationModel& a = ring::catalog().observation;
  const oasis::rt::ObservationModel& b = file.view().observation;
  std::string why;
  if (!oasis::rt::validate(ring::catalog(), &why)) { std::puts(why.c_str()); return 2; }
  if (a.kind != oasis::rt::ObservationKind::kMatrix || a.kind != b.kind ||
      a.reward_source != oasis::rt::RewardSource::kObservedState ||
      a.reward_source != b.reward_source || a.confusion == nullptr) return 3;
  for (int k = 0; k < 9; ++k)
    if (a.confusion[k] != b.confusion[k]) return 4;
  if (ring::catalog().abstractions[0].state_transitions.num_edges == 0) return 5;
  std::puts("same");
  return 0;
}
)";
  const std::filesystem::path binary = scratch.path() / "compare";
  const std::string build =
      std::string(OASIS_CXX_COMPILER) + " -std=c++17 -Wall -Wextra -Werror -I " + OASIS_SOURCE_DIR +
      "/runtime/include -I " + out.string() + " " + program.string() + " " +
      (out / "ring_catalog.cpp").string() + " -o " + binary.string() + " 2>&1";
  ASSERT_EQ(std::system(build.c_str()), 0) << build;
  const std::string run = binary.string() + " " + (out / "ring.bin").string();
  EXPECT_EQ(std::system(run.c_str()), 0) << run;
}

}  // namespace
}  // namespace oasis
