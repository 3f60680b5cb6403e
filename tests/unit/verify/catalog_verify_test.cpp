// `oasisc verify` checks everything a catalog carries: a valid catalog with any one item
// changed (and the file otherwise sound: it loads, its checksum is right) is rejected at the
// right item, and an untouched one passes.

#include <filesystem>
#include <fstream>
#include <functional>
#include <string>

#include <gtest/gtest.h>

#include "../../support/run_oasisc.hpp"
#include "../../support/scratch_directory.hpp"
#include "../../support/spec_models.hpp"
#include "codegen/binary_catalog.hpp"
#include "formats/model_file.hpp"
#include "oasis/rt/catalog_file.hpp"
#include "pipeline/discrete_catalog.hpp"
#include "verify/discrete_catalog_check.hpp"

namespace oasis {
namespace {

const std::string kSpec = std::string(OASIS_SOURCE_DIR) + "/specs/discrete_tracking.oasis";

// The verdicts for `catalog` after a round trip through the binary file (so the change is
// one a file can carry: it must still load).
std::vector<verify::CatalogCheck> verdicts(const model::ExplicitModel& model,
                                           model::CatalogData& catalog,
                                           const verify::CatalogCheckOptions& options = {}) {
  const std::string bytes = codegen::binary_catalog(catalog);
  const rt::LoadedCatalog loaded = rt::LoadedCatalog::from_bytes(bytes.data(), bytes.size());
  EXPECT_TRUE(loaded.ok()) << "the changed catalog must still be a sound file: " << loaded.error();
  if (!loaded.ok()) return {};
  return verify::check_discrete_catalog(model, loaded.view(), options);
}

// The first failing item and its verdict, or "" when everything holds.
std::string first_failure(const std::vector<verify::CatalogCheck>& checks) {
  for (const verify::CatalogCheck& check : checks)
    if (!check.ok) return check.item + ": " + check.verdict;
  return "";
}

struct Change {
  const char* name;
  std::function<void(model::CatalogData&)> apply;
  const char* expected;  // a piece of the failure message
};

class CatalogVerify : public ::testing::Test {
 protected:
  void expect_rejected(const model::ExplicitModel& model, const model::CatalogData& good,
                       const Change& change) {
    model::CatalogData bad = good;
    change.apply(bad);
    const std::string failure = first_failure(verdicts(model, bad));
    EXPECT_NE(failure, "") << change.name << " was not caught";
    EXPECT_NE(failure.find(change.expected), std::string::npos) << change.name << ": " << failure;
  }

