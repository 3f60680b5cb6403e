// `oasisc verify SPEC NAME.controller.json`: controllers compiled from small specs (a bounded
// safety objective in 1-D, an unbounded and an exactly-at-step reach-avoid objective in 2-D
// with sin, cos and uniform noise) pass the structural and the Monte-Carlo checks; every
// structural edit is caught and named by its JSON path; the reader names the path of every
// malformed value; planted unsound files fail the Monte-Carlo check (lower bounds raised to
// the upper ones or to 1, upper bounds lowered to 0, a controller that pushes the wrong way).
// The seeds are fixed and every planted error lies clear of the margin: nothing here is flaky.

#include <algorithm>
#include <cmath>
#include <fstream>
#include <functional>
#include <iterator>
#include <string>
#include <vector>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "../../support/run_oasisc.hpp"
#include "../../support/scratch_directory.hpp"
#include "../../support/spec_models.hpp"
#include "verify/controller_check.hpp"
#include "verify/controller_reader.hpp"

namespace oasis {
namespace {

using nlohmann::json;
using test::run_oasisc;

// x' = x + u/2 + w, w ~ N(0, 0.5): stay in [0, 8] for 5 steps. Every breakpoint and input
// value is an integer, so the file's doubles are exact whatever the compiler rounds.
const char* const kDrift = R"(
mdp drift {
  continuous x : [0 .. 8];
  input u in {-1, 0, 1};
  actions move;
  disturbance x ~ gaussian(0, 0.5);
  dynamics [move] {
    x' = x + 0.5 * u;
  }
  region inside = x >= 0 & x <= 8;
  objective safety inside steps 5;
  grid x : 8;
})";

// The same with three times the noise: every cell's true probability is well inside its
// bounds, below the upper bound by more than two margins.
const char* const kNoisy = R"(
mdp noisy {
  continuous x : [0 .. 8];
  input u in {-1, 0, 1};
  actions move;
  disturbance x ~ gaussian(0, 1.5);
  dynamics [move] {
    x' = x + u;
  }
  region inside = x >= 0 & x <= 8;
  objective safety inside steps 5;
  grid x : 8;
})";

// 2-D, nonlinear, a Gaussian and a uniform axis; breakpoints multiples of 1/2.
std::string reach_spec(const std::string& name, const std::string& horizon) {
  return "mdp " + name + R"( {
  continuous x : [0 .. 4];
  continuous y : [0 .. 4];
  input u in {-0.5, 0, 0.5};
  actions go;
  disturbance x ~ gaussian(0, 0.25);
  disturbance y in [-0.25 .. 0.25];
  dynamics [go] {
    x' = x + u + 0.1 * sin(y);
    y' = y + 0.25 + 0.05 * cos(x) * u;
  }
  region goal = x >= 1.5 & x <= 2.5 & y >= 3;
  objective reach goal)" +
         horizon + R"(;
  grid x : 8, y : 8;
})";
}

json read_json(const std::string& path) {
  std::ifstream in(path);
  return json::parse(std::string((std::istreambuf_iterator<char>(in)), {}));
}

bool contains(const std::string& text, const std::string& part) {
  return text.find(part) != std::string::npos;
}

class ControllerVerify : public ::testing::Test {
 protected:
  std::string path(const std::string& name) const { return (dir_.path() / name).string(); }

  std::string write_spec(const std::string& name, const std::string& text) const {
    const std::string spec = path(name + ".oasis");
    std::ofstream(spec) << text;
    return spec;
  }

  // Compiles `text` (model `name`); returns the controller file's path.
  std::string compile(const std::string& name, const std::string& text) const {
    const std::string spec = write_spec(name, text);
    const auto result = run_oasisc("compile " + spec + " -o " + path("out_" + name));
    EXPECT_EQ(result.status, 0) << result.output;
    return path("out_" + name) + "/" + name + ".controller.json";
  }

  std::string write_json(const std::string& name, const json& document) const {
    const std::string file = path(name);
    std::ofstream(file) << document.dump(1);
    return file;
  }

  test::ScratchDirectory dir_{"controller_verify_test"};
};

