#include "prism/expression_parser.hpp"

#include <algorithm>
#include <array>
#include <string>
#include <utility>

#include "support/limits.hpp"
#include "support/text.hpp"

namespace oasis::prism {
namespace {

// Words that cannot name anything.
constexpr std::array<std::string_view, 30> kKeywords = {
    "dtmc",      "probabilistic", "mdp",     "nondeterministic",
    "ctmc",      "const",         "int",     "double",
    "bool",      "formula",       "global",  "module",
    "endmodule", "label",         "rewards", "endrewards",
    "init",      "endinit",       "true",    "false",
    "min",       "max",           "floor",   "ceil",
    "pow",       "mod",           "system",  "endsystem",
    "func",      "prob"};

// The keywords that name functions, which func(NAME, ...) may call.
constexpr std::array<std::string_view, 6> kFunctions = {"min",  "max", "floor",
                                                        "ceil", "pow", "mod"};

bool is_function(std::string_view word) {
  return std::find(kFunctions.begin(), kFunctions.end(), word) != kFunctions.end();
}

}  // namespace

bool ExpressionParser::is_keyword(std::string_view word) {
  return std::find(kKeywords.begin(), kKeywords.end(), word) != kKeywords.end();
}

ast::Expr ExpressionParser::expression() {
  if (++depth_ > limits::kMaxNesting) {
    fail(peek(),
         "expression nested more than " + std::to_string(limits::kMaxNesting) + " levels deep");
  }
  ast::Expr result = conditional();
  --depth_;
  return result;
}

ast::Expr ExpressionParser::conditional() {
  ast::Expr condition = implication();
  if (!accept(TokenKind::Question)) return condition;
  ast::Expr then = expression();
  expect(TokenKind::Colon, "between the two branches of '? :'");
  ast::Expr otherwise = expression();
  std::vector<ast::Expr> operands;
  operands.push_back(std::move(condition));
  operands.push_back(std::move(then));
  operands.push_back(std::move(otherwise));
  return node(ast::Expr::Kind::IfThenElse, "?", std::move(operands));
}

ast::Expr ExpressionParser::negation() {
  if (!at(TokenKind::Not)) return relation();
  const Token& op = advance();
  nest();
  ast::Expr operand = negation();
  --depth_;
  ast::Expr result = node(ast::Expr::Kind::Unary, "!", one_of(std::move(operand)));
  result.range = span(op.range, result.range);
  return result;
}

ast::Expr ExpressionParser::relation() {
  return left_associative(&ExpressionParser::comparison, {TokenKind::Equal, TokenKind::NotEqual});
}

ast::Expr ExpressionParser::comparison() {
  return left_associative(&ExpressionParser::sum, {TokenKind::Less, TokenKind::LessEqual,
                                                   TokenKind::Greater, TokenKind::GreaterEqual});
}

ast::Expr ExpressionParser::sum() {
  return left_associative(&ExpressionParser::product, {TokenKind::Plus, TokenKind::Minus});
}

ast::Expr ExpressionParser::product() {
  return left_associative(&ExpressionParser::unary, {TokenKind::Star, TokenKind::Slash});
}

ast::Expr ExpressionParser::unary() {
  if (!at(TokenKind::Minus)) return primary();
  const Token& op = advance();
  nest();
  ast::Expr operand = unary();
  --depth_;
  ast::Expr result = node(ast::Expr::Kind::Unary, "-", one_of(std::move(operand)));
  result.range = span(op.range, result.range);
  return result;
}

ast::Expr ExpressionParser::primary() {
  if (std::optional<ast::Expr> extended = extended_primary()) return std::move(*extended);
  const Token& token = peek();
  switch (token.kind) {
    case TokenKind::Integer:
      advance();
      return leaf(ast::Expr::Kind::Integer, token);
    case TokenKind::Real:
      advance();
      return leaf(ast::Expr::Kind::Real, token);
    case TokenKind::LeftParen: {
      advance();
      ast::Expr inner = expression();
      expect(TokenKind::RightParen, "to close the parenthesis");
      return inner;
    }
    case TokenKind::Identifier:
      return name_or_call();
    default:
      fail(token, "expected an expression, found " + describe(token));
  }
}

ast::Expr ExpressionParser::name_or_call() {
  const Token& token = advance();
  if (token.text == "true" || token.text == "false") return leaf(ast::Expr::Kind::Bool, token);
  if (!at(TokenKind::LeftParen)) {
    if (is_keyword(token.text))
      fail(token, "expected an expression, found the keyword " + quoted(token.text));
    return leaf(ast::Expr::Kind::Name, token);
  }
  std::string function(token.text);
  advance();                 // (
  if (function == "func") {  // func(min, a, b) is min(a, b)
    function = std::string(function_name().text);
    expect(TokenKind::Comma, "after the function's name");
  }
  ast::Expr call = leaf(ast::Expr::Kind::Call, token);
  call.text = function;
  nest();
  do {
    call.operands.push_back(expression());
  } while (accept(TokenKind::Comma));
  --depth_;
  const Token& close = expect(TokenKind::RightParen, "to close the function's arguments");
  call.range = span(token.range, close.range);
  for (const ast::Expr& operand : call.operands)
    call.depth = std::max(call.depth, operand.depth + 1);
  check_depth(call);
  return call;
}

const Token& ExpressionParser::function_name() {
  const Token& token = peek();
  if (token.kind != TokenKind::Identifier)
    fail(token, "expected the function's name, found " + describe(token));
  if (is_keyword(token.text) && !is_function(token.text))
    fail(token, "the keyword " + quoted(token.text) + " is not a function");
  return advance();
}

void ExpressionParser::nest() {
  if (++depth_ > limits::kMaxNesting) {
    fail(peek(),
         "expression nested more than " + std::to_string(limits::kMaxNesting) + " levels deep");
  }
}

ast::Expr ExpressionParser::leaf(ast::Expr::Kind kind, const Token& token) {
  ast::Expr expr;
  expr.kind = kind;
  expr.text = std::string(token.text);
  expr.range = token.range;
  return expr;
}

ast::Expr ExpressionParser::node(ast::Expr::Kind kind, std::string op,
                                 std::vector<ast::Expr> operands) {
  ast::Expr expr;
  expr.kind = kind;
  expr.text = std::move(op);
  expr.range = span(operands.front().range, operands.back().range);
  for (const ast::Expr& operand : operands)
    expr.depth = std::max(expr.depth, operand.depth + 1);
  expr.operands = std::move(operands);
  check_depth(expr);
  return expr;
}

std::vector<ast::Expr> ExpressionParser::pair_of(ast::Expr left, ast::Expr right) {
  std::vector<ast::Expr> operands;
  operands.reserve(2);
  operands.push_back(std::move(left));
  operands.push_back(std::move(right));
  return operands;
}

std::vector<ast::Expr> ExpressionParser::one_of(ast::Expr operand) {
  std::vector<ast::Expr> operands;
  operands.push_back(std::move(operand));
  return operands;
}

void ExpressionParser::check_depth(const ast::Expr& expr) {
  if (expr.depth <= limits::kMaxNesting) return;
  diagnostics_.error(expr.range, "expression is too long or nested too deeply (the limit is " +
                                     std::to_string(limits::kMaxNesting) + " levels)");
  throw SyntaxError{};
}

const Token& ExpressionParser::advance() {
  const Token& token = peek();
  if (pos_ + 1 < tokens_.size()) ++pos_;
  return token;
}

bool ExpressionParser::accept(TokenKind kind) {
  if (!at(kind)) return false;
  advance();
  return true;
}

bool ExpressionParser::accept_word(std::string_view word) {
  if (!at(TokenKind::Identifier) || peek().text != word) return false;
  advance();
  return true;
}

const Token& ExpressionParser::expect(TokenKind kind, std::string_view where) {
  if (!at(kind)) {
    fail(peek(), "expected " + std::string(spell_quoted(kind)) + " " + std::string(where) +
                     ", found " + describe(peek()));
  }
  return advance();
}

void ExpressionParser::expect_word(std::string_view word, std::string_view where) {
  if (!accept_word(word)) {
    fail(peek(), "expected '" + std::string(word) + "' " + std::string(where) + ", found " +
                     describe(peek()));
  }
}

const Token& ExpressionParser::identifier(std::string_view what) {
  const Token& token = peek();
  if (token.kind != TokenKind::Identifier)
    fail(token, "expected " + std::string(what) + ", found " + describe(token));
  if (is_keyword(token.text))
    fail(token, "the keyword " + quoted(token.text) + " cannot be " + std::string(what));
  return advance();
}

std::string ExpressionParser::spell_quoted(TokenKind kind) {
  const std::string_view text = spell(kind);
  if (kind == TokenKind::Identifier || kind == TokenKind::String || kind == TokenKind::Integer)
    return std::string(text);
  return "'" + std::string(text) + "'";
}

std::string ExpressionParser::describe(const Token& token) {
  if (token.kind == TokenKind::EndOfFile) return "the end of the file";
  if (token.kind == TokenKind::String) return "\"" + std::string(token.text) + "\"";
  return quoted(token.text);
}

void ExpressionParser::fail(const Token& token, const std::string& message) {
  diagnostics_.error(token.range, message);
  throw SyntaxError{};
}

std::optional<ast::Expr> ExpressionParser::extended_primary() {
  return std::nullopt;
}

}  // namespace oasis::prism
