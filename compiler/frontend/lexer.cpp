#include "frontend/lexer.hpp"

#include <array>
#include <string>
#include <utility>

namespace oasis::frontend {
namespace {

struct Keyword {
  std::string_view spelling;
  TokenKind kind;
};

constexpr std::array kKeywords = {
    Keyword{"mdp", TokenKind::KwMdp},
    Keyword{"catalog", TokenKind::KwCatalog},
    Keyword{"context", TokenKind::KwContext},
    Keyword{"states", TokenKind::KwStates},
    Keyword{"actions", TokenKind::KwActions},
    Keyword{"init", TokenKind::KwInit},
    Keyword{"const", TokenKind::KwConst},
    Keyword{"var", TokenKind::KwVar},
    Keyword{"continuous", TokenKind::KwContinuous},
    Keyword{"default", TokenKind::KwDefault},
    Keyword{"reward", TokenKind::KwReward},
    Keyword{"region", TokenKind::KwRegion},
    Keyword{"dynamics", TokenKind::KwDynamics},
    Keyword{"disturbance", TokenKind::KwDisturbance},
    Keyword{"switching", TokenKind::KwSwitching},
    Keyword{"prior", TokenKind::KwPrior},
    Keyword{"discount", TokenKind::KwDiscount},
    Keyword{"horizon", TokenKind::KwHorizon},
    Keyword{"period", TokenKind::KwPeriod},
    Keyword{"import", TokenKind::KwImport},
    Keyword{"true", TokenKind::KwTrue},
    Keyword{"false", TokenKind::KwFalse},
};

bool is_identifier_start(char c) {
  return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || c == '_';
}
bool is_digit(char c) {
  return c >= '0' && c <= '9';
}
bool is_identifier_char(char c) {
  return is_identifier_start(c) || is_digit(c);
}

class Lexer {
 public:
  Lexer(FileId file, DiagnosticEngine& diagnostics)
      : file_(file), text_(diagnostics.sources().file(file).text()), diagnostics_(diagnostics) {}

  std::vector<Token> run() {
    std::vector<Token> tokens;
    for (;;) {
      skip_space_and_comments();
      if (diagnostics_.should_stop()) break;
      if (pos_ >= text_.size()) break;
      tokens.push_back(next());
      if (starts_property(tokens)) tokens.push_back(property_text());
    }
    tokens.push_back(make(TokenKind::EndOfFile, text_.size(), text_.size()));
    return tokens;
  }

 private:
  Token make(TokenKind kind, std::size_t begin, std::size_t end) const {
    return Token{kind, text_.substr(begin, end - begin),
                 SourceLocation{file_, static_cast<std::uint32_t>(begin)}};
  }

  [[nodiscard]] char peek(std::size_t ahead = 0) const {
    return pos_ + ahead < text_.size() ? text_[pos_ + ahead] : '\0';
  }

  void skip_space_and_comments() {
    while (pos_ < text_.size()) {
      const char c = text_[pos_];
      if (c == ' ' || c == '\t' || c == '\n' || c == '\r' || c == '\f' || c == '\v') {
        ++pos_;
      } else if (c == '/' && peek(1) == '/') {
        while (pos_ < text_.size() && text_[pos_] != '\n')
          ++pos_;
      } else if (c == '/' && peek(1) == '*') {
        skip_block_comment();
      } else {
        return;
      }
    }
  }

  void skip_block_comment() {
    const std::size_t begin = pos_;
    const std::size_t end = text_.find("*/", pos_ + 2);
    if (end == std::string_view::npos) {
      diagnostics_.error(SourceRange{{file_, static_cast<std::uint32_t>(begin)}, 2},
                         "unterminated '/*' comment");
      pos_ = text_.size();
      return;
    }
    pos_ = end + 2;
  }

  // `property NAME =` just read: the property's text follows.
  static bool starts_property(const std::vector<Token>& tokens) {
    const std::size_t n = tokens.size();
    return n >= 3 && tokens[n - 1].is(TokenKind::Assign) &&
           tokens[n - 2].is(TokenKind::Identifier) && tokens[n - 3].is(TokenKind::Identifier) &&
           tokens[n - 3].text == "property";
  }

