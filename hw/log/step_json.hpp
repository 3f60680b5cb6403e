#pragma once
// One StepRecord as one JSON object: the line format of the step log (README.md here lists the
// keys and units). Kept apart from the file handling so that the format has one definition and
// the writer, the reader and the tests all go through it.
//
// Doubles: a finite value is a JSON number (printed with enough digits to read back exactly);
// JSON has no NaN or infinity, so NaN is written as null (perception's "no estimate") and
// +/-infinity as the strings "inf" / "-inf", which the reader turns back into the same values.
// The one exception is time_s, which must be finite: the score derives the step period from it.

#include <optional>
#include <string>

#include <nlohmann/json.hpp>

#include "log/step_record.hpp"

namespace oasis::hw::log {

// Keys in the order of README.md (ordered_json keeps it, so a log reads top to bottom).
// Throws LogError (message without a location) when time_s is not finite.
nlohmann::ordered_json step_to_json(const StepRecord& record);

// The record in `object`, or nullopt with `error` set to a lower-case message naming the key,
// e.g. "missing key 'humans[1].confidence'". Keys not in the format are ignored, so that a
// later version may add some without breaking older readers.
std::optional<StepRecord> step_from_json(const nlohmann::ordered_json& object, std::string& error);

}  // namespace oasis::hw::log
