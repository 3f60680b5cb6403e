#include "codegen/json_writer.hpp"

#include <charconv>
#include <cmath>

namespace oasis::codegen {

void JsonWriter::separate() {
  if (after_key_) {
    after_key_ = false;
    return;
  }
  if (first_.empty()) return;
  if (first_.back()) {
    first_.back() = false;
  } else {
    text_ += ',';
  }
}

void JsonWriter::open(char bracket) {
  separate();
  text_ += bracket;
  first_.push_back(true);
}

void JsonWriter::close(char bracket) {
  first_.pop_back();
  text_ += bracket;
  written();
}

void JsonWriter::key(std::string_view name) {
  value(name);
  text_ += ':';
  after_key_ = true;
}

void JsonWriter::value(std::string_view text) {
  separate();
  // nlohmann's escaping: the same rules as the rest of our JSON output.
  text_ += nlohmann::json(std::string(text)).dump();
  written();
}

void JsonWriter::value(double number) {
  separate();
  if (!std::isfinite(number)) {
    text_ += "null";
    return;
  }
  char digits[32];
  const auto end = std::to_chars(digits, digits + sizeof digits, number).ptr;
  text_.append(digits, end);
  written();
}

void JsonWriter::value(std::uint64_t number) {
  separate();
  char digits[24];
  const auto end = std::to_chars(digits, digits + sizeof digits, number).ptr;
  text_.append(digits, end);
  written();
}

void JsonWriter::value(bool flag) {
  separate();
  text_ += flag ? "true" : "false";
}

void JsonWriter::null() {
  separate();
  text_ += "null";
}

void JsonWriter::embed(const nlohmann::json& small) {
  separate();
  text_ += small.dump();
  written();
}

void JsonWriter::finish() {
  text_ += '\n';
  flush();
}

void JsonWriter::flush() {
  if (!text_.empty()) sink_(text_);
  text_.clear();
}

std::string json_text(const std::function<void(JsonWriter&)>& write) {
  std::string text;
  JsonWriter writer([&text](std::string_view piece) { text += piece; });
  write(writer);
  writer.finish();
  return text;
}

}  // namespace oasis::codegen
