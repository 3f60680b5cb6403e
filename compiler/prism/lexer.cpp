#include "prism/lexer.hpp"

#include <algorithm>
#include <array>
#include <optional>
#include <string>

namespace oasis::prism {
namespace {

bool is_identifier_start(char c) {
  return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || c == '_';
}
bool is_digit(char c) {
  return c >= '0' && c <= '9';
}
bool is_identifier_char(char c) {
  return is_identifier_start(c) || is_digit(c);
}

struct Symbol {
  std::string_view spelling;
  TokenKind kind;
};

// Longest spellings first, so that "<=>" is not read as "<=" then ">".
constexpr std::array kSymbols = {
    Symbol{"<=>", TokenKind::Iff},        Symbol{"->", TokenKind::Arrow},
    Symbol{"=>", TokenKind::Implies},     Symbol{"!=", TokenKind::NotEqual},
    Symbol{"<=", TokenKind::LessEqual},   Symbol{">=", TokenKind::GreaterEqual},
    Symbol{"..", TokenKind::DotDot},      Symbol{"(", TokenKind::LeftParen},
    Symbol{")", TokenKind::RightParen},   Symbol{"[", TokenKind::LeftBracket},
    Symbol{"]", TokenKind::RightBracket}, Symbol{"{", TokenKind::LeftBrace},
    Symbol{"}", TokenKind::RightBrace},   Symbol{";", TokenKind::Semicolon},
    Symbol{":", TokenKind::Colon},        Symbol{",", TokenKind::Comma},
    Symbol{"'", TokenKind::Prime},        Symbol{"=", TokenKind::Equal},
    Symbol{"<", TokenKind::Less},         Symbol{">", TokenKind::Greater},
    Symbol{"+", TokenKind::Plus},         Symbol{"-", TokenKind::Minus},
    Symbol{"*", TokenKind::Star},         Symbol{"/", TokenKind::Slash},
    Symbol{"&", TokenKind::And},          Symbol{"|", TokenKind::Or},
    Symbol{"!", TokenKind::Not},          Symbol{"?", TokenKind::Question},
};

class Lexer {
 public:
  Lexer(FileId file, DiagnosticEngine& diagnostics)
      : file_(file), text_(diagnostics.sources().file(file).text()), diagnostics_(diagnostics) {}
  // Only [begin, end) of the file; tokens keep their places in the whole file.
  Lexer(FileId file, std::size_t begin, std::size_t end, DiagnosticEngine& diagnostics)
      : Lexer(file, diagnostics) {
    text_ = text_.substr(0, std::min(end, text_.size()));
    pos_ = std::min(begin, text_.size());
  }

  std::vector<Token> run() {
    std::vector<Token> tokens;
    for (;;) {
      skip_space_and_comments();
      if (pos_ >= text_.size() || diagnostics_.should_stop()) break;
      if (auto token = next()) tokens.push_back(*token);
    }
    tokens.push_back(make(TokenKind::EndOfFile, pos_, pos_));
    return tokens;
  }

 private:
  void skip_space_and_comments() {
    while (pos_ < text_.size()) {
      const char c = text_[pos_];
      if (c == ' ' || c == '\t' || c == '\n' || c == '\r') {
        ++pos_;
      } else if (text_.substr(pos_, 2) == "//") {
        while (pos_ < text_.size() && text_[pos_] != '\n')
          ++pos_;
      } else {
        return;
      }
    }
  }

  std::optional<Token> next() {
    const std::size_t start = pos_;
    const char c = text_[pos_];
    if (is_identifier_start(c)) {
      while (pos_ < text_.size() && is_identifier_char(text_[pos_]))
        ++pos_;
      return make(TokenKind::Identifier, start, pos_);
    }
    if (is_digit(c) || (c == '.' && pos_ + 1 < text_.size() && is_digit(text_[pos_ + 1]))) {
      return number(start);
    }
    if (c == '"') return string(start);
    for (const Symbol& symbol : kSymbols) {
      if (text_.substr(pos_, symbol.spelling.size()) == symbol.spelling) {
        pos_ += symbol.spelling.size();
        return make(symbol.kind, start, pos_);
      }
    }
    // A run of characters PRISM does not use is one error, not one per byte. The first is
    // always taken: a '.' that starts no ".." and no number is a known start but no token.
    do {
      ++pos_;
    } while (pos_ < text_.size() && !known_start(text_[pos_]));
    diagnostics_.error(range(start, pos_),
                       "unexpected character " + shown(text_[start]) + " in a PRISM program");
    return std::nullopt;
  }

