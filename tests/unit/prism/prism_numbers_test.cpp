// PRISM's number syntax (issue 39): the lexer takes exactly PRISM's REG_INT and REG_DOUBLE
// (".2", "1e-3", "1E+3"; not "2." or "2.e5"), ranges such as "0..5" still split at "..", and
// the values are exact. The crowds program, whose numbers start with their point as Storm's copy
// writes them (".8"), gives Storm's counts.

#include <sstream>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "prism/lexer.hpp"
#include "prism/load_program.hpp"

namespace oasis::prism {
namespace {

struct Lexed {
  std::vector<TokenKind> kinds;
  std::vector<std::string> texts;
  std::string messages;
};

Lexed lex_text(const std::string& text) {
  SourceManager sources;
  std::ostringstream out;
  DiagnosticEngine diagnostics(sources, out);
  const FileId file = sources.add("test.pm", text);
  Lexed lexed;
  for (const Token& token : lex(file, diagnostics)) {
    if (token.kind == TokenKind::EndOfFile) break;
    lexed.kinds.push_back(token.kind);
    lexed.texts.emplace_back(token.text);
  }
  lexed.messages = out.str();
  return lexed;
}

TEST(PrismNumbers, RealsMayStartWithTheirPointAndCarryAnExponent) {
  for (const char* text : {".2", "0.2", "1e-3", "1E+3", "2.5e2", ".5E-1", "12e3"}) {
    const Lexed lexed = lex_text(text);
    EXPECT_EQ(lexed.kinds, std::vector<TokenKind>{TokenKind::Real}) << text;
    EXPECT_EQ(lexed.texts, std::vector<std::string>{text});
    EXPECT_EQ(lexed.messages, "") << text;
  }
  EXPECT_EQ(lex_text("0").kinds, std::vector<TokenKind>{TokenKind::Integer});
  EXPECT_EQ(lex_text("42").kinds, std::vector<TokenKind>{TokenKind::Integer});
  // A leading zero makes REG_DOUBLE the longer match in PRISM's lexer.
  EXPECT_EQ(lex_text("007").kinds, std::vector<TokenKind>{TokenKind::Real});
}

TEST(PrismNumbers, APointWithoutDigitsAfterItIsNotPartOfTheNumber) {
  const std::vector<TokenKind> range = {TokenKind::Integer, TokenKind::DotDot, TokenKind::Integer};
  EXPECT_EQ(lex_text("0..5").kinds, range);
  EXPECT_EQ(lex_text("1 .. 5").kinds, range);
  EXPECT_EQ(lex_text("0...5").kinds,
            (std::vector<TokenKind>{TokenKind::Integer, TokenKind::DotDot, TokenKind::Real}));
  // "1e" is the integer 1 and the name e, as in PRISM.
  EXPECT_EQ(lex_text("1e").kinds,
            (std::vector<TokenKind>{TokenKind::Integer, TokenKind::Identifier}));
  // PRISM refuses "2." and "2.e5": the point is a character its lexer does not know.
  for (const char* text : {"2.", "2.e5"}) {
    EXPECT_NE(lex_text(text).messages.find("test.pm:1:2: error: unexpected character '.'"),
              std::string::npos)
        << text;
  }
}

model::ExplicitModel load(const std::string& text) {
  SourceManager sources;
  std::ostringstream out;
  DiagnosticEngine diagnostics(sources, out);
  const FileId file = sources.add("test.pm", text);
  std::optional<model::ExplicitModel> model =
      load_program_text(file, "test", diagnostics, LoadOptions{});
  EXPECT_TRUE(model) << out.str();
  return model ? std::move(*model) : model::ExplicitModel{};
}

TEST(PrismNumbers, ValuesAreExact) {
  const model::ExplicitModel m = load(R"(
dtmc
const double p = .25;
const double q = 75e-2;
module m
  x : [0..2] init 0;
  [] x=0 -> p : (x'=1) + q : (x'=2);
  [] x>0 -> true;
endmodule
)");
  ASSERT_EQ(m.num_states(), 3U);
  const model::TransitionMatrix& t = *m.contexts.at(0).transitions;
  ASSERT_EQ(t.edges_end(0, 0) - t.edges_begin(0, 0), 2U);
  EXPECT_EQ(m.values[t.edge_probability[t.edges_begin(0, 0)]], Rational(1, 4));
  EXPECT_EQ(m.values[t.edge_probability[t.edges_begin(0, 0) + 1]], Rational(3, 4));
}

TEST(PrismNumbers, CrowdsWrittenWithLeadingPointsGivesStormsCounts) {
  SourceManager sources;
  std::ostringstream out;
  DiagnosticEngine diagnostics(sources, out);
  LoadOptions options;
  options.constants = "TotalRuns=5";
  const std::optional<model::ExplicitModel> m =
      load_program(OASIS_SOURCE_DIR "/tests/data/prism/crowds5.pm", sources, diagnostics, options);
  ASSERT_TRUE(m) << out.str();
  EXPECT_EQ(m->num_states(), 8607U);
  EXPECT_EQ(m->contexts.at(0).transitions->num_edges(), 15113U);
}

}  // namespace
}  // namespace oasis::prism