TEST_F(ControllerVerify, CompiledControllersPass) {
  struct Case {
    std::string name;
    std::string text;
    std::string summary;
  };
  const std::vector<Case> cases = {
      {"drift", kDrift, "Monte-Carlo: 8 cells x 2000 runs, margin 0.0492 at confidence 0.999"},
      {"reach", reach_spec("reach", ""), "Monte-Carlo: 40 cells x 2000 runs, margin 0.0531"},
      {"reach_at", reach_spec("reach_at", " at 6"), "Monte-Carlo: 40 cells x 2000 runs"}};
  for (const Case& c : cases) {
    SCOPED_TRACE(c.name);
    const std::string controller = compile(c.name, c.text);
    const auto result = run_oasisc("verify " + path(c.name + ".oasis") + " " + controller);
    EXPECT_EQ(result.status, 0) << result.output;
    EXPECT_TRUE(contains(result.output, c.summary)) << result.output;
    EXPECT_TRUE(contains(result.output, ": all within their bounds\n")) << result.output;
    for (const char* item :
         {"model: ", "grid: ", "actions: ", "objective: ", "bounds: ", "controller: "})
      EXPECT_TRUE(contains(result.output, item)) << result.output;
  }
}

TEST_F(ControllerVerify, OptionsAndDispatch) {
  const std::string spec = write_spec("drift", kDrift);
  const std::string controller = compile("drift", kDrift);
  const auto small = run_oasisc("verify " + spec + " " + controller +
                                " --cells 3 --samples 500 --seed 9 --confidence 0.99");
  EXPECT_EQ(small.status, 0) << small.output;
  // t = sqrt(ln(2 * 3 / 0.01) / 1000) = 0.0799...
  EXPECT_TRUE(contains(small.output,
                       "Monte-Carlo: 3 cells x 500 runs, margin 0.08 at "
                       "confidence 0.99: all within their bounds"))
      << small.output;
  // The same seed, the same report.
  EXPECT_EQ(run_oasisc("verify " + spec + " " + controller +
                       " --cells 3 --samples 500 --seed 9 "
                       "--confidence 0.99")
                .output,
            small.output);
  // Any name, when the format says so.
  const std::string renamed = write_json("renamed.json", read_json(controller));
  EXPECT_EQ(run_oasisc("verify " + spec + " " + renamed).status, 0);
  EXPECT_EQ(run_oasisc("verify " + spec + " " + controller + " --confidence 1").status, 2);
  EXPECT_EQ(run_oasisc("verify " + spec + " " + controller + " --samples 0").status, 2);
  EXPECT_EQ(run_oasisc("verify " + spec + " " + controller + " --max-steps -3").status, 2);
}

// The first failing item of `document` checked against `spec`, as "item: verdict".
std::string first_failure(const model::ModelIR& ir, const json& document) {
  std::string error;
  const auto file = verify::parse_controller_file(document.dump(), error);
  if (!file) return "unreadable: " + error;
  verify::MonteCarloSettings settings;
  settings.samples = 200;
  for (const verify::CatalogCheck& check : verify::check_controller(ir, *file, settings))
    if (!check.ok) return check.item + ": " + check.verdict;
  return "";
}

