#pragma once
// The index of a UMB file (its `index.json`), reduced to what oasis reads: the counts of the
// transition system, the type of its probabilities, and the atomic propositions and reward
// annotations (docs/formats.md, "UMB"). Everything a DTMC or an MDP does not have (continuous
// time, players beyond one, observations, interval probabilities) is refused here with the
// reason, so the reader of the arrays meets only what it can build.

#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "formats/read_options.hpp"
#include "formats/umb_binary.hpp"
#include "formats/umb_valuations.hpp"

namespace oasis::formats {

struct UmbAnnotation {
  std::string id;    // its folder: annotations/GROUP/ID/
  std::string name;  // the alias where there is one, else the id
  bool states = false;
  bool choices = false;
  bool branches = false;
  umb::ValueType type;
};

struct UmbIndex {
  bool markov_chain = false;  // "#players": 0
  std::uint64_t num_states = 0;
  std::uint64_t num_initial_states = 0;
  std::uint64_t num_choices = 0;
  std::uint64_t num_choice_actions = 0;
  std::uint64_t num_branches = 0;
  umb::ValueType probability;
  std::vector<UmbAnnotation> aps;      // in the order of the index
  std::vector<UmbAnnotation> rewards;  // in the order of the index
  // The states' valuation class when the index has one that oasis keeps; else, when it has
  // one, why it is read past.
  std::optional<UmbValuationClass> valuations;
  std::string valuations_skipped;
};

// Parses and checks `text`; on failure returns false and sets `error` (a message about
// index.json, without the file name).
bool read_umb_index(std::string_view text, const ReadOptions& options, UmbIndex& index,
                    std::string& error);

// Whether `text` is valid UTF-8 without control characters (a name the index can carry).
bool is_umb_name(std::string_view text);

}  // namespace oasis::formats