  const model::ExplicitModel model_ = test::explore_spec_file(kSpec);
};

TEST_F(CatalogVerify, AnUntouchedCatalogPasses) {
  for (const std::optional<double> p_correct : {std::optional<double>{}, std::optional(0.9)}) {
    model::CatalogData catalog = test::compiled_catalog(model_, p_correct);
    const auto checks = verdicts(model_, catalog, {.robust_p_correct = p_correct});
    ASSERT_EQ(checks.size(), 5U);
    EXPECT_EQ(first_failure(checks), "");
  }
}

TEST_F(CatalogVerify, EveryChangedItemIsCaught) {
  const model::CatalogData good =
      test::compiled_catalog(model_);  // with the spec's observation model
  const std::vector<Change> changes = {
      {"observation noise", [](auto& c) { c.p_correct = 0.5; }, "p_correct is 0.5"},
      {"reward source", [](auto& c) { c.reward_source = rt::RewardSource::kObservedState; },
       "reward follows the observed state"},
      {"no observation model",
       [](auto& c) {
         c.observation = rt::ObservationKind::kNone;
         for (auto& abstraction : c.abstractions)
           abstraction.state_transitions = {};
       },
       "observation model is none"},
      {"policy", [](auto& c) { c.abstractions[0].policy[0] ^= 1U; }, "not optimal"},
      {"block reward", [](auto& c) { c.abstractions[0].block_reward[1] = 2.0; }, "has reward"},
      {"R^Z", [](auto& c) { c.abstractions[1].reward[0] += 0.5; }, "R^Z"},
      {"value", [](auto& c) { c.abstractions[1].value[0] += 0.01; }, "value[0]"},
      {"transition probability",
       [](auto& c) {  // move mass between the two targets of a row, keeping its sum
         auto& q = c.abstractions[0].quotient;
         for (std::size_t r = 0; r + 1 < q.choice_begin.size(); ++r) {
           if (q.choice_begin[r + 1] - q.choice_begin[r] == 2) {
             q.probability[q.choice_begin[r]] -= 0.25;
             q.probability[q.choice_begin[r] + 1] += 0.25;
             return;
           }
         }
       },
       "probability"},
      {"transition target",
       [](auto& c) {
         auto& q = c.abstractions[1].quotient;
         q.target[0] = 1 - q.target[0];
       },
       "block"},
      {"switching",
       [](auto& c) {
         c.switching[0] = 0.7;
         c.switching[1] = 0.3;
       },
       "switching[0][0]"},
      {"prior",
       [](auto& c) {
         c.prior[0] = 0.6;
         c.prior[1] = 0.4;
       },
       "prior[0]"},
      {"action name", [](auto& c) { c.action_names[1] = "X"; }, "action 1"},
      {"state name", [](auto& c) { c.state_names[2] = "s9"; }, "state 2"},
      {"context name", [](auto& c) { c.abstractions[1].context = "elsewhere"; },
       "context 'elsewhere'"},
      {"catalog name", [](auto& c) { c.name = "other"; }, "named 'other'"},
      {"robust section",
       [](auto& c) {
         auto& st = c.abstractions[0].state_transitions;
         for (std::size_t r = 0; r + 1 < st.choice_begin.size(); ++r) {
           if (st.choice_begin[r + 1] - st.choice_begin[r] == 2) {
             st.probability[st.choice_begin[r]] -= 0.25;
             st.probability[st.choice_begin[r] + 1] += 0.25;
             return;
           }
         }
       },
       "robust section"},
      {"partition",
       [](auto& c) {
         auto& abs = c.abstractions[0];
         abs.block_of = {0, 1, 1};  // object_at_s1's partition in object_at_s3's place
       },
       "FAILED"},
  };
  for (const Change& change : changes)
    expect_rejected(model_, good, change);
}

TEST_F(CatalogVerify, ObservationModelsAreComparedWithTheSpec) {
  // A confusion matrix: an entry moved within its row (still a distribution) is caught.
  const model::ExplicitModel ring = test::explore_spec_text(R"(
mdp ring {
  states a, b;
  actions go;
  a, go -> b;
  b, go -> a;
}
catalog {
  context at_a { reward a : 1; }
  context at_b { reward b : 1; }
  switching stay 0.9;
  observation { state confusion { a -> 3/4: a + 1/4: b; b -> b; } reward follows observed; }
}
)");
  model::CatalogData matrix = test::compiled_catalog(ring);
  EXPECT_EQ(first_failure(verdicts(ring, matrix)), "");
  EXPECT_EQ(verdicts(ring, matrix)[2].verdict,
            "confusion matrix, reward follows the observed state");
  matrix.confusion[0] = 0.5;
  matrix.confusion[1] = 0.5;
  EXPECT_NE(first_failure(verdicts(ring, matrix)).find("confusion[a][a] is 0.5, the spec says 3/4"),
            std::string::npos)
      << first_failure(verdicts(ring, matrix));

  // A spec without an observation model: its catalog has none, unless compiled with --robust,
  // which verify is then told.
  std::string text = test::read_text_file(kSpec);
  const std::size_t block = text.find("\n\n  // The sensor of Table I");
  ASSERT_NE(block, std::string::npos);
  text.erase(block + 1, text.rfind("}\n") - block - 1);
  const model::ExplicitModel plain = test::explore_spec_text(text);
  EXPECT_EQ(plain.observation.kind, model::ObservationSpec::Kind::kNone);
  model::CatalogData none = test::compiled_catalog(plain);
  EXPECT_EQ(first_failure(verdicts(plain, none)), "");
  model::CatalogData robust = test::compiled_catalog(plain, 0.9);
  EXPECT_NE(first_failure(verdicts(plain, robust))
                .find("observation model: FAILED: the catalog's observation model is symmetric, "
                      "the spec's none (compiled with --robust P?"),
            std::string::npos)
      << first_failure(verdicts(plain, robust));
  EXPECT_EQ(first_failure(verdicts(plain, robust, {.robust_p_correct = 0.9})), "");
  EXPECT_NE(first_failure(verdicts(plain, robust, {.robust_p_correct = 0.8})).find("--robust 0.8"),
            std::string::npos);
  // And the spec's own model, overridden on the command line.
  model::CatalogData overridden = test::compiled_catalog(model_, 0.9);
  EXPECT_NE(first_failure(verdicts(model_, overridden)).find("not 1 - noise = 3/10"),
            std::string::npos)
      << first_failure(verdicts(model_, overridden));
  EXPECT_EQ(first_failure(verdicts(model_, overridden, {.robust_p_correct = 0.9})), "");
}

TEST_F(CatalogVerify, ImportedModelsAndHorizonsAreCheckedToo) {
  SourceManager sources;
  std::ostringstream messages;
  DiagnosticEngine diagnostics(sources, messages);
  const auto coin = formats::read_model_file(
      std::string(OASIS_SOURCE_DIR) + "/tests/data/formats/coin.aut", sources, diagnostics, {});
  ASSERT_TRUE(coin) << messages.str();
  model::CatalogData catalog = test::compiled_catalog(*coin);
  EXPECT_EQ(first_failure(verdicts(*coin, catalog)), "");
  catalog.switching = {0.5};  // not a distribution: refused by the loader itself
  const std::string bytes = codegen::binary_catalog(catalog);
  EXPECT_FALSE(rt::LoadedCatalog::from_bytes(bytes.data(), bytes.size()).ok());

  std::string text = test::read_text_file(kSpec);
  text.replace(text.find("discount 0.9;"), 13, "horizon 4;");
  const model::ExplicitModel horizon = test::explore_spec_text(text);
  model::CatalogData planned = test::compiled_catalog(horizon);
  EXPECT_EQ(first_failure(verdicts(horizon, planned)), "");
  planned.abstractions[0].value[0] += 0.5;
  EXPECT_NE(first_failure(verdicts(horizon, planned)).find("4-step value"), std::string::npos);
}

TEST_F(CatalogVerify, TheCommandLineRejectsAnEditedFile) {
  const test::ScratchDirectory scratch("oasis_catalog_verify");
  model::CatalogData catalog = test::compiled_catalog(model_);
  catalog.spec_hash = rt::spec_hash(test::read_text_file(kSpec));
  const auto good = scratch.path() / "good.bin";
  const auto bad = scratch.path() / "bad.bin";
  std::ofstream(good, std::ios::binary) << codegen::binary_catalog(catalog);
  catalog.abstractions[1].policy[1] ^= 1U;
  std::ofstream(bad, std::ios::binary) << codegen::binary_catalog(catalog);
  const auto passed = test::run_oasisc("verify " + kSpec + " " + good.string());
  EXPECT_EQ(passed.status, 0) << passed.output;
  const auto failed = test::run_oasisc("verify " + kSpec + " " + bad.string());
  EXPECT_EQ(failed.status, 1) << failed.output;
  EXPECT_NE(failed.output.find("context object_at_s1: FAILED"), std::string::npos) << failed.output;
}

TEST_F(CatalogVerify, TheShippedSpecCompilesAndVerifiesWithItsObservationModel) {
  const test::ScratchDirectory scratch("oasis_catalog_verify");
  const std::string out = (scratch.path() / "out").string();
  const std::string robust = (scratch.path() / "robust").string();
  ASSERT_EQ(test::run_oasisc("compile " + kSpec + " -o " + out + " --progress never").status, 0);
  const auto passed = test::run_oasisc("verify " + kSpec + " " + out + "/discrete_tracking.bin");
  EXPECT_EQ(passed.status, 0) << passed.output;
  EXPECT_NE(passed.output.find("observation model: symmetric, p_correct 1 - noise = 3/10 (0.3), "
                               "reward follows the true state"),
            std::string::npos)
      << passed.output;
  EXPECT_NE(passed.output.find("robust section ok"), std::string::npos) << passed.output;
  ASSERT_EQ(test::run_oasisc("compile " + kSpec + " -o " + robust +
                             " --format bin --robust 0.9 --progress never")
                .status,
            0);
  const std::string robust_bin = robust + "/discrete_tracking.bin";
  const auto refused = test::run_oasisc("verify " + kSpec + " " + robust_bin);
  EXPECT_EQ(refused.status, 1) << refused.output;
  EXPECT_NE(refused.output.find("observation model: FAILED"), std::string::npos) << refused.output;
  const auto accepted = test::run_oasisc("verify --robust 0.9 " + kSpec + " " + robust_bin);
  EXPECT_EQ(accepted.status, 0) << accepted.output;
}

}  // namespace
}  // namespace oasis