TEST_F(ControllerVerify, StructuralEditsAreCaught) {
  const model::ModelIR ir = test::check_spec_text_ir(kDrift);
  const json original = read_json(compile("drift", kDrift));
  ASSERT_EQ(first_failure(ir, original), "");
  struct Edit {
    const char* name;
    std::function<void(json&)> apply;
    const char* expected;
  };
  const std::vector<Edit> edits = {
      {"a breakpoint one ulp off",
       [](json& d) { d["grid"][0]["breaks"][3] = std::nextafter(3.0, 4.0); },
       "grid: grid[0].breaks[3] is 3.0000000000000004, not 3 (the nearest double to 3); 1 of "
       "the 9 breakpoints"},
      {"a breakpoint moved", [](json& d) { d["grid"][0]["breaks"][3] = 3.5; },
       "grid: grid[0].breaks[3] is 3.5, not 3"},
      {"breakpoints out of order", [](json& d) { d["grid"][0]["breaks"][3] = 1.5; },
       "grid: grid[0].breaks[3] is not above grid[0].breaks[2]"},
      {"another number of cells", [](json& d) { d["grid"][0]["cells"] = 7; },
       "grid: grid[0].cells is 7, but the spec's grid gives x 8 cells"},
      {"a renamed action", [](json& d) { d["actions"][1]["action"] = "jump"; },
       "actions: actions[1].action is \"jump\", expected \"move\""},
      {"an action's input value", [](json& d) { d["actions"][2]["inputs"][0] = 0.5; },
       "actions: actions[2].inputs[0] is 0.5, not 1"},
      {"actions swapped",
       [](json& d) { std::swap(d["actions"][0]["inputs"][0], d["actions"][2]["inputs"][0]); },
       "actions: actions[0].inputs[0] is 1, not -1"},
      {"an action missing", [](json& d) { d["actions"].erase(2); },
       "actions: the file has 2 actions; the spec's actions with dynamics and its inputs' "
       "values give 3"},
      {"an input's value", [](json& d) { d["inputs"][0]["values"][0] = -2; },
       "actions: inputs[0].values[0] is -2, not -1"},
      {"an input renamed", [](json& d) { d["inputs"][0]["name"] = "v"; },
       "actions: inputs[0].name is \"v\", the spec's \"u\""},
      {"lower above upper", [](json& d) { d["lower"][2] = d["upper"][2].get<double>() + 1e-9; },
       "bounds: not 0 <= lower <= upper <= 1 at cell 2"},
      {"upper above 1", [](json& d) { d["upper"][0] = 1.5; },
       "bounds: not 0 <= lower <= upper <= 1 at cell 0"},
      {"a negative lower bound", [](json& d) { d["lower"][7] = -0.25; },
       "bounds: not 0 <= lower <= upper <= 1 at cell 7"},
      {"a bound too many", [](json& d) { d["lower"].push_back(0.5); },
       "bounds: lower has 9 entries, the grid 8 cells"},
      {"an index out of range", [](json& d) { d["controller"][1][4] = 3; },
       "controller: controller[1][4] is 3, but there are 3 actions"},
      {"a step missing", [](json& d) { d["controller"].erase(4); },
       "controller: has 4 arrays, the objective 5 steps"},
      {"a cell missing", [](json& d) { d["controller"][0].erase(0); },
       "controller: controller[0] has 7 entries, the grid 8 cells"},
      {"one array for a bounded objective", [](json& d) { d["controller"] = d["controller"][0]; },
       "controller: one array, but the objective is bounded"},
      {"another horizon", [](json& d) { d["objective"]["steps"] = 6; },
       "objective: the file's is safety for 6 steps, the spec's safety for 5 steps"},
      {"another kind", [](json& d) { d["objective"]["kind"] = "reach-avoid"; },
       "objective: the file's is reach-avoid within 5 steps"},
      {"unbounded", [](json& d) { d["objective"]["steps"] = nullptr; },
       "objective: the file's is safety, unbounded"},
      {"another model", [](json& d) { d["model"] = "drifting"; },
       "model: the file is of model \"drifting\", the spec's is \"drift\""},
      {"another variable", [](json& d) { d["variables"][0] = "y"; },
       "model: variables are (y), the spec's (x)"},
  };
  for (const Edit& edit : edits) {
    SCOPED_TRACE(edit.name);
    json edited = original;
    edit.apply(edited);
    const std::string failure = first_failure(ir, edited);
    EXPECT_TRUE(failure.starts_with(edit.expected)) << failure;
  }
}

TEST_F(ControllerVerify, AShapeMismatchStopsTheSimulationButADoubleDoesNot) {
  const model::ModelIR ir = test::check_spec_text_ir(kDrift);
  json document = read_json(compile("drift", kDrift));
  const auto monte_carlo = [&ir](const json& d) {
    std::string error;
    const auto file = verify::parse_controller_file(d.dump(), error);
    EXPECT_TRUE(file) << error;
    return verify::check_controller(ir, *file, {}).back();
  };
  document["grid"][0]["breaks"][3] = std::nextafter(3.0, 4.0);
  document["actions"][0]["inputs"][0] = -1.0000000000000002;
  const verify::CatalogCheck simulated = monte_carlo(document);
  EXPECT_EQ(simulated.item, "Monte-Carlo");
  EXPECT_TRUE(simulated.ok) << simulated.verdict;
  document["controller"][0][0] = 5;
  const verify::CatalogCheck stopped = monte_carlo(document);
  EXPECT_FALSE(stopped.ok);
  EXPECT_EQ(stopped.verdict, "not run: the file's shape does not match the spec");
  // A spec without an objective has no controller.
  std::string error;
  const auto file = verify::parse_controller_file(document.dump(), error);
  ASSERT_TRUE(file) << error;
  const auto checks = verify::check_controller(model::ModelIR{}, *file, {});
  ASSERT_EQ(checks.size(), 1U);
  EXPECT_EQ(checks[0].verdict, "the spec states no 'objective', so it has no controller to check");
  // Through the command: exit status 1, every item printed.
  const auto result =
      run_oasisc("verify " + write_spec("drift", kDrift) + " " + write_json("bad.json", document));
  EXPECT_EQ(result.status, 1) << result.output;
  EXPECT_TRUE(contains(result.output, "controller: controller[0][0] is 5, but there are 3 actions"))
      << result.output;
}

