// The spec front end (lexer, parser, checker) and the exploration of what it accepts. Every
// input ends with a model or with at least one printed error, never both and never neither;
// an explored model is structurally sound. Exploration is capped (kMaxStates) so that a
// mutated range such as [0 .. 40000] costs little.

#include <sstream>

#include "frontend/load_spec.hpp"
#include "fuzz_target.hpp"
#include "model/explorer.hpp"

namespace {

constexpr std::uint32_t kMaxStates = 5000;

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace oasis;
  SourceManager sources;
  std::ostringstream messages;
  DiagnosticEngine diagnostics(sources, messages);
  const FileId file = sources.add("fuzz.oasis", fuzz::text_of(data, size));
  const auto ir = frontend::check_spec_text(file, diagnostics);
  // Continuous models are not explored; an imported program is the PRISM target's to read.
  bool has_model = ir && (ir->kind == model::ModelKind::Continuous || ir->imported);
  if (ir && !has_model) {
    model::ExploreOptions options;
    options.max_states = kMaxStates;
    const auto explored = model::explore(*ir, diagnostics, options);
    has_model = explored.has_value();
    if (explored) FUZZ_REQUIRE(!model::find_structural_problem(*explored));
  }
  const bool has_errors = diagnostics.error_count() != 0;
  FUZZ_REQUIRE(has_model != has_errors);
  FUZZ_REQUIRE(!has_errors || messages.str().find(": error: ") != std::string::npos);
  return 0;
}
