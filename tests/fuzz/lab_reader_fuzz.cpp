// PRISM's .lab file alone (formats/explicit_labels.cpp), for a model of kStates states. Labels
// are atomic propositions, so beyond memory safety: labels read xor an error; an accepted
// file names each label once (so at most one "init"), with printable, non-empty names; every
// state and label index is in range; "init" gives exactly the initial states; and the labels
// written back in the .lab format read back the same.

#include <algorithm>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include "formats/explicit_parts.hpp"
#include "fuzz_target.hpp"

namespace {

using namespace oasis;

constexpr std::uint32_t kStates = 16;

struct Labels {
  bool ok = false;
  bool found = false;
  std::vector<model::StateIndex> initial;  // sorted, each once
  model::StateLabels labels;
};

Labels read(const std::string& text) {
  SourceManager sources;
  std::ostringstream messages;
  DiagnosticEngine diagnostics(sources, messages);
  const FileId file = sources.add("fuzz.lab", text);
  Labels result;
  result.ok = formats::read_prism_labels(file, diagnostics, kStates, result.initial, result.labels,
                                         result.found);
  FUZZ_REQUIRE(result.ok == (diagnostics.error_count() == 0));
  std::sort(result.initial.begin(), result.initial.end());
  result.initial.erase(std::unique(result.initial.begin(), result.initial.end()),
                       result.initial.end());
  return result;
}

// The .lab text of `labels`, as PRISM writes it: the names, then one line per labelled state.
std::string written(const model::StateLabels& labels) {
  std::string text;
  for (std::size_t k = 0; k < labels.names.size(); ++k)
    text += (k ? " " : "") + std::to_string(k) + "=\"" + labels.names[k] + "\"";
  text += "\n";
  for (std::uint32_t s = 0; s < kStates; ++s) {
    const auto held = labels.of(s);
    if (held.empty()) continue;
    text += std::to_string(s) + ":";
    for (const std::uint32_t label : held)
      text += " " + std::to_string(label);
    text += "\n";
  }
  return text;
}

void check_accepted(const Labels& read) {
  const model::StateLabels& labels = read.labels;
  const std::set<std::string> distinct(labels.names.begin(), labels.names.end());
  FUZZ_REQUIRE(distinct.size() == labels.names.size());
  for (const std::string& name : labels.names) {
    FUZZ_REQUIRE(!name.empty());
    FUZZ_REQUIRE(std::none_of(name.begin(), name.end(), [](char c) {
      return static_cast<unsigned char>(c) < 0x20 || c == '\x7f' || c == '"';
    }));
  }
  FUZZ_REQUIRE(labels.begin.empty() || labels.begin.size() == kStates + 1);
  const auto init = labels.find("init");
  FUZZ_REQUIRE(read.found == init.has_value());
  std::vector<model::StateIndex> holding_init;
  for (std::uint32_t s = 0; s < kStates; ++s) {
    const auto held = labels.of(s);
    FUZZ_REQUIRE(std::is_sorted(held.begin(), held.end()));
    FUZZ_REQUIRE(std::adjacent_find(held.begin(), held.end()) == held.end());
    for (const std::uint32_t label : held) {
      FUZZ_REQUIRE(label < labels.names.size());
      if (init && label == *init) holding_init.push_back(s);
    }
  }
  FUZZ_REQUIRE(holding_init == read.initial);
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const Labels first = read(fuzz::text_of(data, size));
  if (!first.ok) return 0;
  check_accepted(first);
  const Labels again = read(written(first.labels));
  FUZZ_REQUIRE(again.ok);
  FUZZ_REQUIRE(again.found == first.found);
  FUZZ_REQUIRE(again.initial == first.initial);
  FUZZ_REQUIRE(again.labels.names == first.labels.names);
  for (std::uint32_t s = 0; s < kStates; ++s) {
    const auto a = first.labels.of(s);
    const auto b = again.labels.of(s);
    FUZZ_REQUIRE(std::equal(a.begin(), a.end(), b.begin(), b.end()));
  }
  return 0;
}
