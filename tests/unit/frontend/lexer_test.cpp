// Unit tests of the spec lexer (compiler/frontend/lexer.cpp): token kinds and spellings, numbers,
// comments, and the errors for bad characters and unterminated comments with their line:col.

#include "frontend/lexer.hpp"

#include <sstream>
#include <string>
#include <vector>

#include <gtest/gtest.h>

namespace oasis::frontend {
namespace {

using K = TokenKind;

// Lexes `text` as the file "lex.oasis"; keeps the sources alive for the token views.
struct Lexed {
  explicit Lexed(std::string text) : diagnostics(sources, out) {
    file = sources.add("lex.oasis", std::move(text));
    tokens = lex(file, diagnostics);
  }

  [[nodiscard]] std::vector<K> kinds() const {
    std::vector<K> result;
    for (const Token& token : tokens)
      result.push_back(token.kind);
    return result;
  }
  [[nodiscard]] std::vector<std::string> texts() const {
    std::vector<std::string> result;
    for (const Token& token : tokens)
      result.emplace_back(token.text);
    return result;
  }
  [[nodiscard]] std::string output() const { return out.str(); }

  SourceManager sources;
  std::ostringstream out;
  DiagnosticEngine diagnostics;
  FileId file = 0;
  std::vector<Token> tokens;
};

TEST(Lexer, EmptyInputIsJustEndOfFile) {
  Lexed lexed("");
  ASSERT_EQ(lexed.tokens.size(), 1U);
  EXPECT_EQ(lexed.tokens[0].kind, K::EndOfFile);
  EXPECT_EQ(lexed.tokens[0].location.offset, 0U);
  EXPECT_FALSE(lexed.diagnostics.has_errors());
}

TEST(Lexer, WhitespaceOnlyInput) {
  Lexed lexed(" \t\r\n\f\v  \n");
  EXPECT_EQ(lexed.kinds(), std::vector<K>{K::EndOfFile});
  EXPECT_EQ(lexed.tokens[0].location.offset, 9U);  // end of file
  EXPECT_FALSE(lexed.diagnostics.has_errors());
}

TEST(Lexer, EveryKeyword) {
  Lexed lexed(
      "mdp catalog context states actions init const var continuous default reward region "
      "dynamics disturbance switching prior discount horizon period true false");
  EXPECT_EQ(
      lexed.kinds(),
      (std::vector<K>{K::KwMdp,    K::KwCatalog,  K::KwContext,  K::KwStates,      K::KwActions,
                      K::KwInit,   K::KwConst,    K::KwVar,      K::KwContinuous,  K::KwDefault,
                      K::KwReward, K::KwRegion,   K::KwDynamics, K::KwDisturbance, K::KwSwitching,
                      K::KwPrior,  K::KwDiscount, K::KwHorizon,  K::KwPeriod,      K::KwTrue,
                      K::KwFalse,  K::EndOfFile}));
  EXPECT_FALSE(lexed.diagnostics.has_errors());
}

TEST(Lexer, ContextualWordsAreIdentifiers) {
  // Only meaningful in one spot each; the parser matches them by spelling.
  Lexed lexed("stay in self disabled gaussian uniform base");
  EXPECT_EQ(lexed.kinds(),
            (std::vector<K>{K::Identifier, K::Identifier, K::Identifier, K::Identifier,
                            K::Identifier, K::Identifier, K::Identifier, K::EndOfFile}));
  EXPECT_EQ(lexed.texts(), (std::vector<std::string>{"stay", "in", "self", "disabled", "gaussian",
                                                     "uniform", "base", ""}));
}

TEST(Lexer, IdentifiersAndKeywordPrefixes) {
  // A keyword is a whole word: `mdp2`, `_var`, `States` and `contexts` are names.
  Lexed lexed("mdp2 _var States contexts x_1 A __");
  for (std::size_t i = 0; i + 1 < lexed.tokens.size(); ++i) {
    EXPECT_EQ(lexed.tokens[i].kind, K::Identifier) << lexed.tokens[i].text;
  }
  EXPECT_EQ(lexed.texts(),
            (std::vector<std::string>{"mdp2", "_var", "States", "contexts", "x_1", "A", "__", ""}));
}

TEST(Lexer, EveryPunctuator) {
  Lexed lexed("{ } [ ] ( ) , ; : ' = == != < <= > >= + - * / & && | || ! -> .. ~");
  EXPECT_EQ(lexed.kinds(),
            (std::vector<K>{
                K::LeftBrace,  K::RightBrace,   K::LeftBracket, K::RightBracket, K::LeftParen,
                K::RightParen, K::Comma,        K::Semicolon,   K::Colon,        K::Prime,
                K::Assign,     K::Equal,        K::NotEqual,    K::Less,         K::LessEqual,
                K::Greater,    K::GreaterEqual, K::Plus,        K::Minus,        K::Star,
                K::Slash,      K::And,          K::And,         K::Or,           K::Or,
                K::Not,        K::Arrow,        K::DotDot,      K::Tilde,        K::EndOfFile}));
  EXPECT_FALSE(lexed.diagnostics.has_errors());
}

TEST(Lexer, MaximalMunchWithoutSpaces) {
  Lexed lexed("x'=x+1;a->b<=c>=d!=e==f&&g||!h");
  EXPECT_EQ(lexed.texts(), (std::vector<std::string>{"x",  "'", "=",  "x", "+",  "1", ";",  "a",
                                                     "->", "b", "<=", "c", ">=", "d", "!=", "e",
                                                     "==", "f", "&&", "g", "||", "!", "h",  ""}));
  EXPECT_FALSE(lexed.diagnostics.has_errors());
}

TEST(Lexer, Numbers) {
  Lexed lexed("0 42 0.5 1e-3 2.5E2 1e+10 007");
  EXPECT_EQ(lexed.kinds(), (std::vector<K>{K::Number, K::Number, K::Number, K::Number, K::Number,
                                           K::Number, K::Number, K::EndOfFile}));
  EXPECT_EQ(lexed.texts(),
            (std::vector<std::string>{"0", "42", "0.5", "1e-3", "2.5E2", "1e+10", "007", ""}));
  EXPECT_FALSE(lexed.diagnostics.has_errors());
}

TEST(Lexer, RangeDotsAreNotADecimalPoint) {
  // A '.' is a decimal point only when a digit follows: `0..9` is 0 .. 9.
  Lexed lexed("[0..9] [0.5..1.5] [1 .. 2]");
  EXPECT_EQ(lexed.texts(), (std::vector<std::string>{"[", "0", "..", "9", "]", "[", "0.5", "..",
                                                     "1.5", "]", "[", "1", "..", "2", "]", ""}));
  EXPECT_EQ(lexed.tokens[1].kind, K::Number);
  EXPECT_EQ(lexed.tokens[2].kind, K::DotDot);
  EXPECT_EQ(lexed.tokens[3].kind, K::Number);
  EXPECT_FALSE(lexed.diagnostics.has_errors());
}

TEST(Lexer, ExponentNeedsDigits) {
  // `1e` is not a number: the letter makes it a bad name.
  Lexed lexed("1e");
  EXPECT_EQ(lexed.tokens[0].kind, K::Invalid);
  EXPECT_NE(lexed.output().find("lex.oasis:1:1: error: invalid number '1e': names cannot start "
                                "with a digit"),
            std::string::npos)
      << lexed.output();
  // `1e-` leaves the '-' for the next token.
  Lexed sign("2E-");
  EXPECT_EQ(sign.tokens[0].kind, K::Invalid);
  EXPECT_EQ(sign.tokens[1].kind, K::Minus);
}

TEST(Lexer, NameStartingWithADigitIsOneError) {
  Lexed lexed("x = 12abc + 1;");
  EXPECT_EQ(lexed.kinds(), (std::vector<K>{K::Identifier, K::Assign, K::Invalid, K::Plus, K::Number,
                                           K::Semicolon, K::EndOfFile}));
  EXPECT_EQ(lexed.tokens[2].text, "12abc");
  EXPECT_EQ(lexed.diagnostics.error_count(), 1U);
  EXPECT_NE(lexed.output().find("lex.oasis:1:5: error: invalid number '12abc'"), std::string::npos)
      << lexed.output();
}

TEST(Lexer, TokenLocationsAreByteOffsets) {
  Lexed lexed("mdp  m\n{ x }");
  ASSERT_EQ(lexed.tokens.size(), 6U);
  EXPECT_EQ(lexed.tokens[0].location.offset, 0U);
  EXPECT_EQ(lexed.tokens[1].location.offset, 5U);
  EXPECT_EQ(lexed.tokens[2].location.offset, 7U);
  EXPECT_EQ(lexed.tokens[3].location.offset, 9U);
  EXPECT_EQ(lexed.tokens[4].location.offset, 11U);
  EXPECT_EQ(lexed.tokens[5].location.offset, 12U);  // EndOfFile sits at the end
  EXPECT_EQ(lexed.tokens[0].location.file, lexed.file);
  EXPECT_EQ(lexed.tokens[0].length(), 3U);
}

TEST(Lexer, LineComments) {
  Lexed lexed("a // b c { }\nd // last line without newline");
  EXPECT_EQ(lexed.texts(), (std::vector<std::string>{"a", "d", ""}));
  EXPECT_FALSE(lexed.diagnostics.has_errors());
}

TEST(Lexer, BlockComments) {
  Lexed lexed("a /* b\n c * / ** */ d /**/ e /*/ f */ g/* x *//y");
  EXPECT_EQ(lexed.texts(), (std::vector<std::string>{"a", "d", "e", "g", "/", "y", ""}));
  EXPECT_EQ(lexed.tokens[4].kind, K::Slash);
  EXPECT_FALSE(lexed.diagnostics.has_errors());
}

TEST(Lexer, BlockCommentsDoNotNest) {
  Lexed lexed("a /* /* */ b */");
  EXPECT_EQ(lexed.kinds(),
            (std::vector<K>{K::Identifier, K::Identifier, K::Star, K::Slash, K::EndOfFile}));
}

TEST(Lexer, CommentsMayHoldAnyText) {
  Lexed lexed("a // café ☕ @ # $\nb /* ünïcödé\n@@ */ c");
  EXPECT_EQ(lexed.texts(), (std::vector<std::string>{"a", "b", "c", ""}));
  EXPECT_FALSE(lexed.diagnostics.has_errors());
}

TEST(Lexer, UnterminatedBlockComment) {
  Lexed lexed("mdp m {\n  states a; /* never\n closed");
  EXPECT_EQ(lexed.diagnostics.error_count(), 1U);
  EXPECT_NE(lexed.output().find("lex.oasis:2:13: error: unterminated '/*' comment"),
            std::string::npos)
      << lexed.output();
  // Everything up to the comment is lexed, then the file ends.
  EXPECT_EQ(lexed.texts(), (std::vector<std::string>{"mdp", "m", "{", "states", "a", ";", ""}));
  EXPECT_EQ(lexed.tokens.back().location.offset, lexed.sources.file(lexed.file).text().size());
}

TEST(Lexer, UnterminatedBlockCommentAtEndOfFile) {
  Lexed lexed("/*");
  EXPECT_EQ(lexed.diagnostics.error_count(), 1U);
  EXPECT_NE(lexed.output().find("lex.oasis:1:1: error: unterminated '/*' comment"),
            std::string::npos);
  EXPECT_EQ(lexed.kinds(), std::vector<K>{K::EndOfFile});
  Lexed star("/*/");  // the '*' of "/*" cannot also close it
  EXPECT_EQ(star.diagnostics.error_count(), 1U);
}

TEST(Lexer, InvalidCharactersWithLineAndColumn) {
  Lexed lexed("a @ b\n  # c\n$");
  EXPECT_EQ(lexed.kinds(), (std::vector<K>{K::Identifier, K::Invalid, K::Identifier, K::Invalid,
                                           K::Identifier, K::Invalid, K::EndOfFile}));
  EXPECT_EQ(lexed.diagnostics.error_count(), 3U);
  const std::string out = lexed.output();
  EXPECT_NE(out.find("lex.oasis:1:3: error: unexpected character '@'"), std::string::npos) << out;
  EXPECT_NE(out.find("lex.oasis:2:3: error: unexpected character '#'"), std::string::npos) << out;
  EXPECT_NE(out.find("lex.oasis:3:1: error: unexpected character '$'"), std::string::npos) << out;
}

TEST(Lexer, NonAsciiCharacterIsOneTokenAndOneColumn) {
  // 'é' is two bytes; the error shows the whole character, and columns count code points,
  // so the '@' after it is at column 6 although it is the 7th byte.
  Lexed lexed("x = é@;");
  EXPECT_EQ(lexed.kinds(), (std::vector<K>{K::Identifier, K::Assign, K::Invalid, K::Invalid,
                                           K::Semicolon, K::EndOfFile}));
  EXPECT_EQ(lexed.tokens[2].text, "é");
  EXPECT_EQ(lexed.tokens[2].location.offset, 4U);
  EXPECT_EQ(lexed.tokens[3].location.offset, 6U);
  const std::string out = lexed.output();
  EXPECT_NE(out.find("lex.oasis:1:5: error: unexpected character 'é'"), std::string::npos) << out;
  EXPECT_NE(out.find("lex.oasis:1:6: error: unexpected character '@'"), std::string::npos) << out;
}

TEST(Lexer, NonAsciiInCommentShiftsColumnsByCodePoints) {
  Lexed lexed("/* ☕☕ */ @");  // each ☕ is 3 bytes but one column
  EXPECT_NE(lexed.output().find("lex.oasis:1:10: error: unexpected character '@'"),
            std::string::npos)
      << lexed.output();
}

TEST(Lexer, NonAsciiLetterIsNotAnIdentifier) {
  Lexed lexed("states ñ;");
  EXPECT_EQ(lexed.kinds(), (std::vector<K>{K::KwStates, K::Invalid, K::Semicolon, K::EndOfFile}));
  EXPECT_NE(lexed.output().find("lex.oasis:1:8: error: unexpected character 'ñ'"),
            std::string::npos)
      << lexed.output();
}

TEST(Lexer, LoneDotGetsAHint) {
  Lexed lexed("p = .5;");
  EXPECT_EQ(lexed.kinds(), (std::vector<K>{K::Identifier, K::Assign, K::Invalid, K::Number,
                                           K::Semicolon, K::EndOfFile}));
  EXPECT_NE(lexed.output().find("lex.oasis:1:5: error: unexpected character '.' (decimals need "
                                "a digit on both sides of the point)"),
            std::string::npos)
      << lexed.output();
  Lexed trailing("1.;");  // `1.` is the number 1 and a stray point
  EXPECT_EQ(trailing.kinds(), (std::vector<K>{K::Number, K::Invalid, K::Semicolon, K::EndOfFile}));
  EXPECT_EQ(trailing.tokens[0].text, "1");
}

TEST(Lexer, ErrorsShowTheLineAndACaret) {
  Lexed lexed("  states a;\n  x = 1 @ 2;\n");
  EXPECT_EQ(lexed.output(),
            "lex.oasis:2:9: error: unexpected character '@'\n"
            "  x = 1 @ 2;\n"
            "        ^\n");
}

TEST(Lexer, StopsAtTheErrorLimit) {
  // 100 bad characters, but the engine asks to stop after 20 errors.
  SourceManager sources;
  std::ostringstream out;
  DiagnosticEngine diagnostics(sources, out, 20);
  const FileId file = sources.add("many.oasis", std::string(100, '@'));
  const std::vector<Token> tokens = lex(file, diagnostics);
  EXPECT_EQ(diagnostics.error_count(), 20U);
  EXPECT_TRUE(diagnostics.should_stop());
  EXPECT_LE(tokens.size(), 21U);
  EXPECT_EQ(tokens.back().kind, K::EndOfFile);
  EXPECT_NE(out.str().find("fatal error: too many errors emitted, stopping now"),
            std::string::npos);
}

TEST(Lexer, DescribeTokenKinds) {
  EXPECT_EQ(describe(K::LeftBrace), "'{'");
  EXPECT_EQ(describe(K::Identifier), "name");
  EXPECT_EQ(describe(K::EndOfFile), "end of file");
  EXPECT_EQ(describe(K::KwMdp), "mdp");
  EXPECT_EQ(describe(K::KwFalse), "false");
  EXPECT_EQ(describe(K::Arrow), "'->'");
}

}  // namespace
}  // namespace oasis::frontend
