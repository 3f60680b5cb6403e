#include "verify/controller_reader.hpp"

#include <optional>
#include <set>
#include <utility>

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

std::string a_type(const json& value) {
  switch (value.type()) {
    case json::value_t::null:
      return "null";
    case json::value_t::object:
      return "an object";
    case json::value_t::array:
      return "an array";
    case json::value_t::string:
      return "a string";
    case json::value_t::boolean:
      return "a boolean";
    case json::value_t::binary:
      return "binary data";
    default:
      return "a number";
  }
}

std::string indexed(const std::string& path, std::size_t i) {
  return path + "[" + std::to_string(i) + "]";
}

std::string member_path(const std::string& path, const char* key) {
  return path.empty() ? std::string(key) : path + "." + key;
}

// ---- the per-cell arrays, taken out of the text while it is parsed ------------------------

bool is_cell_key(const std::string& key) {
  return key == "lower" || key == "upper" || key == "controller";
}

// nlohmann's parse callback: at depth 1 the top-level object's keys; the elements of "lower",
// "upper" and "controller" (and of controller's rows) are moved into vectors and dropped from
// the tree. The first problem stops the collection; the parse still finds syntax errors.
class CellArrays {
 public:
  bool on_event(int depth, json::parse_event_t event, json& parsed) {
    if (error) return false;
    using Event = json::parse_event_t;
    if (depth == 1 && event == Event::key) return on_key(parsed.get<std::string>());
    if (!in_cells_) return true;
    if (depth == 1) {
      // The array's start; its end, or not an array at all (the tree's reader says so).
      if (event != Event::array_start) in_cells_ = false;
      return true;
    }
    if (depth == 2) return on_element(event, parsed);
    if (depth == 3 && event == Event::value) return on_step_entry(parsed);
    fail_at(indexed(indexed(key_, index_), row_index_), "an array or object, not an index");
    return false;
  }

  std::vector<double> lower;
  std::vector<double> upper;
  std::vector<std::uint64_t> flat;               // "controller": [a, ...]
  std::vector<std::vector<std::uint64_t>> rows;  // "controller": [[a, ...], ...]
  std::optional<std::string> error;

 private:
  bool on_key(std::string key) {
    key_ = std::move(key);
    in_cells_ = false;
    if (!is_cell_key(key_)) return true;
    if (!seen_.insert(key_).second) {
      error = "\"" + key_ + "\" appears twice";
      return false;
    }
    in_cells_ = true;
    index_ = 0;
    return true;
  }

  // An element of one of the arrays (it starts at depth 2; it ends there too).
  bool on_element(json::parse_event_t event, json& parsed) {
    using Event = json::parse_event_t;
    const std::string where = indexed(key_, index_);
    if (event == Event::array_end) {  // the end of one of controller's rows
      ++index_;
      return true;
    }
    if (key_ != "controller") {
      if (event == Event::value && parsed.is_number()) {
        (key_ == "lower" ? lower : upper).push_back(parsed.get<double>());
        ++index_;
      } else {
        fail_at(where,
                (event == Event::value ? a_type(parsed) : "an array or object") + ", not a number");
      }
      return false;
    }
    if (event == Event::object_start) {
      fail_at(where, "an object, not an action index or an array of them");
      return false;
    }
    const bool row = event == Event::array_start;
    if (row ? !flat.empty() : !rows.empty()) {
      fail_at(where, std::string(row ? "an array" : "not an array") +
                         ", unlike controller[0] (expected one action index per cell, or an "
                         "array of them per step)");
      return false;
    }
    if (row) {
      rows.emplace_back();
      row_index_ = 0;
      return true;  // kept, so that its elements reach this callback
    }
    const std::optional<std::uint64_t> action = index_of(parsed, where);
    if (action) flat.push_back(*action);
    ++index_;
    return false;
  }

  bool on_step_entry(json& parsed) {
    const std::optional<std::uint64_t> action =
        index_of(parsed, indexed(indexed(key_, index_), row_index_));
    if (action) rows.back().push_back(*action);
    ++row_index_;
    return false;
  }

  std::optional<std::uint64_t> index_of(const json& value, const std::string& where) {
    if (value.is_number_unsigned()) return value.get<std::uint64_t>();
    if (value.is_number_integer()) {
      fail_at(where, "negative, not an action index");
    } else if (value.is_number()) {
      fail_at(where, "not a whole number (an action index)");
    } else {
      fail_at(where, a_type(value) + ", not an action index");
    }
    return std::nullopt;
  }

