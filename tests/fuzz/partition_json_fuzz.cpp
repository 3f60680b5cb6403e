// oasisc verify's reader of a quotient's partitions (verify/partition_result_reader.hpp, the
// JSON of `oasisc quotient --format json --partition`): any text is refused with a reason, or
// gives one partition per named context in which every state of the model has a block in
// range. The verifier then checks each partition against Definition 1; a wrong partition must
// come back as a violation with a message, never as a failure of the verifier itself.

#include <fstream>
#include <sstream>
#include <string>

#include "frontend/load_spec.hpp"
#include "fuzz_target.hpp"
#include "model/explorer.hpp"
#include "verify/partition_result_reader.hpp"
#include "verify/verifier.hpp"

namespace {

using namespace oasis;

// The paper's discrete tracking example, specs/discrete_tracking.oasis: the seeds are its
// quotient (`oasisc quotient --format json --partition`).
model::ExplicitModel explore_spec() {
  const std::string path = OASIS_SOURCE_DIR "/specs/discrete_tracking.oasis";
  std::ifstream in(path, std::ios::binary);
  std::ostringstream text;
  if (!(in && text << in.rdbuf()))
    fuzz::broken(("cannot read " + path).c_str(), __FILE__, __LINE__);
  SourceManager sources;
  std::ostringstream messages;
  DiagnosticEngine diagnostics(sources, messages);
  const FileId file = sources.add(path, text.str());
  const auto ir = frontend::check_spec_text(file, diagnostics);
  if (!ir) fuzz::broken(messages.str().c_str(), __FILE__, __LINE__);
  auto model = model::explore(*ir, diagnostics);
  if (!model) fuzz::broken(messages.str().c_str(), __FILE__, __LINE__);
  return std::move(*model);
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  static const model::ExplicitModel model = explore_spec();
  std::string error;
  const auto result = verify::parse_partition_result(fuzz::text_of(data, size), model, error);
  if (!result) {
    FUZZ_REQUIRE(!error.empty());
    return 0;
  }
  for (const verify::ContextPartition& entry : result->contexts) {
    FUZZ_REQUIRE(entry.context < model.contexts.size());
    FUZZ_REQUIRE(entry.partition.num_states() == model.num_states());
    for (const model::BlockIndex block : entry.partition.block_of)
      FUZZ_REQUIRE(block < entry.partition.num_blocks);
    const verify::VerificationResult verdict =
        verify::verify_partition(model, entry.context, entry.partition);
    FUZZ_REQUIRE(verdict.ok() || !verdict.violation->message.empty());
  }
  return 0;
}
