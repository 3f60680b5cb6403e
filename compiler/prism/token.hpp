#pragma once
// Tokens of the PRISM language (docs/formats.md, "PRISM programs"). Keywords are lexed as
// identifiers: the parser recognises them by spelling, and refuses them as names.

#include <cstdint>
#include <string_view>

#include "support/diagnostics.hpp"

namespace oasis::prism {

enum class TokenKind : std::uint8_t {
  EndOfFile,
  Identifier,
  Integer,  // 42
  Real,     // 0.5, 1e-3
  String,   // "name", the quotes excluded from `text`
  LeftParen,
  RightParen,
  LeftBracket,
  RightBracket,
  LeftBrace,
  RightBrace,
  Semicolon,
  Colon,
  Comma,
  Prime,     // '
  DotDot,    // ..
  Arrow,     // ->
  Implies,   // =>
  Iff,       // <=>
  Equal,     // =
  NotEqual,  // !=
  Less,
  LessEqual,
  Greater,
  GreaterEqual,
  Plus,
  Minus,
  Star,
  Slash,
  And,       // &
  Or,        // |
  Not,       // !
  Question,  // ?
};

struct Token {
  TokenKind kind = TokenKind::EndOfFile;
  std::string_view text;  // a view into the source file
  SourceRange range;
};

// What a token kind looks like in a message: "';'", "an identifier".
std::string_view spell(TokenKind kind);

}  // namespace oasis::prism
