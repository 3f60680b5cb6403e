#include "support/input_validation.hpp"

#include <cstdint>
#include <string_view>

namespace oasis {
namespace {

// Length of the well-formed UTF-8 sequence at `i`, or 0 when it is malformed
// (bad lead byte, truncated, overlong, surrogate or beyond U+10FFFF).
std::size_t utf8_sequence_length(std::string_view text, std::size_t i) {
  const auto byte = [&](std::size_t k) { return static_cast<unsigned char>(text[k]); };
  const unsigned char lead = byte(i);
  if (lead < 0x80) return 1;
  std::size_t length = 0;
  std::uint32_t min_code = 0;
  std::uint32_t code = 0;
  if ((lead & 0xE0U) == 0xC0U) {
    length = 2, min_code = 0x80, code = lead & 0x1FU;
  } else if ((lead & 0xF0U) == 0xE0U) {
    length = 3, min_code = 0x800, code = lead & 0x0FU;
  } else if ((lead & 0xF8U) == 0xF0U) {
    length = 4, min_code = 0x10000, code = lead & 0x07U;
  } else {
    return 0;
  }
  if (i + length > text.size()) return 0;
  for (std::size_t k = 1; k < length; ++k) {
    if ((byte(i + k) & 0xC0U) != 0x80U) return 0;
    code = (code << 6U) | (byte(i + k) & 0x3FU);
  }
  if (code < min_code || code > 0x10FFFF || (code >= 0xD800 && code <= 0xDFFF)) return 0;
  return length;
}

}  // namespace

bool validate_input(FileId file, DiagnosticEngine& diagnostics) {
  const std::string_view text = diagnostics.sources().file(file).text();
  for (std::size_t i = 0; i < text.size();) {
    const auto where = SourceLocation{file, static_cast<std::uint32_t>(i)};
    if (text[i] == '\0') {
      diagnostics.error(where, "file contains a NUL byte: it looks binary, not a .oasis spec");
      return false;
    }
    const std::size_t length = utf8_sequence_length(text, i);
    if (length == 0) {
      diagnostics.error(where, "invalid UTF-8 byte sequence: specs must be UTF-8 text");
      return false;
    }
    i += length;
  }
  return true;
}

}  // namespace oasis
