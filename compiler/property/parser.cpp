#include "property/parser.hpp"

#include <array>
#include <string>
#include <utility>

#include "prism/expression_parser.hpp"
#include "prism/lexer.hpp"
#include "support/text.hpp"

namespace oasis::property {
namespace {

using prism::Token;
using prism::TokenKind;
namespace ast = prism::ast;

class PropertyParser : public prism::ExpressionParser {
 public:
  PropertyParser(const std::vector<Token>& tokens, DiagnosticEngine& diagnostics)
      : ExpressionParser(tokens, diagnostics) {}

  PropertiesFile run() {
    while (!at(TokenKind::EndOfFile) && !diagnostics_.should_stop()) {
      try {
        if (definition()) continue;
        file_.properties.push_back(property());
        if (!accept(TokenKind::Semicolon) && !at(TokenKind::EndOfFile) &&
            !starts_property(peek())) {
          fail(peek(), "expected ';' or the end of the property, found " + describe(peek()));
        }
      } catch (const prism::SyntaxError&) {
        skip_past_semicolon();
      }
    }
    return std::move(file_);
  }

 private:
  // A token that can only start a new property (PRISM lets properties follow one another on
  // their own lines, without a ';').
  static bool starts_property(const Token& token) {
    return token.kind == TokenKind::String ||
           (token.kind == TokenKind::Identifier &&
            (token.text == "P" || token.text == "Pmin" || token.text == "Pmax" ||
             token.text == "R" || token.text == "Rmin" || token.text == "Rmax" ||
             token.text == "filter"));
  }

  // `const [int|double|bool] NAME = value;` or `label "NAME" = value;`; false at anything else.
  bool definition() {
    if (!at(TokenKind::Identifier)) return false;
    if (peek().text == "const") {
      advance();
      if (at(TokenKind::Identifier) &&
          (peek().text == "int" || peek().text == "double" || peek().text == "bool"))
        advance();
      const Token& name = identifier("a constant's name");
      if (!at(TokenKind::Equal)) {
        fail(peek(),
             "a constant of a properties file needs its value here ('= ...'): --const "
             "sets the program's constants only");
      }
      advance();
      depth_ = 0;
      file_.constants.push_back({std::string(name.text), expression(), name.range});
    } else if (peek().text == "label") {
      advance();
      const Token& name = peek();
      if (name.kind != TokenKind::String) fail(name, "expected the label's name in quotes");
      advance();
      expect(TokenKind::Equal, "after the label's name");
      depth_ = 0;
      file_.labels.push_back({std::string(name.text), expression(), name.range});
    } else {
      return false;
    }
    expect(TokenKind::Semicolon, "to end the definition");
    return true;
  }

  Property property() {
    Property result;
    const Token& first = peek();
    if (at(TokenKind::String) && peek(1).kind == TokenKind::Colon) {
      result.name = std::string(advance().text);
      advance();  // :
    }
    depth_ = 0;
    result.expression = expression();
    result.range = span(first.range, result.expression.range);
    result.text = text_of(result.expression.range);
    return result;
  }

  std::string text_of(SourceRange range) const {
    const std::string_view text = diagnostics_.sources().file(range.begin.file).text();
    if (range.begin.offset >= text.size()) return {};
    return collapse_blanks(text.substr(range.begin.offset, range.length));
  }

  // Line breaks and runs of blanks inside a property become one space, for its answer line.
  static std::string collapse_blanks(std::string_view text) {
    std::string out;
    bool blank = false;
    for (const char c : text) {
      const bool is_blank = c == ' ' || c == '\t' || c == '\n' || c == '\r';
      if (is_blank) {
        blank = !out.empty();
        continue;
      }
      if (blank) out += ' ';
      blank = false;
      out += c;
    }
    return out;
  }

  // --- The property language's primaries -----------------------------------------------------

  std::optional<ast::Expr> extended_primary() override {
    const Token& token = peek();
    if (token.kind == TokenKind::String) {
      advance();
      return extension(LabelReference{std::string(token.text), token.range}, token.range);
    }
    if (token.kind != TokenKind::Identifier) return std::nullopt;
    if (token.text == "P" || token.text == "Pmin" || token.text == "Pmax") return probability();
    if (token.text == "R" || token.text == "Rmin" || token.text == "Rmax") return reward();
    if (token.text == "filter" && peek(1).kind == TokenKind::LeftParen) return filter();
    if (token.text == "F" || token.text == "G" || token.text == "X" || token.text == "U" ||
        token.text == "I" || token.text == "C") {
      fail(token, "the temporal operator '" + std::string(token.text) +
                      "' must stand inside P[ ... ] or R[ ... ]");
    }
    return std::nullopt;
  }

