#include "log/step_json.hpp"

#include <cmath>
#include <cstdint>
#include <limits>
#include <stdexcept>

#include "log/log_error.hpp"

namespace oasis::hw::log {
namespace {

using Json = nlohmann::ordered_json;

constexpr std::uint64_t kU32Max = std::numeric_limits<std::uint32_t>::max();
constexpr std::uint64_t kU64Max = std::numeric_limits<std::uint64_t>::max();
constexpr std::int64_t kIntMin = std::numeric_limits<int>::min();
constexpr std::int64_t kIntMax = std::numeric_limits<int>::max();

// ---- writing ----

Json double_json(double value) {
  if (std::isnan(value)) return nullptr;
  if (std::isinf(value)) return value > 0 ? "inf" : "-inf";
  return value;
}

Json doubles_json(const std::vector<double>& values) {
  Json array = Json::array();
  for (double value : values)
    array.push_back(double_json(value));
  return array;
}

Json human_json(const ObservedHuman& human) {
  return Json{{"seen", human.seen},
              {"x_m", double_json(human.x_m)},
              {"y_m", double_json(human.y_m)},
              {"confidence", double_json(human.confidence)}};
}

Json command_json(const CommandRecord& command) {
  return Json{{"forward_m_s", double_json(command.forward_m_s)},
              {"lateral_m_s", double_json(command.lateral_m_s)},
              {"yaw_rate_rad_s", double_json(command.yaw_rate_rad_s)}};
}

// ---- reading: a failed check throws FieldError, which step_from_json turns into `error` ----

struct FieldError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

const Json& field(const Json& object, const std::string& prefix, const char* key) {
  const auto found = object.find(key);
  if (found == object.end()) throw FieldError("missing key '" + prefix + key + "'");
  return *found;
}

[[noreturn]] void ill_typed(const std::string& path, const Json& value, const char* expected) {
  throw FieldError("key '" + path + "' must be " + expected + ", not " + value.type_name());
}

double read_double(const Json& value, const std::string& path) {
  if (value.is_number()) return value.get<double>();
  if (value.is_null()) return std::numeric_limits<double>::quiet_NaN();
  if (value == "inf") return std::numeric_limits<double>::infinity();
  if (value == "-inf") return -std::numeric_limits<double>::infinity();
  ill_typed(path, value, "a number, null (NaN), \"inf\" or \"-inf\"");
}

std::uint64_t read_unsigned(const Json& value, const std::string& path, std::uint64_t max) {
  if (!value.is_number_unsigned() || value.get<std::uint64_t>() > max)
    ill_typed(path, value, ("an integer in 0.." + std::to_string(max)).c_str());
  return value.get<std::uint64_t>();
}

int read_int(const Json& value, const std::string& path) {
  if (!value.is_number_integer()) ill_typed(path, value, "an integer");
  // Non-negative numbers parse as unsigned, negative ones as signed: check each in its type.
  const bool in_range =
      value.is_number_unsigned()
          ? value.get<std::uint64_t>() <= std::uint64_t{kIntMax}
          : value.get<std::int64_t>() >= kIntMin && value.get<std::int64_t>() <= kIntMax;
  if (!in_range) throw FieldError("key '" + path + "' is out of range for an int");
  return static_cast<int>(value.get<std::int64_t>());
}

std::string read_string(const Json& value, const std::string& path) {
  if (!value.is_string()) ill_typed(path, value, "a string");
  return value.get<std::string>();
}

bool read_bool(const Json& value, const std::string& path) {
  if (!value.is_boolean()) ill_typed(path, value, "true or false");
  return value.get<bool>();
}

std::vector<double> read_doubles(const Json& value, const std::string& path) {
  if (!value.is_array()) ill_typed(path, value, "an array");
  std::vector<double> values;
  for (std::size_t i = 0; i < value.size(); ++i)
    values.push_back(read_double(value[i], path + "[" + std::to_string(i) + "]"));
  return values;
}

const Json& object_at(const Json& parent, const std::string& prefix, const char* key) {
  const Json& value = field(parent, prefix, key);
  if (!value.is_object()) ill_typed(prefix + key, value, "an object");
  return value;
}

ObservedHuman read_human(const Json& value, const std::string& path) {
  if (!value.is_object()) ill_typed(path, value, "an object");
  const std::string prefix = path + ".";
  ObservedHuman human;
  human.seen = read_bool(field(value, prefix, "seen"), prefix + "seen");
  human.x_m = read_double(field(value, prefix, "x_m"), prefix + "x_m");
  human.y_m = read_double(field(value, prefix, "y_m"), prefix + "y_m");
  human.confidence = read_double(field(value, prefix, "confidence"), prefix + "confidence");
  return human;
}

std::array<ObservedHuman, 2> read_humans(const Json& object) {
  const Json& value = field(object, "", "humans");
  if (!value.is_array() || value.size() != 2)
    ill_typed("humans", value, "an array of 2 objects (human 1, human 2)");
  return {read_human(value[0], "humans[0]"), read_human(value[1], "humans[1]")};
}

CommandRecord read_command(const Json& object) {
  const Json& value = object_at(object, "", "command");
  CommandRecord command;
  command.forward_m_s = read_double(field(value, "command.", "forward_m_s"), "command.forward_m_s");
  command.lateral_m_s = read_double(field(value, "command.", "lateral_m_s"), "command.lateral_m_s");
  command.yaw_rate_rad_s =
      read_double(field(value, "command.", "yaw_rate_rad_s"), "command.yaw_rate_rad_s");
  return command;
}

std::optional<GroundTruth> read_truth(const Json& object) {
  if (!object.contains("truth")) return std::nullopt;
  const Json& value = object_at(object, "", "truth");
  GroundTruth truth;
  truth.abstraction = static_cast<std::uint32_t>(
      read_unsigned(field(value, "truth.", "abstraction"), "truth.abstraction", kU32Max));
  truth.reward = read_double(field(value, "truth.", "reward"), "truth.reward");
  return truth;
}

std::optional<LinkRecord> read_link(const Json& object) {
  if (!object.contains("link")) return std::nullopt;
  const Json& value = object_at(object, "", "link");
  LinkRecord link;
  link.states_received =
      read_unsigned(field(value, "link.", "states_received"), "link.states_received", kU64Max);
  link.states_refused =
      read_unsigned(field(value, "link.", "states_refused"), "link.states_refused", kU64Max);
  link.datagrams_ignored =
      read_unsigned(field(value, "link.", "datagrams_ignored"), "link.datagrams_ignored", kU64Max);
  link.last_ignored_from =
      read_string(field(value, "link.", "last_ignored_from"), "link.last_ignored_from");
  return link;
}

double read_time(const Json& object) {
  const Json& value = field(object, "", "time_s");
  if (!value.is_number()) ill_typed("time_s", value, "a finite number");
  const auto time_s = value.get<double>();
  if (!std::isfinite(time_s)) throw FieldError("key 'time_s' must be a finite number");
  return time_s;
}

StepRecord read_record(const Json& object) {
  StepRecord record;
  record.step = read_unsigned(field(object, "", "step"), "step", kU64Max);
  record.time_s = read_time(object);
  record.humans = read_humans(object);
  record.state = read_doubles(field(object, "", "state"), "state");
  record.holder = read_int(field(object, "", "holder"), "holder");
  record.reward = read_double(field(object, "", "reward"), "reward");
  record.belief = read_doubles(field(object, "", "belief"), "belief");
  record.abstraction = static_cast<std::uint32_t>(
      read_unsigned(field(object, "", "abstraction"), "abstraction", kU32Max));
  record.abstraction_name = read_string(field(object, "", "abstraction_name"), "abstraction_name");
  record.action =
      static_cast<std::uint32_t>(read_unsigned(field(object, "", "action"), "action", kU32Max));
  record.action_name = read_string(field(object, "", "action_name"), "action_name");
  record.command = read_command(object);
  record.filter_status = read_string(field(object, "", "filter_status"), "filter_status");
  record.truth = read_truth(object);
  record.link = read_link(object);
  return record;
}

}  // namespace

Json step_to_json(const StepRecord& record) {
  if (!std::isfinite(record.time_s))
    throw LogError("step " + std::to_string(record.step) + ": time_s must be finite");
  Json object{{"step", record.step},
              {"time_s", record.time_s},
              {"humans", Json::array({human_json(record.humans[0]), human_json(record.humans[1])})},
              {"state", doubles_json(record.state)},
              {"holder", record.holder},
              {"reward", double_json(record.reward)},
              {"belief", doubles_json(record.belief)},
              {"abstraction", record.abstraction},
              {"abstraction_name", record.abstraction_name},
              {"action", record.action},
              {"action_name", record.action_name},
              {"command", command_json(record.command)},
              {"filter_status", record.filter_status}};
  if (record.truth)
    object["truth"] = Json{{"abstraction", record.truth->abstraction},
                           {"reward", double_json(record.truth->reward)}};
  if (record.link)
    object["link"] = Json{{"states_received", record.link->states_received},
                          {"states_refused", record.link->states_refused},
                          {"datagrams_ignored", record.link->datagrams_ignored},
                          {"last_ignored_from", record.link->last_ignored_from}};
  return object;
}

std::optional<StepRecord> step_from_json(const Json& object, std::string& error) {
  if (!object.is_object()) {
    error = std::string("a line must be one JSON object, not ") + object.type_name();
    return std::nullopt;
  }
  try {
    return read_record(object);
  } catch (const FieldError& failure) {
    error = failure.what();
    return std::nullopt;
  }
}

}  // namespace oasis::hw::log
