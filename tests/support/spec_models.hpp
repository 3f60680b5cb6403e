#pragma once
// Test helpers: a spec (text or file) through the front end and exploration, failing the
// current test with the diagnostics when it does not check.

#include <fstream>
#include <iterator>
#include <optional>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

#include <gtest/gtest.h>

#include "frontend/load_spec.hpp"
#include "model/explorer.hpp"
#include "pipeline/discrete_catalog.hpp"

namespace oasis::test {

namespace detail {
template <typename Load>
model::ExplicitModel explore_loaded(Load load) {
  SourceManager sources;
  std::ostringstream messages;
  DiagnosticEngine diagnostics(sources, messages);
  auto ir = load(sources, diagnostics);
  EXPECT_TRUE(ir) << messages.str();
  if (!ir) return {};
  auto model = model::explore(*ir, diagnostics);
  EXPECT_TRUE(model) << messages.str();
  return model ? std::move(*model) : model::ExplicitModel{};
}
}  // namespace detail

inline std::string read_text_file(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

// A spec's text or file through the front end only (continuous specs stop there), failing the
// current test with the diagnostics when it does not check.
inline model::ModelIR check_spec_text_ir(const std::string& text) {
  SourceManager sources;
  std::ostringstream messages;
  DiagnosticEngine diagnostics(sources, messages);
  auto ir = frontend::check_spec_text(sources.add("test.oasis", text), diagnostics);
  EXPECT_TRUE(ir) << messages.str();
  return ir ? std::move(*ir) : model::ModelIR{};
}

// The errors a spec's text must produce, each as "LINE:COL: MESSAGE" in order; fails the
// current test if the text checks.
inline std::vector<std::string> spec_errors(const std::string& source) {
  SourceManager sources;
  std::ostringstream out;
  DiagnosticEngine diagnostics(sources, out, 50);
  const auto ir = frontend::check_spec_text(sources.add("check.oasis", source), diagnostics);
  EXPECT_FALSE(ir) << "expected errors in:\n" << source;
  std::vector<std::string> errors;
  std::istringstream lines(out.str());
  const std::string prefix = "check.oasis:";
  for (std::string line; std::getline(lines, line);) {
    const std::size_t error = line.find(": error: ");
    if (line.rfind(prefix, 0) != 0 || error == std::string::npos) continue;
    errors.push_back(line.substr(prefix.size(), error - prefix.size()) + ": " +
                     line.substr(error + 9));
  }
  return errors;
}

inline model::ModelIR load_spec_ir(const std::string& path) {
  SourceManager sources;
  std::ostringstream messages;
  DiagnosticEngine diagnostics(sources, messages);
  auto ir = frontend::load_spec(path, sources, diagnostics);
  EXPECT_TRUE(ir) << messages.str();
  return ir ? std::move(*ir) : model::ModelIR{};
}

inline model::ModelIR shipped_go1_spec() {
  return load_spec_ir(std::string(OASIS_SOURCE_DIR) + "/specs/go1_treat.oasis");
}

// A line with deterministic unit moves and a reward on [3, 4]: its coarsest bisimulation is
// known (the ten unit intervals and outside), for the geometry tests.
inline constexpr const char* kDeterministicLineSpec = R"(
mdp line {
  continuous x : [0 .. 10];
  actions left, right;
  discount 0.9;
  dynamics [left] { x' = x - 1; }
  dynamics [right] { x' = x + 1; }
  region goal = x >= 3 & x <= 4;
}
catalog { context at_goal { reward goal : 1; } }
)";

inline model::ExplicitModel explore_spec_text(const std::string& text,
                                              const std::string& name = "test.oasis") {
  return detail::explore_loaded([&](SourceManager& sources, DiagnosticEngine& diagnostics) {
    return frontend::check_spec_text(sources.add(name, text), diagnostics);
  });
}

inline model::ExplicitModel explore_spec_file(const std::string& path) {
  return detail::explore_loaded([&](SourceManager& sources, DiagnosticEngine& diagnostics) {
    return frontend::load_spec(path, sources, diagnostics);
  });
}

// The catalog `oasisc compile` would build for `model` (with --robust p_correct if given);
// fails the test and returns an empty catalog if it cannot be built.
inline model::CatalogData compiled_catalog(const model::ExplicitModel& model,
                                           std::optional<double> p_correct = std::nullopt) {
  pipeline::BuildOptions options;
  options.catalog.p_correct = p_correct;
  std::string error;
  std::optional<model::CatalogData> catalog = pipeline::build_catalog(model, 1, options, error);
  EXPECT_TRUE(catalog) << error;
  return catalog ? std::move(*catalog) : model::CatalogData{};
}

}  // namespace oasis::test
