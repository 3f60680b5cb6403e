#pragma once
// A cursor over the text of a model file for hand-written line-oriented readers. Everything
// is inline and works on raw pointers into the (usually memory-mapped) text: the hot loops
// of the readers compile to a few compares per byte, with no allocation.

#include <cstdint>
#include <string_view>

#include "support/source_manager.hpp"

namespace oasis::formats {

// A run of digits read as an unsigned number. More than 19 digits may not fit 64 bits:
// `overflow` is set and `value` is meaningless; `text` still holds the digits.
struct Natural {
  std::uint64_t value = 0;
  std::string_view text;
  bool overflow = false;

  [[nodiscard]] bool empty() const { return text.empty(); }
};

class TextScanner {
 public:
  explicit TextScanner(std::string_view text)
      : begin_(text.data()), cursor_(text.data()), end_(text.data() + text.size()) {}

  [[nodiscard]] bool at_end() const { return cursor_ == end_; }
  [[nodiscard]] char peek() const { return cursor_ < end_ ? *cursor_ : '\0'; }
  [[nodiscard]] SourceOffset offset() const { return static_cast<SourceOffset>(cursor_ - begin_); }
  [[nodiscard]] const char* position() const { return cursor_; }
  [[nodiscard]] const char* end() const { return end_; }
  void seek(const char* position) { cursor_ = position; }
  [[nodiscard]] SourceOffset offset_of(const char* position) const {
    return static_cast<SourceOffset>(position - begin_);
  }

  static bool is_blank(char c) { return c == ' ' || c == '\t'; }
  static bool is_digit(char c) { return static_cast<unsigned char>(c - '0') < 10; }

  void skip_blanks() {
    while (cursor_ < end_ && is_blank(*cursor_))
      ++cursor_;
  }
  bool consume(char c) {
    if (cursor_ < end_ && *cursor_ == c) {
      ++cursor_;
      return true;
    }
    return false;
  }
  // At '\n', "\r\n" or the end of the text.
  [[nodiscard]] bool at_line_end() const {
    return cursor_ == end_ || *cursor_ == '\n' ||
           (*cursor_ == '\r' && (cursor_ + 1 == end_ || cursor_[1] == '\n'));
  }
  // Moves past the current line's terminator (to the end of the text on the last line).
  void skip_line() {
    while (cursor_ < end_ && *cursor_ != '\n')
      ++cursor_;
    if (cursor_ < end_) ++cursor_;
  }
  // Skips lines holding only blanks; stops at the first character of a non-blank line.
  void skip_blank_lines() {
    for (;;) {
      const char* line = cursor_;
      skip_blanks();
      if (cursor_ == end_) return;
      if (at_line_end()) {
        skip_line();
        continue;
      }
      cursor_ = line;
      return;
    }
  }

  Natural read_natural() {
    Natural number;
    const char* start = cursor_;
    std::uint64_t value = 0;
    while (cursor_ < end_ && is_digit(*cursor_)) {
      value = value * 10 + static_cast<std::uint64_t>(*cursor_ - '0');
      ++cursor_;
    }
    number.text = std::string_view(start, static_cast<std::size_t>(cursor_ - start));
    number.overflow = number.text.size() > 19;
    number.value = value;
    return number;
  }

  // The characters up to the next blank or line end (a number, an action name).
  std::string_view read_word() {
    const char* start = cursor_;
    while (cursor_ < end_ && !is_blank(*cursor_) && *cursor_ != '\n' &&
           !(*cursor_ == '\r' && at_line_end())) {
      ++cursor_;
    }
    return {start, static_cast<std::size_t>(cursor_ - start)};
  }

  // The rest of the current line without its terminator; the cursor stays.
  [[nodiscard]] std::string_view rest_of_line() const {
    const char* stop = cursor_;
    while (stop < end_ && *stop != '\n')
      ++stop;
    if (stop > cursor_ && stop[-1] == '\r') --stop;
    return {cursor_, static_cast<std::size_t>(stop - cursor_)};
  }

 private:
  const char* begin_;
  const char* cursor_;
  const char* end_;
};

}  // namespace oasis::formats
