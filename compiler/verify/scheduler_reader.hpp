#pragma once
// Reading a scheduler file (`oasisc query --scheduler FILE.json`) for `oasisc verify`:
//
//   {"schedulers": [{"property": TEXT, "name"?: NAME,
//                    "memoryless": [{"state": NAME, "action": NAME or null}, ...]
//                    or "by_step": [[...], ...]}, ...]}
//
// Only the file's shape is checked here (every type, every required key): whether its names
// are the model's states and actions is the check's business (scheduler_check.hpp), so that
// one scheduler's wrong name fails that scheduler alone.

#include <cstddef>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace oasis::verify {

struct StateChoice {
  std::string state;
  std::optional<std::string> action;  // nullopt: null, "any action"
};

struct SchedulerEntry {
  std::string property;             // the property's text, as query printed it
  std::optional<std::string> name;  // a named property's name
  bool step_bounded = false;        // "by_step": not checked by verify
  std::vector<StateChoice> memoryless;
};

struct SchedulerFile {
  std::vector<SchedulerEntry> schedulers;  // in the order of the file
};

// True when `path` is a JSON object with a "schedulers" key. A file that is not (or cannot be
// read) is left to verify's other readers, which say what is wrong with it.
bool is_scheduler_file(const std::string& path, std::size_t max_bytes);

// Reads `path`. On failure (also a file larger than `max_bytes`) returns nullopt and sets
// `error` to one sentence (without the path).
std::optional<SchedulerFile> read_scheduler_file(const std::string& path, std::size_t max_bytes,
                                                 std::string& error);
// The same on the file's text.
std::optional<SchedulerFile> parse_scheduler_file(std::string_view text, std::string& error);

}  // namespace oasis::verify
