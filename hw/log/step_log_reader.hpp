#pragma once
// Reads a step log back (replay, score, tests). Strict about everything the writer controls,
// lenient about the one thing a killed run leaves behind: a last line cut short.
//
//  * every line must be one JSON object with every key of step_json.hpp, well typed, or the
//    read stops with LogError "FILE:LINE: error: message" (lines count from 1);
//  * an empty line is an error too (the writer never writes one);
//  * the last line, when it has no trailing newline and is not valid JSON, is what a kill
//    during write() leaves: it is dropped and reported as a warning
//    "FILE:LINE: warning: ..." in StepLog::warnings, not thrown. A last line without a newline
//    that is a complete record is kept.

#include <filesystem>
#include <string>
#include <string_view>
#include <vector>

#include "log/step_record.hpp"

namespace oasis::hw::log {

struct StepLog {
  std::vector<StepRecord> records;  // in file order
  std::vector<std::string> warnings;
};

// Throws LogError if the file cannot be read or a line is not a step record.
StepLog read_step_log(const std::filesystem::path& path);

// The same on text already in memory; `name` stands for FILE in the messages.
StepLog parse_step_log(std::string_view text, const std::string& name);

}  // namespace oasis::hw::log
