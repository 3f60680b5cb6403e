// The PRISM-language front end (lexer, parser, checker) and the exploration of what it
// accepts. Every input ends with a model or with at least one printed error, never both and
// never neither; an explored model is structurally sound. Exploration is capped (kMaxStates)
// so that a mutated range such as [0..40000] costs little. Undefined constants get no value
// here: such programs must end in a located error.

#include <sstream>

#include "fuzz_target.hpp"
#include "prism/load_program.hpp"

namespace {

constexpr std::uint32_t kMaxStates = 5000;

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace oasis;
  SourceManager sources;
  std::ostringstream messages;
  DiagnosticEngine diagnostics(sources, messages);
  const FileId file = sources.add("fuzz.pm", fuzz::text_of(data, size));
  prism::LoadOptions options;
  options.rewards = model::LabelSelection{};  // every reward structure: more code reached
  options.explore.max_states = kMaxStates;
  const auto model = prism::load_program_text(file, "fuzz", diagnostics, options);
  if (model) FUZZ_REQUIRE(!model::find_structural_problem(*model));
  const bool has_errors = diagnostics.error_count() != 0;
  FUZZ_REQUIRE(model.has_value() != has_errors);
  FUZZ_REQUIRE(!has_errors || messages.str().find(": error: ") != std::string::npos);
  return 0;
}