  void fail_at(const std::string& where, const std::string& what) {
    if (!error) error = where + " is " + what;
  }

  std::string key_;
  bool in_cells_ = false;
  std::size_t index_ = 0;
  std::size_t row_index_ = 0;
  std::set<std::string> seen_;
};

// ---- the rest, read from the (small) tree --------------------------------------------------

const json& member(const json& object, const char* key, const std::string& path) {
  const auto it = object.find(key);
  if (it == object.end())
    fail((path.empty() ? std::string("the file") : path) + " has no \"" + key + "\"");
  return *it;
}

const json& object_at(const json& value, const std::string& path) {
  if (!value.is_object()) fail(path + " is " + a_type(value) + ", not an object");
  return value;
}

const json& array_at(const json& value, const std::string& path) {
  if (!value.is_array()) fail(path + " is " + a_type(value) + ", not an array");
  return value;
}

std::string string_at(const json& value, const std::string& path) {
  if (!value.is_string()) fail(path + " is " + a_type(value) + ", not a string");
  return value.get<std::string>();
}

double number_at(const json& value, const std::string& path) {
  if (!value.is_number()) fail(path + " is " + a_type(value) + ", not a number");
  return value.get<double>();
}

std::uint64_t whole_at(const json& value, const std::string& path) {
  if (!value.is_number_unsigned()) fail(path + " is " + a_type(value) + ", not a whole number");
  return value.get<std::uint64_t>();
}

std::vector<double> numbers_at(const json& value, const std::string& path) {
  std::vector<double> numbers;
  for (std::size_t i = 0; i < array_at(value, path).size(); ++i)
    numbers.push_back(number_at(value[i], indexed(path, i)));
  return numbers;
}

// `key` of the top-level object: a member named `key`, read by `read` at its path.
template <typename Read>
auto read_member(const json& object, const char* key, const std::string& path, Read read) {
  const std::string where = member_path(path, key);
  return read(member(object, key, path), where);
}

std::vector<std::string> read_variables(const json& value, const std::string& path) {
  std::vector<std::string> names;
  for (std::size_t i = 0; i < array_at(value, path).size(); ++i)
    names.push_back(string_at(value[i], indexed(path, i)));
  return names;
}

std::vector<ControllerAxis> read_grid(const json& value, const std::string& path) {
  std::vector<ControllerAxis> axes;
  for (std::size_t i = 0; i < array_at(value, path).size(); ++i) {
    const std::string where = indexed(path, i);
    const json& axis = object_at(value[i], where);
    axes.push_back({read_member(axis, "cells", where, whole_at),
                    read_member(axis, "breaks", where, numbers_at)});
  }
  return axes;
}

std::vector<ControllerInput> read_inputs(const json& value, const std::string& path) {
  std::vector<ControllerInput> inputs;
  for (std::size_t i = 0; i < array_at(value, path).size(); ++i) {
    const std::string where = indexed(path, i);
    const json& input = object_at(value[i], where);
    inputs.push_back({read_member(input, "name", where, string_at),
                      read_member(input, "values", where, numbers_at)});
  }
  return inputs;
}

std::vector<ControllerAction> read_actions(const json& value, const std::string& path) {
  std::vector<ControllerAction> actions;
  for (std::size_t i = 0; i < array_at(value, path).size(); ++i) {
    const std::string where = indexed(path, i);
    const json& action = object_at(value[i], where);
    actions.push_back({read_member(action, "action", where, string_at),
                       read_member(action, "inputs", where, numbers_at)});
  }
  return actions;
}

ControllerObjective read_objective(const json& value, const std::string& path) {
  const json& object = object_at(value, path);
  ControllerObjective objective;
  objective.kind = read_member(object, "kind", path, string_at);
  const json& steps = member(object, "steps", path);
  if (!steps.is_null()) objective.steps = whole_at(steps, member_path(path, "steps"));
  const json& exactly = member(object, "exactly_at_step", path);
  if (!exactly.is_boolean())
    fail(member_path(path, "exactly_at_step") + " is " + a_type(exactly) + ", not a boolean");
  objective.exactly_at_step = exactly.get<bool>();
  return objective;
}

