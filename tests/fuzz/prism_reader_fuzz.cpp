// PRISM's explicit files. One input holds the files of one model separated by NUL bytes, in
// the order .tra, .sta, .lab, .srew, .trew; missing or empty trailing parts are files that do
// not exist. A model or at least one error, never both; a model read is structurally sound.

#include <optional>
#include <sstream>
#include <string>
#include <vector>

#include "formats/explicit_reader.hpp"
#include "fuzz_target.hpp"
#include "model/explicit_model.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace oasis;
  const std::string text = fuzz::text_of(data, size);
  std::vector<std::string> parts;
  std::size_t begin = 0;
  while (parts.size() < 4) {
    const std::size_t separator = text.find('\0', begin);
    if (separator == std::string::npos) break;
    parts.push_back(text.substr(begin, separator - begin));
    begin = separator + 1;
  }
  parts.push_back(text.substr(begin));
  parts.resize(5);

  SourceManager sources;
  std::ostringstream messages;
  DiagnosticEngine diagnostics(sources, messages);
  const auto add = [&](std::size_t index, const char* extension) -> std::optional<FileId> {
    if (index > 0 && parts[index].empty()) return std::nullopt;
    return sources.add(std::string("fuzz") + extension, parts[index]);
  };
  formats::PrismFiles files;
  files.transitions = *add(0, ".tra");
  files.states = add(1, ".sta");
  files.labels = add(2, ".lab");
  files.state_rewards = add(3, ".srew");
  files.transition_rewards = add(4, ".trew");
  formats::ReadOptions options;
  options.max_states = 100000;
  const auto model = formats::read_prism(files, diagnostics, options);
  FUZZ_REQUIRE(model.has_value() != (diagnostics.error_count() != 0));
  if (model) FUZZ_REQUIRE(!model::find_structural_problem(*model));
  return 0;
}
