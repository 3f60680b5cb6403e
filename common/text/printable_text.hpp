#pragma once
// Input quoted in a message, made safe to print: the one rule of oasisc's diagnostics and of
// oasis-go1's settings errors and step log reader (issue 28). A message must stay a few lines
// whatever the input holds: control bytes (a NUL, an escape sequence) are escaped or replaced, so
// that nothing cuts it short or moves the terminal's cursor, and long text (a 10 MB name on one
// line) is cut. Header-only, C++17.

#include <cstddef>
#include <string>
#include <string_view>

namespace oasis::text {

// The longest piece of input a message quotes whole.
inline constexpr std::size_t kMaxQuotedBytes = 80;
// The longest message printed whole.
inline constexpr std::size_t kMaxMessageBytes = 1000;
// The widest part of a source line shown under a message (a window around the caret).
inline constexpr std::size_t kMaxShownColumns = 160;

inline bool is_continuation_byte(char c) {
  return (static_cast<unsigned char>(c) & 0xC0U) == 0x80U;
}

// `text` with control bytes escaped (a NUL as \0, others as \xNN), cut after `max_bytes` with
// "... (N bytes)".
inline std::string printable_excerpt(std::string_view text,
                                     std::size_t max_bytes = kMaxQuotedBytes) {
  static constexpr char kHex[] = "0123456789abcdef";
  std::string out;
  std::size_t shown = text.size() > max_bytes ? max_bytes : text.size();
  while (shown < text.size() && shown > 0 && is_continuation_byte(text[shown]))
    --shown;  // never half a UTF-8 character
  for (std::size_t i = 0; i < shown; ++i) {
    const auto byte = static_cast<unsigned char>(text[i]);
    if (byte == 0) {
      out += "\\0";
    } else if (byte < 0x20 || byte == 0x7f) {
      out += "\\x";
      out += kHex[byte >> 4];
      out += kHex[byte & 0xf];
    } else {
      out += static_cast<char>(byte);
    }
  }
  if (shown < text.size()) out += "... (" + std::to_string(text.size()) + " bytes)";
  return out;
}

// A whole message: control bytes other than line breaks and tabs shown as '?', at most
// kMaxMessageBytes.
inline std::string printable_message(std::string_view message) {
  std::string out(message.substr(0, kMaxMessageBytes));
  for (char& c : out)
    if ((static_cast<unsigned char>(c) < 0x20 && c != '\t' && c != '\n') || c == '\x7f') c = '?';
  if (message.size() > kMaxMessageBytes)
    out += "... (cut: " + std::to_string(message.size()) + " bytes)";
  return out;
}

// The part of a source line to show with a caret at byte `caret`: the whole line when it is
// short, else a window of about kMaxShownColumns around the caret, marked by "..." in front.
struct SourceWindow {
  std::string text;         // control bytes other than tabs as '?'
  std::size_t caret = 0;    // the caret's byte within `text`
  bool cut_before = false;  // print "..." before it (and three more spaces before the caret)
};

inline SourceWindow source_window(std::string_view line, std::size_t caret) {
  if (caret > line.size()) caret = line.size();  // a column past the end: the caret at the end
  std::size_t start = 0;
  std::size_t end = line.size();
  if (line.size() > kMaxShownColumns) {
    start = caret > kMaxShownColumns / 2 ? caret - kMaxShownColumns / 2 : 0;
    while (start > 0 && start < line.size() && is_continuation_byte(line[start]))
      --start;
    end = start + kMaxShownColumns < line.size() ? start + kMaxShownColumns : line.size();
    while (end < line.size() && is_continuation_byte(line[end]))
      ++end;
  }
  SourceWindow window{std::string(line.substr(start, end - start)), caret - start, start > 0};
  for (char& c : window.text)
    if (static_cast<unsigned char>(c) < 0x20 && c != '\t') c = '?';
  return window;
}

}  // namespace oasis::text