  ast::Expr extension(Extension node, SourceRange range) {
    ast::Expr expr;
    expr.kind = ast::Expr::Kind::Extension;
    expr.text = std::to_string(file_.extensions.size());
    expr.range = range;
    file_.extensions.push_back(std::move(node));
    return expr;
  }

  ast::Expr probability() {
    const Token& head = advance();
    Quantifier q;
    q.optimum = optimum_of(head.text);
    return bracketed(std::move(q), head, "path formula",
                     [this](Quantifier& node) { node.path = path_formula(); });
  }

  ast::Expr reward() {
    const Token& head = advance();
    Quantifier q;
    q.reward = true;
    q.optimum = optimum_of(head.text);
    if (accept(TokenKind::LeftBrace)) {
      const Token& name = peek();
      if (name.kind != TokenKind::String) {
        fail(name, "expected the reward structure's name in quotes, found " + describe(name));
      }
      advance();
      q.reward_name = std::string(name.text);
      q.reward_name_range = name.range;
      expect(TokenKind::RightBrace, "after the reward structure's name");
    }
    if (q.optimum == Quantifier::Optimum::kNone && at(TokenKind::Identifier) &&
        (peek().text == "min" || peek().text == "max")) {
      q.optimum = advance().text == "min" ? Quantifier::Optimum::kMin : Quantifier::Optimum::kMax;
    }
    return bracketed(std::move(q), head, "reward formula",
                     [this](Quantifier& node) { node.reward_formula = reward_formula(); });
  }

  // The rest of an operator after its name: the comparison, then `[ inner ]`, which `read`
  // parses into the node; the node spans from its name to the ']'.
  template <typename ReadInner>
  ast::Expr bracketed(Quantifier q, const Token& head, const std::string& inner, ReadInner read) {
    read_comparison(q, head);
    q.head_range = span(head.range, tokens_[pos_ - 1].range);
    nest();
    expect(TokenKind::LeftBracket, "to open the " + inner);
    read(q);
    const Token& close = expect(TokenKind::RightBracket, "to close the " + inner);
    --depth_;
    q.range = span(head.range, close.range);
    const SourceRange range = q.range;
    return extension(std::move(q), range);
  }

  static Quantifier::Optimum optimum_of(std::string_view head) {
    if (head.ends_with("min")) return Quantifier::Optimum::kMin;
    if (head.ends_with("max")) return Quantifier::Optimum::kMax;
    return Quantifier::Optimum::kNone;
  }

  // `=?`, or a comparison with a bound: `>=0.5`.
  void read_comparison(Quantifier& q, const Token& head) {
    if (accept(TokenKind::Equal)) {
      expect(TokenKind::Question, "after '=' (a query is written '=?')");
      return;
    }
    switch (peek().kind) {
      case TokenKind::Less:
        q.comparison = Quantifier::Comparison::kLess;
        break;
      case TokenKind::LessEqual:
        q.comparison = Quantifier::Comparison::kLessEqual;
        break;
      case TokenKind::Greater:
        q.comparison = Quantifier::Comparison::kGreater;
        break;
      case TokenKind::GreaterEqual:
        q.comparison = Quantifier::Comparison::kGreaterEqual;
        break;
      default:
        fail(peek(), "expected '=?' or a bound such as '>=0.5' after " + quoted(head.text) +
                         ", found " + describe(peek()));
    }
    advance();
    q.bound = expression();  // the '[' that follows ends it
  }