std::string read_error(const std::string& text) {
  std::string error;
  const auto file = verify::parse_controller_file(text, error);
  return file ? "read" : error;
}

TEST_F(ControllerVerify, TheReaderNamesThePathOfAMalformedValue) {
  const json original = read_json(compile("drift", kDrift));
  ASSERT_EQ(read_error(original.dump()), "read");
  struct Edit {
    const char* name;
    std::function<void(json&)> apply;
    const char* expected;
  };
  const std::vector<Edit> edits = {
      {"a string bound", [](json& d) { d["lower"][3] = "x"; },
       "lower[3] is a string, not a number"},
      {"an array bound", [](json& d) { d["upper"][1] = json::array({1}); },
       "upper[1] is an array or object, not a number"},
      {"a negative index", [](json& d) { d["controller"][2][1] = -1; },
       "controller[2][1] is negative, not an action index"},
      {"a fractional index", [](json& d) { d["controller"][0][0] = 1.5; },
       "controller[0][0] is not a whole number (an action index)"},
      {"a null index", [](json& d) { d["controller"][4][7] = nullptr; },
       "controller[4][7] is null, not an action index"},
      {"rows and numbers", [](json& d) { d["controller"][1] = 0; },
       "controller[1] is not an array, unlike controller[0]"},
      {"numbers and rows",
       [](json& d) {
         d["controller"] = json::array({0, json::array({0})});
       },
       "controller[1] is an array, unlike controller[0]"},
      {"an object among the rows", [](json& d) { d["controller"][0] = json::object(); },
       "controller[0] is an object, not an action index or an array of them"},
      {"bounds not an array", [](json& d) { d["lower"] = 0.5; }, "lower is a number, not an array"},
      {"a null breakpoint", [](json& d) { d["grid"][0]["breaks"][1] = nullptr; },
       "grid[0].breaks[1] is null, not a number"},
      {"no cells", [](json& d) { d["grid"][0].erase("cells"); }, "grid[0] has no \"cells\""},
      {"no objective", [](json& d) { d.erase("objective"); }, "the file has no \"objective\""},
      {"steps as text", [](json& d) { d["objective"]["steps"] = "5"; },
       "objective.steps is a string, not a whole number"},
      {"exactly as a number", [](json& d) { d["objective"]["exactly_at_step"] = 0; },
       "objective.exactly_at_step is a number, not a boolean"},
      {"an action's name", [](json& d) { d["actions"][1]["action"] = 1; },
       "actions[1].action is a number, not a string"},
      {"an input's values", [](json& d) { d["inputs"][0]["values"] = "all"; },
       "inputs[0].values is a string, not an array"},
      {"a variable", [](json& d) { d["variables"][0] = false; },
       "variables[0] is a boolean, not a string"},
      {"another format", [](json& d) { d["format"] = "oasis-catalog"; },
       "format is \"oasis-catalog\", not \"oasis-controller\""},
      {"another version", [](json& d) { d["version"] = 2; },
       "version is 2; this oasisc reads version 1"},
  };
  for (const Edit& edit : edits) {
    SCOPED_TRACE(edit.name);
    json edited = original;
    edit.apply(edited);
    const std::string error = read_error(edited.dump());
    EXPECT_TRUE(error.starts_with(edit.expected)) << error;
  }
  std::string twice = original.dump();
  twice.replace(twice.find("\"upper\""), 7, "\"lower\"");
  EXPECT_EQ(read_error(twice), "\"lower\" appears twice");
  EXPECT_EQ(read_error("[1, 2]"), "the file is an array, not a JSON object");
  EXPECT_TRUE(read_error("{\"format\": ").starts_with("not valid JSON: ")) << read_error("{");
  EXPECT_TRUE(read_error("{\"lower\": [1e400]}").starts_with("not valid JSON: "));
}

