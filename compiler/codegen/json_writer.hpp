#pragma once
// A JSON document written as it is produced, without a tree in memory: the continuous
// catalog with transitions has millions of `next` entries, which as an nlohmann::json tree
// took several times the memory and most of the time of a compile. Small parts (names,
// short arrays) can still be built as nlohmann::json and written with embed().

#include <cstddef>
#include <cstdint>
#include <functional>
#include <string>
#include <string_view>
#include <vector>

#include <nlohmann/json.hpp>

namespace oasis::codegen {

class JsonWriter {
 public:
  // Receives the text in pieces of about kChunkBytes, in order; the last piece at finish().
  using Sink = std::function<void(std::string_view)>;
  static constexpr std::size_t kChunkBytes = std::size_t{1} << 20;

  explicit JsonWriter(Sink sink) : sink_(std::move(sink)) { text_.reserve(kChunkBytes + 256); }

  void begin_object() { open('{'); }
  void end_object() { close('}'); }
  void begin_array() { open('['); }
  void end_array() { close(']'); }
  // The key of the next value, inside an object.
  void key(std::string_view name);

  void value(std::string_view text);
  void value(const char* text) { value(std::string_view(text)); }
  // The shortest text that reads back as the same double; null for NaN and infinities
  // (JSON has no such numbers).
  void value(double number);
  void value(std::uint64_t number);
  void value(std::uint32_t number) { value(std::uint64_t{number}); }
  void value(bool flag);
  void null();
  void value(const std::string& text) { value(std::string_view(text)); }
  // A small value built as a tree (names, short arrays).
  void embed(const nlohmann::json& small);

  // Ends the document with a newline and hands the rest to the sink.
  void finish();

 private:
  void open(char bracket);
  void close(char bracket);
  // The comma between elements; nothing after a key or before a container's first element.
  void separate();
  void written() {
    if (text_.size() >= kChunkBytes) flush();
  }
  void flush();

  Sink sink_;
  std::string text_;
  std::vector<bool> first_;  // per open container: no element written yet
  bool after_key_ = false;
};

// The whole document as one string (small documents and tests).
std::string json_text(const std::function<void(JsonWriter&)>& write);

}  // namespace oasis::codegen