  PathFormula path_formula() {
    PathFormula path;
    const Token& start = peek();
    if (at(TokenKind::Identifier) &&
        (start.text == "F" || start.text == "G" || start.text == "X")) {
      advance();
      path.kind = start.text == "F"   ? PathFormula::Kind::kEventually
                  : start.text == "G" ? PathFormula::Kind::kGlobally
                                      : PathFormula::Kind::kNext;
      if (path.kind != PathFormula::Kind::kNext) read_step_bound(path);
      path.right = expression();
    } else {
      path.kind = PathFormula::Kind::kUntil;
      path.left = expression();
      if (!(at(TokenKind::Identifier) && peek().text == "U")) {
        fail(peek(),
             "expected a path formula (F, G, X or U) inside P[ ... ], found " + describe(peek()));
      }
      advance();
      read_step_bound(path);
      path.right = expression();
    }
    path.range = span(start.range, path.right.range);
    return path;
  }

  void read_step_bound(PathFormula& path) {
    if (at(TokenKind::LessEqual) || at(TokenKind::Less)) {
      path.strict_bound = advance().kind == TokenKind::Less;
      path.steps = unary();
      return;
    }
    if (at(TokenKind::GreaterEqual) || at(TokenKind::Greater) || at(TokenKind::LeftBracket) ||
        at(TokenKind::Equal)) {
      fail(peek(), "only upper step bounds ('<=k', '<k') are supported on a path formula");
    }
  }

  RewardFormula reward_formula() {
    RewardFormula formula;
    const Token& start = peek();
    if (!at(TokenKind::Identifier)) {
      fail(start, "expected a reward formula (F, C<=k or I=k), found " + describe(start));
    }
    if (start.text == "F") {
      advance();
      formula.kind = RewardFormula::Kind::kReachability;
      formula.target = expression();
      formula.range = span(start.range, formula.target->range);
      return formula;
    }
    if (start.text == "C") {
      advance();
      formula.kind = RewardFormula::Kind::kCumulative;
      if (!accept(TokenKind::LessEqual)) {
        fail(peek(), "expected '<=k' after 'C': the total reward (C alone) is not supported");
      }
    } else if (start.text == "I") {
      advance();
      formula.kind = RewardFormula::Kind::kInstantaneous;
      expect(TokenKind::Equal, "after 'I' (the instant is written 'I=k')");
    } else {
      fail(start, "expected a reward formula (F, C<=k or I=k), found " + describe(start));
    }
    formula.steps = unary();
    formula.range = span(start.range, formula.steps->range);
    return formula;
  }

  ast::Expr filter() {
    const Token& head = advance();
    advance();  // (
    nest();
    const Token& op_token = peek();
    if (!at(TokenKind::Identifier)) fail(op_token, "expected the filter's operator");
    advance();
    Filter result;
    result.op = filter_op(op_token);
    expect(TokenKind::Comma, "after the filter's operator");
    result.property = expression();
    if (accept(TokenKind::Comma)) result.states = expression();
    const Token& close = expect(TokenKind::RightParen, "to close the filter");
    --depth_;
    result.range = span(head.range, close.range);
    const SourceRange range = result.range;
    return extension(std::move(result), range);
  }

  Filter::Op filter_op(const Token& token) {
    static constexpr std::array<std::pair<std::string_view, Filter::Op>, 8> kOps = {{
        {"first", Filter::Op::kFirst},
        {"min", Filter::Op::kMin},
        {"max", Filter::Op::kMax},
        {"avg", Filter::Op::kAvg},
        {"sum", Filter::Op::kSum},
        {"count", Filter::Op::kCount},
        {"forall", Filter::Op::kForall},
        {"exists", Filter::Op::kExists},
    }};
    for (const auto& [word, op] : kOps)
      if (token.text == word) return op;
    fail(token, "unknown filter " + quoted(token.text) +
                    " (first, min, max, avg, sum, count, forall and exists are known)");
  }

  void skip_past_semicolon() {
    depth_ = 0;
    while (!at(TokenKind::EndOfFile)) {
      if (accept(TokenKind::Semicolon)) return;
      advance();
    }
  }

  PropertiesFile file_;
};

}  // namespace

PropertiesFile parse(const std::vector<Token>& tokens, DiagnosticEngine& diagnostics) {
  return PropertyParser(tokens, diagnostics).run();
}

PropertiesFile parse_file(FileId file, DiagnosticEngine& diagnostics) {
  return parse(prism::lex(file, diagnostics), diagnostics);
}

PropertiesFile parse_range(SourceRange range, DiagnosticEngine& diagnostics) {
  return parse(prism::lex(range, diagnostics), diagnostics);
}

}  // namespace oasis::property
