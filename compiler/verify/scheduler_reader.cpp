#include "verify/scheduler_reader.hpp"

#include <nlohmann/json.hpp>

#include "support/mapped_file.hpp"

namespace oasis::verify {
namespace {

using nlohmann::json;

struct ReadError {
  std::string message;
};

[[noreturn]] void fail(std::string message) {
  throw ReadError{std::move(message)};
}

// The value of `key` in `object` if it is a string; fails otherwise (a missing key too).
std::string string_at(const json& object, const char* key, const std::string& where) {
  const auto it = object.find(key);
  if (it == object.end()) fail(where + " has no \"" + key + "\"");
  if (!it->is_string()) fail(where + ": \"" + key + "\" is " + it->type_name() + ", not a string");
  return it->get<std::string>();
}

StateChoice read_choice(const json& item, const std::string& where) {
  if (!item.is_object()) fail(where + " is " + item.type_name() + ", not an object");
  StateChoice choice;
  choice.state = string_at(item, "state", where);
  const auto action = item.find("action");
  if (action == item.end())
    fail(where + " has no \"action\" (an action's name, or null where any will do)");
  if (action->is_string()) {
    choice.action = action->get<std::string>();
  } else if (!action->is_null()) {
    fail(where + ": \"action\" is " + action->type_name() + ", not a name or null");
  }
  return choice;
}

SchedulerEntry read_entry(const json& entry, const std::string& where) {
  if (!entry.is_object()) fail(where + " is " + entry.type_name() + ", not an object");
  SchedulerEntry result;
  result.property = string_at(entry, "property", where);
  if (entry.contains("name")) result.name = string_at(entry, "name", where);
  const bool memoryless = entry.contains("memoryless");
  const bool by_step = entry.contains("by_step");
  if (memoryless == by_step)
    fail(where +
         (memoryless ? " has both \"memoryless\" and \"by_step\""
                     : " has neither \"memoryless\" nor \"by_step\"") +
         " (exactly one is expected)");
  const json& list = entry[memoryless ? "memoryless" : "by_step"];
  if (!list.is_array())
    fail(where + ": \"" + (memoryless ? "memoryless" : "by_step") + "\" is " + list.type_name() +
         ", not an array");
  result.step_bounded = by_step;
  if (by_step) return result;  // not checked; its shape does not matter
  result.memoryless.reserve(list.size());
  for (std::size_t i = 0; i < list.size(); ++i)
    result.memoryless.push_back(
        read_choice(list[i], where + ".memoryless[" + std::to_string(i) + "]"));
  return result;
}

SchedulerFile read_document(const json& document) {
  if (!document.is_object()) fail("the file is not a JSON object");
  const auto schedulers = document.find("schedulers");
  if (schedulers == document.end())
    fail("no \"schedulers\" key (expected the output of 'oasisc query --scheduler')");
  if (!schedulers->is_array())
    fail(std::string("\"schedulers\" is ") + schedulers->type_name() + ", not an array");
  if (schedulers->empty()) fail("\"schedulers\" is empty: nothing to verify");
  SchedulerFile file;
  for (std::size_t i = 0; i < schedulers->size(); ++i)
    file.schedulers.push_back(
        read_entry((*schedulers)[i], "schedulers[" + std::to_string(i) + "]"));
  return file;
}

// nullopt and `error` set when `text` is not JSON.
std::optional<json> parse_json(std::string_view text, std::string& error) {
  try {
    return json::parse(text.begin(), text.end());
  } catch (const json::exception& e) {
    // nlohmann's message names the byte offset; drop its "[json.exception...]" prefix.
    const std::string what = e.what();
    const auto space = what.find("] ");
    error = "not valid JSON: " + (space == std::string::npos ? what : what.substr(space + 2));
    return std::nullopt;
  }
}

}  // namespace

bool is_scheduler_file(const std::string& path, std::size_t max_bytes) {
  MappedFile file;
  std::string error;
  if (!file.open(path, max_bytes, error)) return false;
  const std::optional<json> document = parse_json(file.text(), error);
  return document && document->is_object() && document->contains("schedulers");
}

std::optional<SchedulerFile> read_scheduler_file(const std::string& path, std::size_t max_bytes,
                                                 std::string& error) {
  MappedFile file;
  if (!file.open(path, max_bytes, error)) {
    error = "cannot read: " + error;
    return std::nullopt;
  }
  return parse_scheduler_file(file.text(), error);
}

std::optional<SchedulerFile> parse_scheduler_file(std::string_view text, std::string& error) {
  const std::optional<json> document = parse_json(text, error);
  if (!document) return std::nullopt;
  try {
    return read_document(*document);
  } catch (const ReadError& e) {
    error = e.message;
    return std::nullopt;
  }
}

}  // namespace oasis::verify
