// Storm's DRN reader: a model or at least one error, never both; a model read is structurally
// sound, its initial states are exactly its "init" states (or state 0 without that label),
// and the writer takes it back without complaint (into /dev/null: the round trip of the bytes
// is a unit test, drn_format_test).

#include <algorithm>
#include <sstream>
#include <string>
#include <vector>

#include "formats/drn_reader.hpp"
#include "formats/drn_writer.hpp"
#include "fuzz_target.hpp"
#include "model/explicit_model.hpp"

namespace {

// The states labelled "init", ascending; {0} when no state is.
std::vector<oasis::model::StateIndex> init_states(const oasis::model::ExplicitModel& model) {
  std::vector<oasis::model::StateIndex> states;
  const auto init = model.labels.find("init");
  for (oasis::model::StateIndex s = 0; init && s < model.num_states(); ++s) {
    const auto held = model.labels.of(s);
    if (std::find(held.begin(), held.end(), *init) != held.end()) states.push_back(s);
  }
  if (!init) states.push_back(0);
  return states;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace oasis;
  SourceManager sources;
  std::ostringstream messages;
  DiagnosticEngine diagnostics(sources, messages);
  const FileId file = sources.add("fuzz.drn", fuzz::text_of(data, size));
  formats::ReadOptions options;
  options.max_states = 100000;
  const auto model = formats::read_drn(file, diagnostics, options);
  FUZZ_REQUIRE(model.has_value() != (diagnostics.error_count() != 0));
  if (!model) return 0;
  FUZZ_REQUIRE(!model::find_structural_problem(*model));
  FUZZ_REQUIRE(model->states.initial == init_states(*model));
  std::vector<std::size_t> contexts(model->contexts.size());
  for (std::size_t c = 0; c < contexts.size(); ++c)
    contexts[c] = c;
  std::string error;
  FUZZ_REQUIRE(formats::write_drn_file(*model, contexts, "/dev/null", error));
  return 0;
}