  // Everything up to the next `;` outside a quoted label and a `//` comment, blanks trimmed:
  // the property language's own lexer reads it later, with its errors placed in this file.
  Token property_text() {
    skip_space_and_comments();
    const std::size_t begin = pos_;
    std::size_t end = begin;
    while (pos_ < text_.size() && text_[pos_] != ';') {
      if (text_[pos_] == '"') {
        const std::size_t close = text_.find_first_of("\"\n", pos_ + 1);
        pos_ = close == std::string_view::npos || text_[close] == '\n' ? close : close + 1;
        if (pos_ == std::string_view::npos) pos_ = text_.size();
      } else if (text_[pos_] == '/' && peek(1) == '/') {
        skip_space_and_comments();
        continue;
      } else {
        ++pos_;
      }
      end = pos_;
      skip_space_and_comments();
    }
    return make(TokenKind::PropertyText, begin, end);
  }

  Token next() {
    const std::size_t begin = pos_;
    const char c = text_[pos_];
    if (is_identifier_start(c)) return identifier(begin);
    if (is_digit(c)) return number(begin);
    if (c == '"') return string(begin);
    if (auto kind = punctuation(); kind != TokenKind::Invalid) return make(kind, begin, pos_);
    return invalid_character(begin);
  }

  Token identifier(std::size_t begin) {
    while (pos_ < text_.size() && is_identifier_char(text_[pos_]))
      ++pos_;
    const std::string_view word = text_.substr(begin, pos_ - begin);
    for (const Keyword& keyword : kKeywords) {
      if (keyword.spelling == word) return make(keyword.kind, begin, pos_);
    }
    return make(TokenKind::Identifier, begin, pos_);
  }

  // digits [ '.' digits ] [ ('e'|'E') ['+'|'-'] digits ]. A '.' is a decimal point only
  // when a digit follows, so that `0..9` lexes as 0 .. 9.
  Token number(std::size_t begin) {
    while (is_digit(peek()))
      ++pos_;
    if (peek() == '.' && is_digit(peek(1))) {
      ++pos_;
      while (is_digit(peek()))
        ++pos_;
    }
    if ((peek() == 'e' || peek() == 'E') &&
        (is_digit(peek(1)) || ((peek(1) == '+' || peek(1) == '-') && is_digit(peek(2))))) {
      pos_ += 2;
      while (is_digit(peek()))
        ++pos_;
    }
    if (is_identifier_start(peek())) {
      std::size_t end = pos_;
      while (end < text_.size() && is_identifier_char(text_[end]))
        ++end;
      diagnostics_.error(SourceRange{{file_, static_cast<std::uint32_t>(begin)},
                                     static_cast<std::uint32_t>(end - begin)},
                         "invalid number '" + std::string(text_.substr(begin, end - begin)) +
                             "': names cannot start with a digit");
      pos_ = end;
      return make(TokenKind::Invalid, begin, end);
    }
    return make(TokenKind::Number, begin, pos_);
  }

  TokenKind punctuation() {
    auto take = [this](std::size_t n, TokenKind kind) {
      pos_ += n;
      return kind;
    };
    const char c = peek();
    const char d = peek(1);
    switch (c) {
      case '{':
        return take(1, TokenKind::LeftBrace);
      case '}':
        return take(1, TokenKind::RightBrace);
      case '[':
        return take(1, TokenKind::LeftBracket);
      case ']':
        return take(1, TokenKind::RightBracket);
      case '(':
        return take(1, TokenKind::LeftParen);
      case ')':
        return take(1, TokenKind::RightParen);
      case ',':
        return take(1, TokenKind::Comma);
      case ';':
        return take(1, TokenKind::Semicolon);
      case ':':
        return take(1, TokenKind::Colon);
      case '\'':
        return take(1, TokenKind::Prime);
      case '+':
        return take(1, TokenKind::Plus);
      case '*':
        return take(1, TokenKind::Star);
      case '/':
        return take(1, TokenKind::Slash);
      case '^':
        return take(1, TokenKind::Caret);
      case '&':
        return take(d == '&' ? 2 : 1, TokenKind::And);
      case '|':
        return take(d == '|' ? 2 : 1, TokenKind::Or);
      case '~':
        return take(1, TokenKind::Tilde);
      case '-':
        return d == '>' ? take(2, TokenKind::Arrow) : take(1, TokenKind::Minus);
      case '=':
        return d == '=' ? take(2, TokenKind::Equal) : take(1, TokenKind::Assign);
      case '!':
        return d == '=' ? take(2, TokenKind::NotEqual) : take(1, TokenKind::Not);
      case '<':
        return d == '=' ? take(2, TokenKind::LessEqual) : take(1, TokenKind::Less);
      case '>':
        return d == '=' ? take(2, TokenKind::GreaterEqual) : take(1, TokenKind::Greater);
      case '.':
        if (d == '.') return take(2, TokenKind::DotDot);
        break;
      default:
        break;
    }
    return TokenKind::Invalid;
  }

