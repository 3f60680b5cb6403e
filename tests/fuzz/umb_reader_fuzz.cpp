// The UMB reader: a model or at least one error, never both; a model read is structurally
// sound, its initial states are exactly its "init" states, and it round-trips through the
// writer: what the writer makes of it reads back without a message to a model that the writer
// turns into the same bytes.

#include <algorithm>
#include <sstream>
#include <string>
#include <vector>

#include "formats/umb_reader.hpp"
#include "formats/umb_writer.hpp"
#include "fuzz_target.hpp"
#include "model/explicit_model.hpp"

namespace {

std::vector<oasis::model::StateIndex> init_states(const oasis::model::ExplicitModel& model) {
  std::vector<oasis::model::StateIndex> states;
  const auto init = model.labels.find("init");
  for (oasis::model::StateIndex s = 0; init && s < model.num_states(); ++s) {
    const auto held = model.labels.of(s);
    if (std::find(held.begin(), held.end(), *init) != held.end()) states.push_back(s);
  }
  return states;
}

struct Read {
  std::optional<oasis::model::ExplicitModel> model;
  std::size_t errors = 0;
  std::string messages;
};

Read read(std::string bytes) {
  using namespace oasis;
  Read result;
  SourceManager sources;
  std::ostringstream messages;
  DiagnosticEngine diagnostics(sources, messages);
  const FileId file = sources.add("fuzz.umb", std::move(bytes));
  formats::ReadOptions options;
  options.max_states = 100000;
  options.max_bytes = std::size_t{64} << 20;
  result.model = formats::read_umb(file, diagnostics, options);
  result.errors = diagnostics.error_count();
  result.messages = messages.str();
  return result;
}

std::string write(const oasis::model::ExplicitModel& model) {
  std::vector<std::size_t> contexts(model.contexts.size());
  for (std::size_t c = 0; c < contexts.size(); ++c)
    contexts[c] = c;
  std::string bytes;
  std::string error;
  FUZZ_REQUIRE(oasis::formats::write_umb_bytes(model, contexts, bytes, error));
  return bytes;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace oasis;
  const Read first = read(fuzz::text_of(data, size));
  FUZZ_REQUIRE(first.model.has_value() != (first.errors != 0));
  if (!first.model) return 0;
  FUZZ_REQUIRE(!model::find_structural_problem(*first.model));
  FUZZ_REQUIRE(first.model->states.initial == init_states(*first.model));
  const std::string bytes = write(*first.model);
  const Read second = read(bytes);
  FUZZ_REQUIRE(second.model.has_value() && second.errors == 0);
  FUZZ_REQUIRE(second.model->num_states() == first.model->num_states());
  FUZZ_REQUIRE(second.model->contexts.size() == first.model->contexts.size());
  FUZZ_REQUIRE(second.model->states.initial == first.model->states.initial);
  FUZZ_REQUIRE(write(*second.model) == bytes);
  return 0;
}