ControllerFile read_document(const json& document, CellArrays& cells) {
  if (!document.is_object()) fail("the file is " + a_type(document) + ", not a JSON object");
  const std::string format = read_member(document, "format", "", string_at);
  if (format != "oasis-controller") fail("format is \"" + format + "\", not \"oasis-controller\"");
  const std::uint64_t version = read_member(document, "version", "", whole_at);
  if (version != 1) fail("version is " + std::to_string(version) + "; this oasisc reads version 1");
  ControllerFile file;
  file.model = read_member(document, "model", "", string_at);
  file.variables = read_member(document, "variables", "", read_variables);
  file.grid = read_member(document, "grid", "", read_grid);
  file.inputs = read_member(document, "inputs", "", read_inputs);
  file.actions = read_member(document, "actions", "", read_actions);
  file.objective = read_member(document, "objective", "", read_objective);
  // The cell arrays' elements were taken out while parsing: what is left is an empty array.
  for (const char* key : {"lower", "upper", "controller"})
    read_member(document, key, "", array_at);
  file.lower = std::move(cells.lower);
  file.upper = std::move(cells.upper);
  file.per_step = !cells.rows.empty();
  if (file.per_step) {
    file.controller = std::move(cells.rows);
  } else {
    file.controller.push_back(std::move(cells.flat));
  }
  return file;
}

// nlohmann's message without its "[json.exception...]" prefix (it names the byte offset).
std::string json_message(const json::exception& e) {
  const std::string what = e.what();
  const auto space = what.find("] ");
  return space == std::string::npos ? what : what.substr(space + 2);
}

// Stops at the top-level "format": whether it is "oasis-controller".
class FormatSniffer : public nlohmann::json_sax<json> {
 public:
  bool found = false;

  bool null() override { return scalar(); }
  bool boolean(bool) override { return scalar(); }
  bool number_integer(number_integer_t) override { return scalar(); }
  bool number_unsigned(number_unsigned_t) override { return scalar(); }
  bool number_float(number_float_t, const string_t&) override { return scalar(); }
  bool string(string_t& value) override {
    if (at_format()) found = value == "oasis-controller";
    return scalar();
  }
  bool binary(binary_t&) override { return scalar(); }
  bool start_object(std::size_t) override { return open(); }
  bool start_array(std::size_t) override { return depth_ > 0 && open(); }
  bool end_object() override { return close(); }
  bool end_array() override { return close(); }
  bool key(string_t& value) override {
    is_format_ = depth_ == 1 && value == "format";
    return true;
  }
  bool parse_error(std::size_t, const std::string&, const nlohmann::detail::exception&) override {
    return false;
  }

 private:
  [[nodiscard]] bool at_format() const { return depth_ == 1 && is_format_; }
  // A value at the top level's "format" ends the search, whatever it is.
  bool scalar() { return !at_format(); }
  bool open() {
    if (at_format()) return false;
    ++depth_;
    return true;
  }
  bool close() {
    --depth_;
    return depth_ > 0;
  }
  int depth_ = 0;
  bool is_format_ = false;
};

}  // namespace

bool is_controller_file(const std::string& path, std::size_t max_bytes) {
  if (path.ends_with(".controller.json")) return true;
  MappedFile file;
  std::string error;
  if (!file.open(path, max_bytes, error)) return false;
  FormatSniffer sniffer;
  const std::string_view text = file.text();
  json::sax_parse(text.begin(), text.end(), &sniffer);
  return sniffer.found;
}

std::optional<ControllerFile> read_controller_file(const std::string& path, std::size_t max_bytes,
                                                   std::string& error) {
  MappedFile file;
  if (!file.open(path, max_bytes, error)) {
    error = "cannot read: " + error;
    return std::nullopt;
  }
  return parse_controller_file(file.text(), error);
}

std::optional<ControllerFile> parse_controller_file(std::string_view text, std::string& error) {
  CellArrays cells;
  json document;
  try {
    document = json::parse(text.begin(), text.end(),
                           [&cells](int depth, json::parse_event_t event, json& parsed) {
                             return cells.on_event(depth, event, parsed);
                           });
  } catch (const json::exception& e) {
    error = "not valid JSON: " + json_message(e);
    return std::nullopt;
  }
  if (cells.error) {
    error = *cells.error;
    return std::nullopt;
  }
  try {
    return read_document(document, cells);
  } catch (const ReadError& e) {
    error = e.message;
    return std::nullopt;
  }
}

}  // namespace oasis::verify