  // A file name in `import "robot.nm"` or a reward structure's name: no escapes, one line.
  Token string(std::size_t begin) {
    const std::size_t close = text_.find_first_of("\"\n", begin + 1);
    if (close == std::string_view::npos || text_[close] != '"') {
      diagnostics_.error(SourceRange{{file_, static_cast<std::uint32_t>(begin)}, 1},
                         "string not closed on its line");
      pos_ = close == std::string_view::npos ? text_.size() : close;
      return make(TokenKind::Invalid, begin, pos_);
    }
    pos_ = close + 1;
    return make(TokenKind::String, begin, pos_);
  }

  Token invalid_character(std::size_t begin) {
    // Take the whole UTF-8 sequence so the message shows the character, not a byte.
    std::size_t end = begin + 1;
    while (end < text_.size() && (static_cast<unsigned char>(text_[end]) & 0xC0U) == 0x80U)
      ++end;
    pos_ = end;
    const std::string_view character = text_.substr(begin, end - begin);
    std::string message = "unexpected character '" + std::string(character) + "'";
    if (character == ".") message += " (decimals need a digit on both sides of the point)";
    diagnostics_.error(SourceRange{{file_, static_cast<std::uint32_t>(begin)}, 1}, message);
    return make(TokenKind::Invalid, begin, end);
  }

  FileId file_;
  std::string_view text_;
  DiagnosticEngine& diagnostics_;
  std::size_t pos_ = 0;
};

}  // namespace

std::string_view describe(TokenKind kind) {
  switch (kind) {
    case TokenKind::EndOfFile:
      return "end of file";
    case TokenKind::Identifier:
      return "name";
    case TokenKind::Number:
      return "number";
    case TokenKind::String:
      return "string";
    case TokenKind::LeftBrace:
      return "'{'";
    case TokenKind::RightBrace:
      return "'}'";
    case TokenKind::LeftBracket:
      return "'['";
    case TokenKind::RightBracket:
      return "']'";
    case TokenKind::LeftParen:
      return "'('";
    case TokenKind::RightParen:
      return "')'";
    case TokenKind::Comma:
      return "','";
    case TokenKind::Semicolon:
      return "';'";
    case TokenKind::Colon:
      return "':'";
    case TokenKind::Prime:
      return "'''";
    case TokenKind::Assign:
      return "'='";
    case TokenKind::Equal:
      return "'=='";
    case TokenKind::NotEqual:
      return "'!='";
    case TokenKind::Less:
      return "'<'";
    case TokenKind::LessEqual:
      return "'<='";
    case TokenKind::Greater:
      return "'>'";
    case TokenKind::GreaterEqual:
      return "'>='";
    case TokenKind::Plus:
      return "'+'";
    case TokenKind::Minus:
      return "'-'";
    case TokenKind::Star:
      return "'*'";
    case TokenKind::Slash:
      return "'/'";
    case TokenKind::Caret:
      return "'^'";
    case TokenKind::And:
      return "'&'";
    case TokenKind::Or:
      return "'|'";
    case TokenKind::Not:
      return "'!'";
    case TokenKind::Arrow:
      return "'->'";
    case TokenKind::DotDot:
      return "'..'";
    case TokenKind::Tilde:
      return "'~'";
    case TokenKind::PropertyText:
      return "property";
    case TokenKind::Invalid:
      return "invalid token";
    default:
      break;
  }
  for (const Keyword& keyword : kKeywords) {
    if (keyword.kind == kind) return keyword.spelling;
  }
  return "token";
}

bool is_identifier(std::string_view text) {
  if (text.empty() || !is_identifier_start(text.front())) return false;
  for (const char c : text)
    if (!is_identifier_char(c)) return false;
  for (const Keyword& keyword : kKeywords)
    if (keyword.spelling == text) return false;
  return true;
}

std::vector<Token> lex(FileId file, DiagnosticEngine& diagnostics) {
  return Lexer(file, diagnostics).run();
}

}  // namespace oasis::frontend
