// The mCRL2 .aut reader: a model or at least one error, never both; a model read is
// structurally sound (probabilities sum to one, targets in range). The declared state count
// is capped so that "des (0,1,4000000000)" is refused before anything is allocated.

#include <sstream>

#include "formats/aut_reader.hpp"
#include "fuzz_target.hpp"
#include "model/explicit_model.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace oasis;
  SourceManager sources;
  std::ostringstream messages;
  DiagnosticEngine diagnostics(sources, messages);
  const FileId file = sources.add("fuzz.aut", fuzz::text_of(data, size));
  formats::ReadOptions options;
  options.max_states = 100000;
  const auto model = formats::read_aut(file, diagnostics, options);
  FUZZ_REQUIRE(model.has_value() != (diagnostics.error_count() != 0));
  if (model) FUZZ_REQUIRE(!model::find_structural_problem(*model));
  return 0;
}