TEST_F(ControllerVerify, ControllerFilesAreRecognised) {
  const auto is_controller = [this](const std::string& name, const std::string& text) {
    std::ofstream(path(name)) << text;
    return verify::is_controller_file(path(name), 1 << 20);
  };
  EXPECT_TRUE(is_controller("a.controller.json", "anything"));
  EXPECT_TRUE(is_controller("a.json", R"({"format": "oasis-controller", "version": 1})"));
  EXPECT_TRUE(is_controller("b.json", R"({"model": {"format": 1}, "format": "oasis-controller"})"));
  EXPECT_FALSE(is_controller("c.json", R"({"format": 3, "contexts": []})"));
  EXPECT_FALSE(is_controller("d.json", R"({"inner": {"format": "oasis-controller"}})"));
  EXPECT_FALSE(is_controller("e.json", R"(["format", "oasis-controller"])"));
  // Cut short after its format: a controller file still, which the reader then refuses.
  EXPECT_TRUE(is_controller("f.json", R"({"format": "oasis-controller", "ver)"));
  EXPECT_FALSE(is_controller("g.json", "not json"));
  // A discrete model has no controller file.
  const auto discrete = run_oasisc("verify " + std::string(OASIS_SOURCE_DIR) +
                                   "/tests/data/prism/two_dice.nm " + path("a.controller.json"));
  EXPECT_EQ(discrete.status, 1);
  EXPECT_TRUE(contains(discrete.output, "a controller file, but the model is not a continuous"))
      << discrete.output;
  const auto result = run_oasisc("verify " + write_spec("drift", kDrift) + " " + path("f.json"));
  EXPECT_EQ(result.status, 1);
  EXPECT_TRUE(contains(result.output, "f.json: error: not valid JSON: ")) << result.output;
}

// Verifies `document` against the spec through the command; returns its output, expecting
// exit status 1.
std::string failing_verify(const std::string& spec, const std::string& file) {
  const auto result = run_oasisc("verify " + spec + " " + file);
  EXPECT_EQ(result.status, 1) << result.output;
  EXPECT_TRUE(contains(result.output, "cells outside their bounds")) << result.output;
  return result.output;
}

TEST_F(ControllerVerify, PlantedUnsoundFilesFail) {
  // Every lower bound raised to its upper bound. On this model the true probabilities are
  // below the upper bounds by 0.07 (the margin 0.049 and 3 standard deviations) or more, 0.15
  // at the edge cells.
  const std::string noisy_spec = write_spec("noisy", kNoisy);
  const json noisy = read_json(compile("noisy", kNoisy));
  {
    json document = noisy;
    for (std::size_t c = 0; c < document["lower"].size(); ++c)
      document["lower"][c] = std::min(1.0, document["upper"][c].get<double>());
    const std::string output = failing_verify(noisy_spec, write_json("raised.json", document));
    EXPECT_TRUE(contains(output, "below lower - t")) << output;
  }
  // Both bounds 1 where the compiler's own upper bound is below 0.9: whatever its bounds' gaps,
  // a sound upper bound puts the truth more than the margin below 1.
  {
    json document = noisy;
    int planted = 0;
    for (std::size_t c = 0; c < document["lower"].size(); ++c) {
      if (document["upper"][c].get<double>() >= 0.9) continue;
      document["lower"][c] = document["upper"][c] = 1.0;
      ++planted;
    }
    ASSERT_GT(planted, 0);
    const std::string output = failing_verify(noisy_spec, write_json("ones.json", document));
    EXPECT_TRUE(contains(output, std::to_string(planted) + " of 8 cells outside")) << output;
  }
  const std::string spec = write_spec("drift", kDrift);
  const json original = read_json(compile("drift", kDrift));
  ASSERT_GT(original["lower"][0].get<double>(), 0.5);  // every cell's, the edge cells' least
  // Every upper bound lowered to 0 (and the lower bounds with them): the compiler's own lower
  // bounds, above 0.5, say that the truth is far above.
  {
    json document = original;
    for (std::size_t c = 0; c < document["lower"].size(); ++c)
      document["lower"][c] = document["upper"][c] = 0.0;
    const std::string output = failing_verify(spec, write_json("lowered.json", document));
    EXPECT_TRUE(contains(output, "above upper + t")) << output;
    EXPECT_TRUE(contains(output, "8 of 8 cells outside their bounds")) << output;
  }
  // The bounds kept, the controller pushing every cell towards its nearer edge: from the edge
  // cells the state leaves [0, 8] within a few steps.
  {
    json document = original;
    for (auto& step : document["controller"])
      for (std::size_t c = 0; c < step.size(); ++c)
        step[c] = c < 4 ? 0 : 2;
    const std::string output = failing_verify(spec, write_json("pushed.json", document));
    EXPECT_TRUE(contains(output, "cell 0: from x = ")) << output;
    EXPECT_TRUE(contains(output, "cell 7: from x = ")) << output;
  }
}

}  // namespace
}  // namespace oasis
