#pragma once
// PRISM's expression grammar over a token stream, shared by the program parser (parser.cpp)
// and the property parser (compiler/property/), as PRISM's own grammar shares it: a property
// is an expression with more kinds of primary (`P=? [ ... ]`, `"label"`, `filter(...)`), which
// a derived parser adds through extended_primary(). Errors are reported where they are found
// and raise SyntaxError, which the caller catches to skip to a safe point.

#include <algorithm>
#include <cstddef>
#include <initializer_list>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "prism/ast.hpp"
#include "prism/token.hpp"

namespace oasis::prism {

// Raised after a syntax error has been reported; the caller skips to a safe point.
struct SyntaxError {};

class ExpressionParser {
 public:
  ExpressionParser(const std::vector<Token>& tokens, DiagnosticEngine& diagnostics)
      : tokens_(tokens), diagnostics_(diagnostics) {}
  virtual ~ExpressionParser() = default;
  ExpressionParser(const ExpressionParser&) = delete;
  ExpressionParser& operator=(const ExpressionParser&) = delete;

  // One expression, loosest operator first.
  ast::Expr expression();

  // Whether `word` is a keyword of the model language, which cannot name anything.
  static bool is_keyword(std::string_view word);

 protected:
  // A primary expression the model language lacks, at the current token; nullopt when the
  // token does not start one (the base grammar then goes on as usual).
  virtual std::optional<ast::Expr> extended_primary();

  // --- Expressions, loosest first --------------------------------------------------------
  ast::Expr conditional();
  // PRISM's grammar (ExpressionImplies) makes a => b => c mean (a => b) => c.
  ast::Expr implication() {
    return left_associative(&ExpressionParser::equivalence, {TokenKind::Implies});
  }
  template <typename Next>
  ast::Expr left_associative(Next next, std::initializer_list<TokenKind> operators) {
    ast::Expr left = (this->*next)();
    while (std::find(operators.begin(), operators.end(), peek().kind) != operators.end()) {
      const std::string op(advance().text);
      ast::Expr right = (this->*next)();
      left = node(ast::Expr::Kind::Binary, op, pair_of(std::move(left), std::move(right)));
    }
    return left;
  }
  ast::Expr equivalence() {
    return left_associative(&ExpressionParser::disjunction, {TokenKind::Iff});
  }
  ast::Expr disjunction() {
    return left_associative(&ExpressionParser::conjunction, {TokenKind::Or});
  }
  ast::Expr conjunction() {
    return left_associative(&ExpressionParser::negation, {TokenKind::And});
  }
  ast::Expr negation();
  // PRISM binds < <= > >= tighter than = and != (ExpressionEquality over ExpressionRelop), so
  // `true = 1 < 2` is `true = (1 < 2)`; both levels are left associative.
  ast::Expr relation();
  ast::Expr comparison();
  ast::Expr sum();
  ast::Expr product();
  ast::Expr unary();
  ast::Expr primary();
  ast::Expr name_or_call();
  // The name in func(NAME, ...): a function's name is a keyword (min, max, floor, ...), which
  // identifier() refuses; any other identifier is left to the checker to report as unknown.
  const Token& function_name();

  // --- Building the tree -------------------------------------------------------------------
  void nest();
  static ast::Expr leaf(ast::Expr::Kind kind, const Token& token);
  ast::Expr node(ast::Expr::Kind kind, std::string op, std::vector<ast::Expr> operands);
  // An initializer list would copy its elements, making a long chain quadratic.
  static std::vector<ast::Expr> pair_of(ast::Expr left, ast::Expr right);
  static std::vector<ast::Expr> one_of(ast::Expr operand);
  void check_depth(const ast::Expr& expr);

  // --- Tokens ------------------------------------------------------------------------------
  [[nodiscard]] const Token& peek(std::size_t ahead = 0) const {
    return tokens_[std::min(pos_ + ahead, tokens_.size() - 1)];
  }
  [[nodiscard]] bool at(TokenKind kind) const { return peek().kind == kind; }
  const Token& advance();
  bool accept(TokenKind kind);
  bool accept_word(std::string_view word);
  const Token& expect(TokenKind kind, std::string_view where);
  void expect_word(std::string_view word, std::string_view where);
  const Token& identifier(std::string_view what);
  static std::string spell_quoted(TokenKind kind);
  static std::string describe(const Token& token);
  [[noreturn]] void fail(const Token& token, const std::string& message);

  const std::vector<Token>& tokens_;
  DiagnosticEngine& diagnostics_;
  std::size_t pos_ = 0;
  int depth_ = 0;
};

}  // namespace oasis::prism
