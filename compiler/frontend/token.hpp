#pragma once
// Tokens of the .oasis spec language (docs/spec-language.md).

#include <cstdint>
#include <string_view>

#include "support/rational.hpp"
#include "support/source_manager.hpp"

namespace oasis::frontend {

enum class TokenKind : std::uint8_t {
  EndOfFile,
  Identifier,
  Number,
  String,  // "text" on one line; the token's text keeps the quotes
  // Keywords.
  // Reserved words. Words that only mean something in one spot (self, disabled, in, gaussian,
  // stay, uniform, base) are not reserved: the parser recognises them there by spelling.
  KwMdp,
  KwCatalog,
  KwContext,
  KwStates,
  KwActions,
  KwInit,
  KwConst,
  KwVar,
  KwContinuous,
  KwDefault,
  KwReward,
  KwRegion,
  KwDynamics,
  KwDisturbance,
  KwSwitching,
  KwPrior,
  KwDiscount,
  KwHorizon,
  KwPeriod,
  KwImport,
  KwTrue,
  KwFalse,
  // Punctuation and operators.
  LeftBrace,
  RightBrace,
  LeftBracket,
  RightBracket,
  LeftParen,
  RightParen,
  Comma,
  Semicolon,
  Colon,
  Prime,
  Assign,
  Equal,
  NotEqual,
  Less,
  LessEqual,
  Greater,
  GreaterEqual,
  Plus,
  Minus,
  Star,
  Slash,
  Caret,
  And,
  Or,
  Not,
  Arrow,
  DotDot,
  Tilde,
  // The text of a PRISM property after `property NAME =`, up to (not with) its `;`: the
  // property language (docs/properties.md) has its own lexer, so the spec's keeps it whole.
  PropertyText,
  Invalid,  // the lexer has reported an error for it
};

struct Token {
  TokenKind kind = TokenKind::EndOfFile;
  std::string_view text;  // points into the source file
  SourceLocation location;

  [[nodiscard]] bool is(TokenKind k) const { return kind == k; }
  [[nodiscard]] std::uint32_t length() const { return static_cast<std::uint32_t>(text.size()); }
};

// How a token kind is spelled in messages: "'{'", "identifier", "'mdp'".
std::string_view describe(TokenKind kind);
using oasis::describe;  // keep describe(Rational) visible beside the overload above

}  // namespace oasis::frontend
