#pragma once
// Test helpers: a spec (text or file) through the front end and exploration, failing the
// current test with the diagnostics when it does not check.

#include <fstream>
#include <iterator>
#include <sstream>
#include <string>
#include <utility>

#include <gtest/gtest.h>

#include "model/explorer.hpp"
#include "spec/frontend.hpp"

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

inline model::ExplicitModel explore_spec_text(const std::string& text,
                                              const std::string& name = "test.oasis") {
  return detail::explore_loaded([&](SourceManager& sources, DiagnosticEngine& diagnostics) {
    return spec::check_spec_text(sources.add(name, text), diagnostics);
  });
}

inline model::ExplicitModel explore_spec_file(const std::string& path) {
  return detail::explore_loaded([&](SourceManager& sources, DiagnosticEngine& diagnostics) {
    return spec::load_spec(path, sources, diagnostics);
  });
}

}  // namespace oasis::test
