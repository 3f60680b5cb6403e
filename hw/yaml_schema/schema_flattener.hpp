#pragma once
// A schema visitor that flattens values to (key path, value text) pairs in schema order: the
// settings' and the hallway scenario's differing_keys() compare two values through it. A
// codec writes the shortest text that reads back to the same value, so two values are equal
// exactly when their texts are. Visitors with more kinds of entry derive from it.
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "yaml_schema/codecs.hpp"

namespace oasis::hw::yaml_schema {

class SchemaFlattener {
 public:
  template <class Body>
  void section(std::string_view key, std::string_view, Body&& body) {
    prefix_.push_back(std::string(key));
    body();
    prefix_.pop_back();
  }

  template <class T, class Codec>
  void value(std::string_view key, const T& field, const Codec& codec, std::string_view) {
    add(path(key), codec.format(field));
  }

  std::vector<std::pair<std::string, std::string>> pairs;

 protected:
  std::string path(std::string_view key) const { return dotted_key(prefix_, key); }
  void add(std::string key, std::string text) {
    pairs.emplace_back(std::move(key), std::move(text));
  }

 private:
  std::vector<std::string> prefix_;
};

}  // namespace oasis::hw::yaml_schema
