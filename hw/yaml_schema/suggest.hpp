// "Did you mean": the one candidate closest to a misspelt word.
#pragma once

#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace oasis::hw::yaml_schema {

// Edit distance counting an insertion, a deletion, a substitution or a swap of two adjacent
// characters as one edit (optimal string alignment), ignoring ASCII case.
std::size_t edit_distance(std::string_view a, std::string_view b);

// The candidate within a few edits of `word` (1 for words up to 4 characters, 2 up to 8, 3
// beyond), if exactly one candidate is the closest; nothing otherwise.
std::optional<std::string> closest_candidate(std::string_view word,
                                             const std::vector<std::string>& candidates);

}  // namespace oasis::hw::yaml_schema
