// `oasisc fit` end to end on the small files of tests/data/fit/: each fit prints its
// estimate, interval and a fragment that pastes into the spec; malformed CSVs give
// file:line:col errors with the line and a caret, and exit status 1.

#include <cstdlib>
#include <sstream>
#include <string>

#include <gtest/gtest.h>

#include "../../support/run_oasisc.hpp"
#include "../../support/spec_models.hpp"
#include "fit/csv_table.hpp"
#include "fit/forward_algorithm.hpp"
#include "fit/spec_fragment.hpp"
#include "fit/switching_fit.hpp"
#include "fit/switching_log.hpp"
#include "pipeline/discrete_catalog.hpp"

namespace oasis {
namespace {

const std::string kData = std::string(OASIS_SOURCE_DIR) + "/tests/data/fit";
const std::string kSpec = kData + "/tracking.oasis";

std::string data(const std::string& name) {
  return kData + "/" + name;
}

// The switching fit through the library on the same files, for the expected fragment.
fit::SwitchingFit library_fit(const std::string& spec, const std::string& log,
                              bool with_spec_noise) {
  SourceManager sources;
  std::ostringstream messages;
  DiagnosticEngine diagnostics(sources, messages);
  const model::ExplicitModel model = test::explore_spec_file(spec);
  std::string error;
  const auto catalog = pipeline::build_catalog(model, 0, {}, error);
  EXPECT_TRUE(catalog) << error;
  const auto table = fit::read_csv(log, sources, diagnostics);
  EXPECT_TRUE(table) << messages.str();
  std::vector<fit::LoggedRun> runs;
  EXPECT_TRUE(fit::read_switching_log(*table, {catalog->state_names, catalog->action_names}, runs,
                                      diagnostics))
      << messages.str();
  fit::FilterModel filter = fit::filter_model(*catalog, model);
  if (with_spec_noise) {
    EXPECT_EQ(catalog->observation, rt::ObservationKind::kSymmetric);
    filter.noise.kind = fit::StateNoise::Kind::kSymmetric;
    filter.noise.p_correct = catalog->p_correct;
  }
  const auto result = fit::fit_switching(filter, runs, {}, error);
  EXPECT_TRUE(result) << error;
  return result ? *result : fit::SwitchingFit{};
}

// The spec with its switching line replaced by `fragment` checks.
void expect_pastes(const std::string& fragment, const std::string& replaced) {
  std::string spec = test::read_text_file(kSpec);
  const std::size_t at = spec.find(replaced);
  ASSERT_NE(at, std::string::npos);
  spec.replace(at, replaced.size(), fragment);
  test::check_spec_text_ir(spec);
}

TEST(FitCli, SwitchingPrintsTheFitAndAFragment) {
  const auto result = test::run_oasisc("fit switching " + kSpec + " " + data("switching_log.csv") +
                                       " --progress never");
  ASSERT_EQ(result.status, 0) << result.output;
  const fit::SwitchingFit expected = library_fit(kSpec, data("switching_log.csv"), false);
  EXPECT_NEAR(expected.p_stay, 0.8, 0.06);  // 4 runs of 100 steps
  EXPECT_NE(result.output.find("4 runs, 400 steps (1 file), 2 contexts"), std::string::npos)
      << result.output;
  EXPECT_NE(result.output.find("(profile likelihood)"), std::string::npos) << result.output;
  const std::string fragment = fit::switching_stay_fragment(expected.p_stay);
  EXPECT_NE(result.output.find("\n" + fragment), std::string::npos) << result.output;
  expect_pastes(fragment, "switching stay 0.8;\n");
}

TEST(FitCli, SwitchingFullMatrixFragmentPastes) {
  const auto result = test::run_oasisc("fit switching " + kSpec + " " + data("switching_log.csv") +
                                       " --full --progress never");
  ASSERT_EQ(result.status, 0) << result.output;
  const std::size_t at = result.output.find("switching {\n");
  ASSERT_NE(at, std::string::npos) << result.output;
  const std::string fragment = result.output.substr(at, result.output.find("}\n", at) + 2 - at);
  expect_pastes(fragment, "switching stay 0.8;\n");
}

TEST(FitCli, SwitchingReadsOasisSimTraces) {
  // `oasis-sim table1 --csv-dir` columns: t,true_context,inferred_ml,true_state,observed_state,
  // reward (one run per file, no actions).
  const auto result = test::run_oasisc("fit switching " + kSpec + " " + data("sim_trace.csv") +
                                       " --progress never");
  ASSERT_EQ(result.status, 0) << result.output;
  EXPECT_NE(result.output.find("1 run, 200 steps"), std::string::npos) << result.output;
  const fit::SwitchingFit expected = library_fit(kSpec, data("sim_trace.csv"), false);
  EXPECT_NE(result.output.find(fit::switching_stay_fragment(expected.p_stay)), std::string::npos)
      << result.output;
}

TEST(FitCli, SwitchingUsesTheSpecsObservationModel) {
  const std::string noisy = data("tracking_noisy.oasis");
  const auto result = test::run_oasisc("fit switching " + noisy + " " + data("switching_log.csv") +
                                       " --progress never");
  ASSERT_EQ(result.status, 0) << result.output;
  EXPECT_NE(result.output.find("joint forward algorithm"), std::string::npos) << result.output;
  EXPECT_NE(result.output.find("= 0.3 (from the spec)"), std::string::npos) << result.output;
  const fit::SwitchingFit expected = library_fit(noisy, data("switching_log.csv"), true);
  EXPECT_NE(result.output.find(fit::switching_stay_fragment(expected.p_stay)), std::string::npos)
      << result.output;
  // --paper ignores it.
  const auto paper = test::run_oasisc("fit switching " + noisy + " " + data("switching_log.csv") +
                                      " --paper --progress never");
  EXPECT_NE(paper.output.find("forward algorithm of Algorithm 1"), std::string::npos)
      << paper.output;
}

TEST(FitCli, NoisePrintsTheClosedFormAndAFragment) {
  // 2 of the 20 labelled pairs are wrong: sigma = 0.1 exactly.
  const auto result =
      test::run_oasisc("fit noise " + kSpec + " " + data("labels.csv") + " --progress never");
  ASSERT_EQ(result.status, 0) << result.output;
  EXPECT_NE(result.output.find("P(observed != true) = 0.1000  95% CI [0.0279, 0.3010] (Wilson "
                               "score; closed-form MLE, 2 of 20 wrong)"),
            std::string::npos)
      << result.output;
  const std::string fragment = "observation {\n  state noise 0.1;\n  reward follows true;\n}\n";
  EXPECT_NE(result.output.find(fragment), std::string::npos) << result.output;
  expect_pastes("switching stay 0.8;\n" + fragment, "switching stay 0.8;\n");

  const auto matrix = test::run_oasisc("fit noise " + kSpec + " " + data("labels.csv") +
                                       " --matrix --reward-follows observed --progress never");
  ASSERT_EQ(matrix.status, 0) << matrix.output;
  const std::string confusion =
      "observation {\n  state confusion {\n    s1 -> 1: s1;\n"
      "    s2 -> 0.7143: s2 + 0.2857: s3;\n    s3 -> 1: s3;\n  }\n"
      "  reward follows observed;\n}\n";
  EXPECT_NE(matrix.output.find(confusion), std::string::npos) << matrix.output;
  expect_pastes("switching stay 0.8;\n" + confusion, "switching stay 0.8;\n");
}

// Issue 28: labels that are all wrong fit a state noise of 1, which the spec language refuses
// ([0, 1)); no fragment that `oasisc check` would refuse is printed, and the status says so.
TEST(FitCli, NoiseOfAllWrongLabelsIsRefusedNotPrintedAsAFragment) {
  const auto result =
      test::run_oasisc("fit noise " + kSpec + " " + data("all_wrong.csv") + " --progress never");
  EXPECT_EQ(result.status, 1) << result.output;
  EXPECT_NE(result.output.find("error: the fitted state noise is 1: (nearly) every label is wrong"),
            std::string::npos)
      << result.output;
  EXPECT_EQ(result.output.find("state noise 1;"), std::string::npos) << result.output;
}

// The Go1 spec with its first object replaced by `object` checks.
void expect_object_pastes(const std::string& object) {
  std::string spec = test::read_text_file(std::string(OASIS_SOURCE_DIR) + "/specs/go1_treat.oasis");
  const std::string first =
      "object human1 (x1, y1) { noise 0.002 + 0.002 * d + 0.005 * d * d; "
      "detection 0.9; }\n";
  const std::size_t at = spec.find(first);
  ASSERT_NE(at, std::string::npos);
  spec.replace(at, first.size(), object);
  test::check_spec_text_ir(spec);
}

TEST(FitCli, DepthNoisePrintsSigmaAndAnObjectToPaste) {
  const auto result = test::run_oasisc("fit depth-noise " + data("calibration.csv") + " --at 1,3");
  ASSERT_EQ(result.status, 0) << result.output;
  EXPECT_NE(result.output.find("50 pairs (1 file), 5 distinct true distances in [1, 5] m"),
            std::string::npos)
      << result.output;
  EXPECT_NE(result.output.find("(Wald, observed information)"), std::string::npos) << result.output;
  // (Parsed by hand: std::regex trips a false -Wmaybe-uninitialized in the ASan build.)
  const std::string start = "object human1 (x1, y1) { noise ";
  const std::size_t at = result.output.find(start);
  ASSERT_NE(at, std::string::npos) << result.output;
  const std::string object = result.output.substr(at, result.output.find('\n', at) + 1 - at);
  EXPECT_NE(object.find(" * d "), std::string::npos) << object;
  EXPECT_NE(object.find(" * d * d; }"), std::string::npos) << object;
  expect_object_pastes(object);
  const std::string sigma_at_3 = "  d = 3 m: ";
  const std::size_t at_3 = result.output.find(sigma_at_3);
  ASSERT_NE(at_3, std::string::npos) << result.output;
  const double sigma = std::strtod(result.output.c_str() + at_3 + sigma_at_3.size(), nullptr);
  EXPECT_GE(sigma, 0.03) << result.output;
  EXPECT_LT(sigma, 0.08) << result.output;
  const auto named = test::run_oasisc("fit depth-noise " + data("calibration.csv") +
                                      " --degree 1 --object person --variables x2,y2 -o /dev/null");
  ASSERT_EQ(named.status, 0) << named.output;
  EXPECT_NE(named.output.find("object person (x2, y2) { noise "), std::string::npos)
      << named.output;
}

struct BadInput {
  std::string command;  // before the file
  std::string file;
  std::string message;  // after "<path>:"
};

TEST(FitCli, MalformedCsvsGiveLocatedErrors) {
  const std::string sw = "fit switching " + kSpec + " ";
  const BadInput cases[] = {
      {sw, "bad_reward.csv",
       "3:10: error: expected a number for the reward, found 'one'\n0,1,R,s2,one\n         ^~~\n"},
      {sw, "bad_state.csv",
       "2:7: error: unknown state 's7' (the spec's states: s1, s2, s3)\n0,0,L,s7,0\n      ^~\n"},
      {sw, "bad_action.csv",
       "2:5: error: unknown action 'Up' (the spec's actions: L, R)\n0,0,Up,s1,0\n    ^~\n"},
      {sw, "ragged.csv", "2:9: error: expected 5 cells as in the header, found 4\n0,0,L,s1\n"},
      {sw, "missing_column.csv",
       "1:1: error: the header has no column 'observed_state' (columns: run, step, action, "
       "state, reward)\n"},
      {sw, "bad_step.csv",
       "3:3: error: step 3 does not follow step 5 of run '0': steps must increase within a "
       "run\n0,3,R,s2,0\n  ^\n"},
      {"fit noise " + kSpec + " ", "unterminated.csv",
       "2:1: error: unterminated quoted cell\n\"s1,s2\n^\n"},
      {"fit noise " + kSpec + " ", "bad_state.csv",
       "1:1: error: the header has no column 'true_state'"},
      {"fit depth-noise ", "negative_distance.csv",
       "3:1: error: a distance cannot be negative\n-2.0,2.1\n^~~~\n"},
      {"fit depth-noise ", "labels.csv", "1:1: error: the header has no column 'true_m'"},
  };
  for (const BadInput& bad : cases) {
    const std::string path = data(bad.file);
    const auto result = test::run_oasisc(bad.command + path);
    SCOPED_TRACE(bad.command + bad.file);
    EXPECT_EQ(result.status, 1) << result.output;
    EXPECT_NE(result.output.find(path + ":" + bad.message), std::string::npos) << result.output;
  }
}

TEST(FitCli, ErrorsExitWithStatusOne) {
  EXPECT_EQ(test::run_oasisc("fit switching " + kSpec + " " + data("bad_reward.csv")).status, 1);
  EXPECT_EQ(test::run_oasisc("fit noise " + kSpec + " " + data("unterminated.csv")).status, 1);
  EXPECT_EQ(test::run_oasisc("fit depth-noise " + data("negative_distance.csv")).status, 1);
  EXPECT_EQ(test::run_oasisc("fit switching " + kSpec + " " + data("no_such_file.csv")).status, 1);
  // Two distances cannot identify a quadratic sigma(d).
  const auto few = test::run_oasisc("fit depth-noise " + data("two_distances.csv"));
  EXPECT_EQ(few.status, 1);
  EXPECT_NE(few.output.find("oasisc: fit depth-noise: error: sigma(d) of degree 2 needs pairs at 3 "
                            "or more distinct true distances, the calibration has 2"),
            std::string::npos)
      << few.output;
  // Bad usage is 2.
  EXPECT_EQ(test::run_oasisc("fit depth-noise " + data("calibration.csv") + " --degree 3").status,
            2);
  EXPECT_EQ(test::run_oasisc("fit").status, 2);
}

}  // namespace
}  // namespace oasis
