// The index of a UMB file (umb_index.hpp), on nlohmann/json. Objects keep the order of the
// file (ordered_json), so reward annotations become contexts in the order they are listed.

#include "formats/umb_index.hpp"

#include <limits>
#include <set>

#include <nlohmann/json.hpp>

#include "formats/model_size.hpp"

namespace oasis::formats {
namespace {

using Json = nlohmann::ordered_json;

// Thrown inside this file only, caught by read_umb_index: the first problem ends the reading.
struct IndexError {
  std::string message;
};

[[noreturn]] void fail(std::string message) {
  throw IndexError{std::move(message)};
}

const Json& member(const Json& object, const char* key, const std::string& where) {
  const auto it = object.find(key);
  if (it == object.end()) fail(where + "has no \"" + key + "\"");
  return *it;
}

const Json& object_at(const Json& object, const char* key, const std::string& where) {
  const Json& value = member(object, key, where);
  if (!value.is_object()) fail(where + "\"" + key + "\" is not an object");
  return value;
}

std::uint64_t count_at(const Json& object, const char* key, const std::string& where,
                       std::uint64_t max) {
  const Json& value = member(object, key, where);
  if (!value.is_number_unsigned() && !(value.is_number_integer() && value.get<std::int64_t>() >= 0))
    fail(where + "\"" + key + "\" is not a whole number");
  const auto count = value.get<std::uint64_t>();
  if (count > max) {
    fail(where + "\"" + key + "\" is " + std::to_string(count) + ", more than oasis reads (" +
         std::to_string(max) + ")");
  }
  return count;
}

std::string string_at(const Json& object, const char* key, const std::string& where) {
  const Json& value = member(object, key, where);
  if (!value.is_string()) fail(where + "\"" + key + "\" is not a string");
  return value.get<std::string>();
}

std::uint64_t default_bits(const std::string& type) {
  if (type == "bool") return 1;
  if (type == "rational" || type == "int-interval" || type == "uint-interval" ||
      type == "double-interval")
    return 128;
  if (type == "rational-interval") return 256;
  return 64;
}

umb::ValueType type_at(const Json& object, const char* key, const std::string& where) {
  const Json& value = member(object, key, where);
  if (!value.is_object()) fail(where + "\"" + key + "\" is not a type object");
  const std::string inner = where + "\"" + key + "\": ";
  umb::ValueType type;
  type.name = string_at(value, "type", inner);
  type.bits =
      value.contains("size") ? count_at(value, "size", inner, UINT32_MAX) : default_bits(type.name);
  if (type.bits == 0) fail(inner + "\"size\" is 0");
  return type;
}

// A number type oasis reads exactly: a 64-bit double or a rational of 128k bits.
void check_number_type(const umb::ValueType& type, const std::string& where) {
  if (type.name == "double") {
    if (type.bits != 64) fail(where + "a double has 64 bits, not " + std::to_string(type.bits));
    return;
  }
  if (type.name == "rational") {
    if (type.bits % 128 != 0) {
      fail(where + "a rational's size must be a multiple of 128 bits, not " +
           std::to_string(type.bits));
    }
    return;
  }
  fail(where + "values of type '" + type.name +
       "' are not supported: oasis reads double and rational numbers");
}

bool is_identifier(const std::string& id) {
  if (id.empty()) return false;
  for (const char c : id) {
    if (!((c >= 'a' && c <= 'z') || (c >= '0' && c <= '9') || c == '_' || c == '-')) return false;
  }
  return true;
}

std::vector<UmbAnnotation> read_group(const Json& annotations, const char* group, bool aps) {
  std::vector<UmbAnnotation> result;
  const auto found = annotations.find(group);
  if (found == annotations.end()) return result;
  const std::string where = std::string("annotations: \"") + group + "\": ";
  if (!found->is_object()) fail(where + "is not an object");
  for (const auto& [id, value] : found->items()) {
    const std::string here = where + "\"" + id + "\": ";
    if (!is_identifier(id)) {
      fail(here + "an identifier holds only lower-case letters, digits, '_' and '-'");
    }
    if (!value.is_object()) fail(here + "is not an object");
    UmbAnnotation annotation;
    annotation.id = id;
    annotation.name = value.contains("alias") ? string_at(value, "alias", here) : id;
    if (!is_umb_name(annotation.name) || annotation.name.empty())
      fail(here + "the alias is empty or holds a control character");
    if (value.contains("probability-type"))
      fail(here + "annotations with distributions over values are not supported");
    const Json& applies = member(value, "applies-to", here);
    if (!applies.is_array() || applies.empty()) fail(here + "\"applies-to\" is not a list");
    for (const Json& entity : applies) {
      const std::string text = entity.is_string() ? entity.get<std::string>() : "";
      if (text == "states") {
        annotation.states = true;
      } else if (text == "choices" && !aps) {
        annotation.choices = true;
      } else if (text == "branches" && !aps) {
        annotation.branches = true;
      } else {
        // Never dump() the value: a hostile one nests deep enough to exhaust the stack.
        fail(here + "applies to " + (entity.is_string() ? "'" + text + "'" : "a non-string") +
             (aps ? ": an atomic proposition applies to states"
                  : ": oasis reads rewards of "
                    "states, choices and branches"));
      }
    }
    annotation.type = type_at(value, "type", here);
    if (aps && (annotation.type.name != "bool" || annotation.type.bits != 1)) {
      fail(here + "an atomic proposition has the type bool (1 bit)");
    }
    if (!aps) check_number_type(annotation.type, here);
    for (const UmbAnnotation& other : result) {
      if (other.name == annotation.name) fail(here + "'" + annotation.name + "' is named twice");
    }
    result.push_back(std::move(annotation));
  }
  return result;
}

void read_transition_system(const Json& ts, const ReadOptions& options, UmbIndex& index) {
  const std::string where = "transition-system: ";
  const std::string time = string_at(ts, "time", where);
  if (time != "discrete") {
    fail(where + "time '" + time +
         "' is not supported: oasis reads discrete-time models (DTMCs and MDPs)");
  }
  const std::uint64_t players = count_at(ts, "#players", where, UINT32_MAX);
  if (players > 1) {
    fail(where + "a game of " + std::to_string(players) +
         " players is not supported: oasis reads DTMCs (0 players) and MDPs (1)");
  }
  index.markov_chain = players == 0;
  const std::uint64_t states = count_at(ts, "#states", where, UINT64_MAX);
  if (const auto refusal = state_count_refusal(std::to_string(states), states, options))
    fail(where + "\"#states\" is " + *refusal);
  index.num_states = states;
  if (index.num_states == 0) fail(where + "\"#states\" is 0: the model has no states");
  index.num_initial_states = count_at(ts, "#initial-states", where, index.num_states);
  // Edge and choice indices are 32-bit.
  index.num_choices = count_at(ts, "#choices", where, UINT32_MAX - 1);
  index.num_choice_actions = count_at(ts, "#choice-actions", where, UINT32_MAX);
  index.num_branches = count_at(ts, "#branches", where, UINT32_MAX - 2);
  // The index is read before the model's arrays are decoded from the archive's entries (the
  // entries themselves are unpacked already: a tar may hold them in any order). A model whose
  // reading alone would not fit the memory budget is refused here.
  const DeclaredSize size{
      .states = states, .choices = index.num_choices, .edges = index.num_branches};
  if (const auto refusal = memory_refusal(size, options)) {
    fail(where + "the index declares " + std::to_string(states) + " states, " +
         std::to_string(index.num_choices) + " choices and " + std::to_string(index.num_branches) +
         " branches: " + *refusal);
  }
  if (count_at(ts, "#observations", where, std::numeric_limits<std::uint64_t>::max()) != 0)
    fail(where + "observations are not supported: oasis reads fully observable models");
  if (!ts.contains("branch-probability-type")) {
    fail(where +
         "there is no \"branch-probability-type\": a model without probabilities "
         "(an LTS) is not supported");
  }
  index.probability = type_at(ts, "branch-probability-type", where);
  check_number_type(index.probability, where + "\"branch-probability-type\": ");
}

// Thrown for state valuations of a form oasis does not keep: they are read past.
struct Unsupported {
  std::string reason;
};

UmbField read_field(const Json& variable, std::set<std::string>& names) {
  if (!variable.is_object()) throw Unsupported{"a variable is not an object"};
  if (variable.contains("padding")) {
    const Json& bits = variable["padding"];
    if (!bits.is_number_unsigned() || bits.get<std::uint64_t>() == 0 ||
        bits.get<std::uint64_t>() > UINT32_MAX)
      throw Unsupported{"a padding is not a positive whole number"};
    return {"", UmbField::Kind::kPadding, bits.get<std::uint64_t>(), 0};
  }
  if (!variable.contains("name") || !variable["name"].is_string())
    throw Unsupported{"a variable has no name"};
  UmbField field;
  field.name = variable["name"].get<std::string>();
  if (!is_umb_variable_name(field.name) || !names.insert(field.name).second)
    throw Unsupported{"variable names are not distinct identifiers"};
  if (variable.contains("is-optional") && variable["is-optional"] != false)
    throw Unsupported{"variable '" + field.name + "' is optional"};
  if (!variable.contains("type") || !variable["type"].is_object() ||
      !variable["type"].contains("type") || !variable["type"]["type"].is_string())
    throw Unsupported{"variable '" + field.name + "' has no type"};
  const std::string type = variable["type"]["type"].get<std::string>();
  if (type != "bool" && type != "int" && type != "uint")
    throw Unsupported{"variable '" + field.name + "' is of type '" + type + "'"};
  field.kind = type == "bool"  ? UmbField::Kind::kBool
               : type == "int" ? UmbField::Kind::kInt
                               : UmbField::Kind::kUint;
  field.bits = type == "bool" ? 1 : 64;
  if (variable["type"].contains("size")) {
    const Json& size = variable["type"]["size"];
    if (!size.is_number_unsigned() || size.get<std::uint64_t>() == 0 ||
        size.get<std::uint64_t>() > 64)
      throw Unsupported{"variable '" + field.name + "' is not of 1 to 64 bits"};
    field.bits = size.get<std::uint64_t>();
  }
  if (variable.contains("offset") && field.kind != UmbField::Kind::kBool) {
    const Json& offset = variable["offset"];
    if (!offset.is_number_integer() ||
        (offset.is_number_unsigned() && offset.get<std::uint64_t>() > INT64_MAX))
      throw Unsupported{"the offset of variable '" + field.name + "' is not a 64-bit integer"};
    field.offset = offset.get<std::int64_t>();
  }
  return field;
}

// The index's "valuations" of states, if any: into index.valuations, or the reason they are
// read past into index.valuations_skipped.
void read_valuations(const Json& json, UmbIndex& index) {
  const auto valuations = json.find("valuations");
  if (valuations == json.end() || !valuations->is_object() || !valuations->contains("states"))
    return;
  try {
    const Json& states = (*valuations)["states"];
    if (!states.is_object() || !states.contains("classes") || !states["classes"].is_array())
      throw Unsupported{"there is no list of classes"};
    if (states["classes"].size() != 1) throw Unsupported{"there is not exactly one class"};
    const Json& shape = states["classes"][0];
    if (!shape.is_object() || !shape.contains("variables") || !shape["variables"].is_array())
      throw Unsupported{"the class lists no variables"};
    UmbValuationClass result;
    std::set<std::string> names;
    for (const Json& variable : shape["variables"]) {
      result.fields.push_back(read_field(variable, names));
      result.bits += result.fields.back().bits;
    }
    if (names.empty()) throw Unsupported{"the class has no variables"};
    if (result.bits % 8 != 0) throw Unsupported{"a valuation is not a whole number of bytes"};
    index.valuations = std::move(result);
  } catch (const Unsupported& problem) {
    index.valuations_skipped = problem.reason;
  }
}

}  // namespace

bool is_umb_name(std::string_view text) {
  std::size_t i = 0;
  while (i < text.size()) {
    const auto byte = static_cast<unsigned char>(text[i]);
    if (byte < 0x20 || byte == 0x7f) return false;
    std::size_t length = 1;
    std::uint32_t code = byte;
    if (byte >= 0x80) {
      if (byte >= 0xc2 && byte <= 0xdf) {
        length = 2;
        code = byte & 0x1fU;
      } else if (byte >= 0xe0 && byte <= 0xef) {
        length = 3;
        code = byte & 0x0fU;
      } else if (byte >= 0xf0 && byte <= 0xf4) {
        length = 4;
        code = byte & 0x07U;
      } else {
        return false;
      }
      if (i + length > text.size()) return false;
      for (std::size_t k = 1; k < length; ++k) {
        const auto next = static_cast<unsigned char>(text[i + k]);
        if ((next & 0xc0U) != 0x80U) return false;
        code = (code << 6) | (next & 0x3fU);
      }
      // Overlong forms, surrogates and code points past U+10FFFF are not UTF-8.
      const std::uint32_t least = length == 2 ? 0x80 : length == 3 ? 0x800 : 0x10000;
      if (code < least || code > 0x10ffff || (code >= 0xd800 && code <= 0xdfff)) return false;
      if (code >= 0x80 && code < 0xa0) return false;  // C1 control characters
    }
    i += length;
  }
  return true;
}

bool read_umb_index(std::string_view text, const ReadOptions& options, UmbIndex& index,
                    std::string& error) {
  Json json;
  try {
    json = Json::parse(text);
  } catch (const Json::parse_error& problem) {
    error = "index.json is not valid JSON (at byte " + std::to_string(problem.byte) + ")";
    return false;
  } catch (const Json::exception&) {  // a number beyond a double's range (1e400)
    error = "index.json holds a number out of range";
    return false;
  }
  try {
    if (!json.is_object()) fail("is not a JSON object");
    const std::uint64_t version = count_at(json, "format-version", "", UINT32_MAX);
    if (version != 1) {
      fail("format version " + std::to_string(version) +
           " is not supported: oasis reads version 1");
    }
    read_transition_system(object_at(json, "transition-system", ""), options, index);
    const auto annotations = json.find("annotations");
    if (annotations != json.end()) {
      if (!annotations->is_object()) fail("\"annotations\" is not an object");
      index.aps = read_group(*annotations, "aps", true);
      index.rewards = read_group(*annotations, "rewards", false);
    }
    read_valuations(json, index);
  } catch (const IndexError& problem) {
    error = "index.json: " + problem.message;
    return false;
  } catch (const Json::exception& problem) {  // a value of another type than checked
    error = "index.json: unexpected content (" + std::string(problem.what()) + ")";
    return false;
  }
  return true;
}

}  // namespace oasis::formats