  static bool known_start(char c) {
    if (is_identifier_char(c) || c == '"' || c == ' ' || c == '\t' || c == '\n' || c == '\r' ||
        c == '/') {
      return true;
    }
    for (const Symbol& symbol : kSymbols) {
      if (symbol.spelling[0] == c) return true;
    }
    return false;
  }

  static std::string shown(char c) {
    const auto byte = static_cast<unsigned char>(c);
    if (byte >= 0x20 && byte < 0x7F) return std::string("'") + c + "'";
    static constexpr char kHex[] = "0123456789abcdef";
    return std::string("byte 0x") + kHex[byte >> 4] + kHex[byte & 0xF];
  }

  // PRISM's REG_DOUBLE is [digits] [.] digits [e [+-] digits], and its REG_INT is 0 or a
  // digit string without a leading zero; JavaCC takes the longest match, the integer on a
  // tie. So ".2" and "1e-3" are reals, "2." is the integer 2 then a stray '.', "007" is a real
  // (and refused where an int is needed, as in PRISM), and "0..5" is 0, "..", 5: a '.' belongs
  // to the number only when a digit follows it.
  Token number(std::size_t start) {
    skip_digits();
    bool real = pos_ - start > 1 && text_[start] == '0';
    if (pos_ + 1 < text_.size() && text_[pos_] == '.' && is_digit(text_[pos_ + 1])) {
      real = true;
      ++pos_;
      skip_digits();
    }
    if (pos_ < text_.size() && (text_[pos_] == 'e' || text_[pos_] == 'E')) {
      std::size_t after = pos_ + 1;
      if (after < text_.size() && (text_[after] == '+' || text_[after] == '-')) ++after;
      if (after < text_.size() && is_digit(text_[after])) {
        real = true;
        pos_ = after;
        skip_digits();
      }
    }
    return make(real ? TokenKind::Real : TokenKind::Integer, start, pos_);
  }

  void skip_digits() {
    while (pos_ < text_.size() && is_digit(text_[pos_]))
      ++pos_;
  }

  std::optional<Token> string(std::size_t start) {
    ++pos_;
    while (pos_ < text_.size() && text_[pos_] != '"' && text_[pos_] != '\n')
      ++pos_;
    if (pos_ >= text_.size() || text_[pos_] != '"') {
      diagnostics_.error(range(start, start + 1), "string not closed on its line");
      return std::nullopt;
    }
    ++pos_;
    Token token = make(TokenKind::String, start, pos_);
    token.text = text_.substr(start + 1, pos_ - start - 2);
    return token;
  }

  [[nodiscard]] SourceRange range(std::size_t begin, std::size_t end) const {
    return {SourceLocation{file_, static_cast<std::uint32_t>(begin)},
            static_cast<std::uint32_t>(end > begin ? end - begin : 1)};
  }
  [[nodiscard]] Token make(TokenKind kind, std::size_t begin, std::size_t end) const {
    return Token{kind, text_.substr(begin, end - begin), range(begin, end)};
  }

  FileId file_;
  std::string_view text_;
  DiagnosticEngine& diagnostics_;
  std::size_t pos_ = 0;
};

}  // namespace

std::string_view spell(TokenKind kind) {
  switch (kind) {
    case TokenKind::EndOfFile:
      return "the end of the file";
    case TokenKind::Identifier:
      return "a name";
    case TokenKind::Integer:
      return "an integer";
    case TokenKind::Real:
      return "a number";
    case TokenKind::String:
      return "a quoted name";
    default:
      break;
  }
  for (const Symbol& symbol : kSymbols) {
    if (symbol.kind == kind) return symbol.spelling;
  }
  return "?";
}

std::vector<Token> lex(FileId file, DiagnosticEngine& diagnostics) {
  return Lexer(file, diagnostics).run();
}

std::vector<Token> lex(SourceRange range, DiagnosticEngine& diagnostics) {
  return Lexer(range.begin.file, range.begin.offset, range.begin.offset + range.length, diagnostics)
      .run();
}

}  // namespace oasis::prism
