// Continuous observation models (issue 12): `object NAME (x, y) { noise sigma(d); detection
// p; }` in a continuous spec's observation block is parsed and checked (every diagnostic with
// its message and place), carried by the binary file, the C++ tables and the JSON, checked by
// verify, and runs the runtime's noise-aware filter on the shipped Go1 catalog.

#include <sstream>
#include <string>
#include <vector>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "../../support/spec_models.hpp"
#include "codegen/binary_catalog.hpp"
#include "codegen/continuous_json.hpp"
#include "codegen/cpp_catalog.hpp"
#include "frontend/load_spec.hpp"
#include "oasis/rt/attention_filter.hpp"
#include "oasis/rt/catalog_file.hpp"
#include "pipeline/continuous_catalog.hpp"
#include "pipeline/continuous_catalog_data.hpp"
#include "verify/continuous_check.hpp"

namespace oasis {
namespace {

// A two-person plane whose catalog ends with `observation` (one or more lines, line 12 on).
std::string continuous_spec(const std::string& observation) {
  return "mdp m {\n"
         "  continuous x1 : [0 .. 4];\n"
         "  continuous y1 : [-3 .. 3];\n"
         "  continuous x2 : [0 .. 4];\n"
         "  const k = 0.01;\n"
         "  actions stay;\n"
         "  dynamics [stay] { }\n"
         "  region near = x1 <= 1;\n"
         "}\n"
         "catalog {\n"
         "  context c { reward near : 1; }\n" +
         observation + "}\n";
}

std::vector<std::string> errors_of(const std::string& source) {
  return test::spec_errors(source);
}

TEST(PositionNoiseSyntax, ObjectsBecomeTheModel) {
  const model::ModelIR ir = test::check_spec_text_ir(continuous_spec(
      "  observation {\n"
      "    object person (x1, y1) { noise 2 * k + k * d + 0.005 * d * d - (d * k) / 2; "
      "detection 0.9; }\n"
      "    object other (x2) { detection 1/2; }\n"
      "    reward follows observed;\n"
      "  }\n"));
  ASSERT_EQ(ir.observation.objects.size(), 2U);
  const model::MeasuredObject& person = ir.observation.objects[0];
  EXPECT_EQ(person.name, "person");
  EXPECT_EQ(person.variables, (std::vector<std::uint32_t>{0, 1}));
  EXPECT_EQ(person.sigma[0], Rational(1, 50));
  EXPECT_EQ(person.sigma[1], Rational(1, 200));
  EXPECT_EQ(person.sigma[2], Rational(1, 200));
  EXPECT_EQ(person.detection, Rational(9, 10));
  const model::MeasuredObject& other = ir.observation.objects[1];
  EXPECT_EQ(other.variables, std::vector<std::uint32_t>{2});
  EXPECT_EQ(other.sigma[0], 0);  // no noise: only missed detections
  EXPECT_EQ(other.detection, Rational(1, 2));
  EXPECT_TRUE(ir.observation.reward_follows_observed);
  EXPECT_EQ(ir.observation.kind, model::ObservationSpec::Kind::kNone);
}

TEST(PositionNoiseSyntax, ParserErrorsSayWhatWasExpected) {
  EXPECT_EQ(errors_of(continuous_spec("  observation { object (x1) { } }\n")),
            std::vector<std::string>{"12:24: expected an object name after 'object', found '('"});
  EXPECT_EQ(
      errors_of(continuous_spec("  observation { object p x1 { } }\n")),
      std::vector<std::string>{"12:26: expected '(' before the object's variables, found 'x1'"});
  EXPECT_EQ(errors_of(continuous_spec("  observation { object p (x1) { sigma 1; } }\n")),
            std::vector<std::string>{
                "12:33: expected 'noise' or 'detection' in an object, found 'sigma'"});
  EXPECT_EQ(errors_of(continuous_spec("  observation { object p (x1) { noise 1; noise 2; } }\n")),
            std::vector<std::string>{"12:42: the object already has a noise"});
}

TEST(PositionNoiseSyntax, CheckerErrorsAreExactAndPlaced) {
  EXPECT_EQ(errors_of(continuous_spec("  observation {\n"
                                      "    object p (x1, y1) { noise d * d * d; detection 0; }\n"
                                      "    object q (y1, k, z) { noise x1; }\n"
                                      "    object p (x1) { noise 1 / d; }\n"
                                      "    object r (x2) { noise 0.1 - 0.1 * d; }\n"
                                      "  }\n")),
            (std::vector<std::string>{
                "13:31: sigma(d) must be at most quadratic in the distance d: a + b * d + c * d "
                "* d",
                "13:52: the detection probability must be in (0, 1], not 0",
                "14:15: variable 'y1' is already measured by another object",
                "14:19: constant 'k' is not a continuous variable",
                "14:22: unknown variable 'z'",
                "14:33: continuous variable 'x1' cannot be used in a constant expression",
                "15:12: object 'p' is already declared",
                "15:15: variable 'x1' is already measured by another object",
                "15:27: sigma(d) is a polynomial in the distance d: numbers, constants, d, '+', "
                "'-', '*' and division by a number (a + b * d + c * d * d)",
                "16:27: sigma(d) is negative at d = 4, within the object's reach (d from 0 to 4)",
            }));
}

// The shipped Go1 spec declares its camera; a coarse catalog of it carries the model.
const pipeline::ContinuousCatalog& go1_catalog() {
  static const pipeline::ContinuousCatalog catalog = [] {
    pipeline::ContinuousCatalogOptions options;
    options.abstraction.target.epsilon = 0.3;
    std::string error;
    auto built = pipeline::build_continuous_catalog(test::shipped_go1_spec(), 5, options, error);
    EXPECT_TRUE(built) << error;
    return std::move(*built);
  }();
  return catalog;
}

void expect_go1_noise(const rt::PositionNoise& noise) {
  ASSERT_EQ(noise.num_objects, 2U);
  EXPECT_EQ(noise.object_of[0], 0U);
  EXPECT_EQ(noise.object_of[1], 0U);
  EXPECT_EQ(noise.object_of[2], 1U);
  EXPECT_EQ(noise.object_of[3], 1U);
  EXPECT_EQ(noise.sigma[3 + 2], 0.005);
  EXPECT_EQ(noise.detection[1], 0.9);
  EXPECT_NEAR(rt::object_sigma(noise, 0, 2.0), 0.002 + 0.004 + 0.02, 1e-15);
}

TEST(PositionNoiseCatalog, TheBinaryFileAndTheJsonCarryIt) {
  model::CatalogData data = pipeline::continuous_catalog_data(go1_catalog(), false);
  expect_go1_noise(data.view().observation.position);
  const std::string bytes = codegen::binary_catalog(data);
  const rt::LoadedCatalog file = rt::LoadedCatalog::from_bytes(bytes.data(), bytes.size());
  ASSERT_TRUE(file.ok()) << file.error();
  expect_go1_noise(file.view().observation.position);
  EXPECT_TRUE(file.view().has_noise_model());
  const auto json = nlohmann::json::parse(codegen::continuous_catalog_json(go1_catalog(), false));
  const auto& objects = json.at("observation").at("objects");
  ASSERT_EQ(objects.size(), 2U);
  EXPECT_EQ(objects[1].at("variables"), (std::vector<std::string>{"x2", "y2"}));
  EXPECT_EQ(objects[0].at("sigma"), (std::vector<double>{0.002, 0.002, 0.005}));
  EXPECT_EQ(json.at("observation").at("reward_follows"), "true");
}

TEST(PositionNoiseCatalog, TheCppTablesCarryIt) {
  const model::CatalogData data = pipeline::continuous_catalog_data(go1_catalog(), false);
  const codegen::CppSources cpp = codegen::cpp_catalog(data, "go1", "go1_treat.oasis");
  EXPECT_NE(cpp.source.find("const double kObjectSigma[] = {"), std::string::npos);
  EXPECT_NE(cpp.source.find("{2u, kObjectOf, kObjectSigma, kObjectDetection}"), std::string::npos);
}

TEST(PositionNoiseCatalog, VerifyComparesItWithTheSpec) {
  model::CatalogData data = pipeline::continuous_catalog_data(go1_catalog(), false);
  const model::ModelIR ir = test::shipped_go1_spec();
  const auto verdict = [&](const rt::CatalogView& view) {
    for (const verify::CatalogCheck& check : verify::check_continuous_catalog(ir, view))
      if (check.item == "observation model") return check.verdict;
    return std::string("missing");
  };
  EXPECT_EQ(verdict(data.view()), "2 measured objects, sigma(d) and detection as the spec says");
  data.position.sigma[1] = 0.003;
  EXPECT_EQ(verdict(data.view()), "FAILED: object 'human1': sigma(d) coefficient 1 differs");
  data.position.sigma[1] = 0.002;
  data.position.object_of[2] = rt::kExactVariable;
  EXPECT_EQ(verdict(data.view()),
            "FAILED: object 'human2': variable 'x2' is not measured by it in the catalog");
  data.position = {};
  EXPECT_EQ(verdict(data.view()), "FAILED: the catalog has 0 measured objects, the spec 2");
}

// On the Go1 catalog, a reading of the holder just outside the reach region while the robot
// gets the treat's reward: Algorithm 1 blames the other person (whose reading happens to be
// in reach); the noise-aware filter weighs how far each reading is from its region.
TEST(PositionNoiseCatalog, TheNoiseAwareFilterWeighsReadingsNearTheRegionsEdge) {
  model::CatalogData data = pipeline::continuous_catalog_data(go1_catalog(), false);
  const rt::CatalogView view = data.view();
  rt::FilterOptions paper;
  rt::FilterOptions robust;
  robust.mode = rt::FilterMode::kNoiseAware;
  std::vector<double> paper_work(rt::AttentionFilter::workspace_size(view, paper));
  std::vector<double> robust_work(rt::AttentionFilter::workspace_size(view, robust));
  rt::AttentionFilter algorithm1(view, paper, paper_work.data(), paper_work.size());
  rt::AttentionFilter noise_aware(view, robust, robust_work.data(), robust_work.size());
  ASSERT_TRUE(noise_aware.ok());
  // Human 1 at 0.82 m (0.02 m past the region, sigma there 7 mm), human 2 at 0.5 m.
  const double reading[4] = {0.82, 0.0, 0.5, 0.1};
  algorithm1.start(reading, 4);
  noise_aware.start(reading, 4);
  EXPECT_EQ(algorithm1.step(reading, 4, 1.0, 0), rt::StepStatus::kOk);
  EXPECT_EQ(noise_aware.step(reading, 4, 1.0, 0), rt::StepStatus::kOk);
  EXPECT_EQ(algorithm1.belief(1), 1.0);
  EXPECT_GT(noise_aware.belief(0), 0.0);
  EXPECT_LT(noise_aware.belief(0), 0.5);  // human 2's reading is well inside
  EXPECT_LT(noise_aware.likelihood_error(), 1e-6);
  // Human 1 missed: prediction only.
  const double missed[4] = {std::nan(""), std::nan(""), 0.5, 0.1};
  EXPECT_EQ(noise_aware.step(missed, 4, 1.0, 0), rt::StepStatus::kMissingObservation);
}

}  // namespace
}  // namespace oasis
