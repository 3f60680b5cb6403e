#include "prism/parser.hpp"

#include <algorithm>
#include <array>
#include <string>
#include <utility>

#include "support/limits.hpp"
#include "support/text.hpp"

namespace oasis::prism {
namespace {

// Raised after a syntax error has been reported; the caller skips to a safe point.
struct SyntaxError {};

// Model types PRISM has that oasis does not explore, named in the refusal.
constexpr std::array<std::string_view, 9> kRefusedTypes = {
    "ctmc", "stochastic", "pta", "pomdp", "popta", "smg", "csg", "tsg", "ma"};

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

bool is_keyword(std::string_view word) {
  return std::find(kKeywords.begin(), kKeywords.end(), word) != kKeywords.end();
}

// The keywords that name functions, which func(NAME, ...) may call.
constexpr std::array<std::string_view, 6> kFunctions = {"min",  "max", "floor",
                                                        "ceil", "pow", "mod"};

bool is_function(std::string_view word) {
  return std::find(kFunctions.begin(), kFunctions.end(), word) != kFunctions.end();
}

class Parser {
 public:
  Parser(const std::vector<Token>& tokens, DiagnosticEngine& diagnostics)
      : tokens_(tokens), diagnostics_(diagnostics) {}

  ast::Program run() {
    program_.type_range = peek().range;  // where a missing model type is reported
    while (!at(TokenKind::EndOfFile) && !diagnostics_.should_stop()) {
      try {
        item();
      } catch (const SyntaxError&) {
        skip_past_item();
      }
    }
    return std::move(program_);
  }

 private:
  // --- Top-level items -----------------------------------------------------------------

  void item() {
    const Token& token = peek();
    if (token.kind != TokenKind::Identifier)
      fail(token, "expected a declaration, a module or a model type");
    const std::string_view word = token.text;
    if (word == "dtmc" || word == "probabilistic") return model_type(ast::ModelType::Dtmc);
    if (word == "mdp" || word == "nondeterministic") return model_type(ast::ModelType::Mdp);
    if (std::find(kRefusedTypes.begin(), kRefusedTypes.end(), word) != kRefusedTypes.end()) {
      fail(token, "model type '" + std::string(word) +
                      "' is not supported: oasis explores dtmc and mdp programs");
    }
    if (word == "const") return constant();
    if (word == "formula") return formula();
    if (word == "global") return global();
    if (word == "module") return module();
    if (word == "label") return label();
    if (word == "rewards") return rewards();
    if (word == "init") return init();
    if (word == "system")
      fail(token,
           "'system ... endsystem' is not supported: oasis composes every module in parallel, "
           "synchronising on shared actions");
    fail(token, "expected a declaration, a module or a model type, not " + quoted(word));
  }

  void model_type(ast::ModelType type) {
    const Token& token = advance();
    if (program_.type_given) {
      diagnostics_.error(token.range, "the model type is given twice");
      diagnostics_.note(program_.type_range, "first given here");
      return;
    }
    program_.type = type;
    program_.type_given = true;
    program_.type_range = token.range;
  }

  void constant() {
    advance();  // const
    ast::Constant constant;
    if (accept_word("int")) {
      constant.type = ast::ConstantType::Int;
    } else if (accept_word("double") || accept_word("prob") || accept_word("rate")) {
      constant.type = ast::ConstantType::Double;
    } else if (accept_word("bool")) {
      constant.type = ast::ConstantType::Bool;
    }
    const Token& name = identifier("the constant's name");
    constant.name = std::string(name.text);
    constant.range = name.range;
    if (accept(TokenKind::Equal)) constant.value = expression();
    expect(TokenKind::Semicolon, "after the constant");
    program_.constants.push_back(std::move(constant));
  }

  void formula() {
    advance();
    const Token& name = identifier("the formula's name");
    expect(TokenKind::Equal, "after the formula's name");
    ast::Expr value = expression();
    expect(TokenKind::Semicolon, "after the formula");
    program_.formulas.push_back({std::string(name.text), std::move(value), name.range});
  }

  void global() {
    advance();
    program_.globals.push_back(variable());
  }

  // NAME : [low..high] [init e];  or  NAME : bool [init e];
  ast::Variable variable() {
    ast::Variable var;
    const Token& name = identifier("the variable's name");
    var.name = std::string(name.text);
    var.range = name.range;
    expect(TokenKind::Colon, "after the variable's name");
    if (accept_word("bool")) {
      var.boolean = true;
    } else {
      expect(TokenKind::LeftBracket, "to open the variable's range, as in [0..5]");
      var.low = expression();
      expect(TokenKind::DotDot, "between the bounds of the range");
      var.high = expression();
      expect(TokenKind::RightBracket, "to close the range");
    }
    if (accept_word("init")) var.init = expression();
    expect(TokenKind::Semicolon, "after the variable");
    return var;
  }

  void module() {
    advance();
    ast::Module module;
    const Token& name = identifier("the module's name");
    module.name = std::string(name.text);
    module.range = name.range;
    if (accept(TokenKind::Equal)) {
      renamed_module(module);
    } else {
      module_body(module);
    }
    program_.modules.push_back(std::move(module));
  }

  void renamed_module(ast::Module& module) {
    const Token& base = identifier("the module to copy");
    module.base = std::string(base.text);
    module.base_range = base.range;
    expect(TokenKind::LeftBracket, "to open the renaming, as in [x1=x2, a=b]");
    do {
      const Token& from = identifier("a name to rename");
      expect(TokenKind::Equal, "between the old and the new name");
      const Token& to = identifier("the new name");
      module.renames.push_back(
          {std::string(from.text), std::string(to.text), span(from.range, to.range)});
    } while (accept(TokenKind::Comma));
    expect(TokenKind::RightBracket, "to close the renaming");
    expect_word("endmodule", "to end the module");
  }

  // Variables and commands up to `endmodule`. An error skips one variable or command.
  void module_body(ast::Module& module) {
    for (;;) {
      if (accept_word("endmodule")) return;
      if (at(TokenKind::EndOfFile))
        fail(peek(), "expected 'endmodule' to end module " + quoted(module.name));
      if (at_top_level_word())
        fail(peek(), "expected 'endmodule' to end module " + quoted(module.name) + " before this");
      try {
        if (at(TokenKind::LeftBracket)) {
          module.commands.push_back(command());
        } else {
          module.variables.push_back(variable());
        }
      } catch (const SyntaxError&) {
        if (diagnostics_.should_stop()) throw;
        skip_past(TokenKind::Semicolon, /*stop_at_endmodule=*/true);
      }
    }
  }

  ast::Command command() {
    ast::Command command;
    const Token& open = advance();  // [
    if (at(TokenKind::Identifier)) {
      const Token& action = identifier("the action");
      command.action = std::string(action.text);
      command.action_range = action.range;
    } else {
      command.action_range = open.range;
    }
    expect(TokenKind::RightBracket, "to close the action");
    command.guard = expression();
    expect(TokenKind::Arrow, "between the guard and the updates");
    do {
      command.updates.push_back(update());
    } while (accept(TokenKind::Plus));
    const Token& end = expect(TokenKind::Semicolon, "after the command");
    command.range = span(open.range, end.range);
    return command;
  }

  // `p : assignments`, or `assignments` alone (probability 1).
  ast::Update update() {
    ast::Update update;
    const SourceRange start = peek().range;
    if (!starts_assignments()) {
      update.probability = expression();
      expect(TokenKind::Colon, "between the probability and the assignments");
    }
    update.assignments = assignments();
    update.range = span(start, tokens_[pos_ - 1].range);
    return update;
  }

  [[nodiscard]] bool starts_assignments() const {
    if (peek().kind == TokenKind::Identifier && peek().text == "true") {
      const TokenKind after = peek(1).kind;
      return after == TokenKind::Semicolon || after == TokenKind::Plus;
    }
    return peek().kind == TokenKind::LeftParen && peek(1).kind == TokenKind::Identifier &&
           peek(2).kind == TokenKind::Prime;
  }

  std::vector<ast::Assignment> assignments() {
    std::vector<ast::Assignment> result;
    if (accept_word("true")) return result;
    do {
      expect(TokenKind::LeftParen, "to open an assignment, as in (x'=x+1)");
      const Token& name = identifier("the variable to update");
      expect(TokenKind::Prime, "after the updated variable's name");
      expect(TokenKind::Equal, "in the assignment");
      ast::Expr value = expression();
      expect(TokenKind::RightParen, "to close the assignment");
      result.push_back({std::string(name.text), name.range, std::move(value)});
    } while (accept(TokenKind::And));
    return result;
  }

  void label() {
    advance();
    const Token& name = expect(TokenKind::String, "naming the label, as in label \"done\" = s=7;");
    expect(TokenKind::Equal, "after the label's name");
    ast::Expr value = expression();
    expect(TokenKind::Semicolon, "after the label");
    program_.labels.push_back({std::string(name.text), std::move(value), name.range});
  }

  void rewards() {
    const Token& keyword = advance();
    ast::Rewards rewards;
    rewards.range = keyword.range;
    if (at(TokenKind::String)) {
      const Token& name = advance();
      rewards.name = std::string(name.text);
      rewards.range = name.range;
    }
    for (;;) {
      if (accept_word("endrewards")) break;
      if (at(TokenKind::EndOfFile) || at_top_level_word())
        fail(peek(), "expected 'endrewards' to end the reward structure");
      try {
        rewards.items.push_back(reward_item());
      } catch (const SyntaxError&) {
        if (diagnostics_.should_stop()) throw;
        skip_past(TokenKind::Semicolon, /*stop_at_endmodule=*/false);
      }
    }
    program_.rewards.push_back(std::move(rewards));
  }

  ast::RewardItem reward_item() {
    ast::RewardItem item;
    const SourceRange start = peek().range;
    if (accept(TokenKind::LeftBracket)) {
      item.action = "";
      item.action_range = start;
      if (at(TokenKind::Identifier)) {
        const Token& action = identifier("the action");
        item.action = std::string(action.text);
        item.action_range = action.range;
      }
      expect(TokenKind::RightBracket, "to close the action");
    }
    item.guard = expression();
    expect(TokenKind::Colon, "between the reward's guard and its value");
    item.value = expression();
    const Token& end = expect(TokenKind::Semicolon, "after the reward");
    item.range = span(start, end.range);
    return item;
  }

  void init() {
    const Token& keyword = advance();
    ast::Expr predicate = expression();
    expect_word("endinit", "to end the initial states");
    if (program_.init) {
      diagnostics_.error(keyword.range, "'init ... endinit' is given twice");
      return;
    }
    program_.init = std::move(predicate);
    program_.init_range = keyword.range;
  }

  // --- Expressions, loosest first --------------------------------------------------------

  ast::Expr expression() {
    if (++depth_ > limits::kMaxNesting) {
      fail(peek(),
           "expression nested more than " + std::to_string(limits::kMaxNesting) + " levels deep");
    }
    ast::Expr result = conditional();
    --depth_;
    return result;
  }

  ast::Expr conditional() {
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

  // PRISM's grammar (ExpressionImplies) makes a => b => c mean (a => b) => c.
  ast::Expr implication() { return left_associative(&Parser::equivalence, {TokenKind::Implies}); }

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

  ast::Expr equivalence() { return left_associative(&Parser::disjunction, {TokenKind::Iff}); }
  ast::Expr disjunction() { return left_associative(&Parser::conjunction, {TokenKind::Or}); }
  ast::Expr conjunction() { return left_associative(&Parser::negation, {TokenKind::And}); }

  ast::Expr negation() {
    if (!at(TokenKind::Not)) return relation();
    const Token& op = advance();
    nest();
    ast::Expr operand = negation();
    --depth_;
    ast::Expr result = node(ast::Expr::Kind::Unary, "!", one_of(std::move(operand)));
    result.range = span(op.range, result.range);
    return result;
  }

  // PRISM binds < <= > >= tighter than = and != (ExpressionEquality over ExpressionRelop), so
  // `true = 1 < 2` is `true = (1 < 2)`; both levels are left associative.
  ast::Expr relation() {
    return left_associative(&Parser::comparison, {TokenKind::Equal, TokenKind::NotEqual});
  }
  ast::Expr comparison() {
    return left_associative(&Parser::sum, {TokenKind::Less, TokenKind::LessEqual,
                                           TokenKind::Greater, TokenKind::GreaterEqual});
  }
  ast::Expr sum() {
    return left_associative(&Parser::product, {TokenKind::Plus, TokenKind::Minus});
  }
  ast::Expr product() {
    return left_associative(&Parser::unary, {TokenKind::Star, TokenKind::Slash});
  }

  ast::Expr unary() {
    if (!at(TokenKind::Minus)) return primary();
    const Token& op = advance();
    nest();
    ast::Expr operand = unary();
    --depth_;
    ast::Expr result = node(ast::Expr::Kind::Unary, "-", one_of(std::move(operand)));
    result.range = span(op.range, result.range);
    return result;
  }

  ast::Expr primary() {
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

  ast::Expr name_or_call() {
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

  // The name in func(NAME, ...): a function's name is a keyword (min, max, floor, ...), which
  // identifier() refuses; any other identifier is left to the checker to report as unknown.
  const Token& function_name() {
    const Token& token = peek();
    if (token.kind != TokenKind::Identifier)
      fail(token, "expected the function's name, found " + describe(token));
    if (is_keyword(token.text) && !is_function(token.text))
      fail(token, "the keyword " + quoted(token.text) + " is not a function");
    return advance();
  }

  void nest() {
    if (++depth_ > limits::kMaxNesting) {
      fail(peek(),
           "expression nested more than " + std::to_string(limits::kMaxNesting) + " levels deep");
    }
  }

  static ast::Expr leaf(ast::Expr::Kind kind, const Token& token) {
    ast::Expr expr;
    expr.kind = kind;
    expr.text = std::string(token.text);
    expr.range = token.range;
    return expr;
  }

  ast::Expr node(ast::Expr::Kind kind, std::string op, std::vector<ast::Expr> operands) {
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

  // An initializer list would copy its elements, making a long chain quadratic.
  static std::vector<ast::Expr> pair_of(ast::Expr left, ast::Expr right) {
    std::vector<ast::Expr> operands;
    operands.reserve(2);
    operands.push_back(std::move(left));
    operands.push_back(std::move(right));
    return operands;
  }
  static std::vector<ast::Expr> one_of(ast::Expr operand) {
    std::vector<ast::Expr> operands;
    operands.push_back(std::move(operand));
    return operands;
  }

  void check_depth(const ast::Expr& expr) {
    if (expr.depth <= limits::kMaxNesting) return;
    diagnostics_.error(expr.range, "expression is too long or nested too deeply (the limit is " +
                                       std::to_string(limits::kMaxNesting) + " levels)");
    throw SyntaxError{};
  }

  // --- Tokens ------------------------------------------------------------------------------

  [[nodiscard]] const Token& peek(std::size_t ahead = 0) const {
    return tokens_[std::min(pos_ + ahead, tokens_.size() - 1)];
  }
  [[nodiscard]] bool at(TokenKind kind) const { return peek().kind == kind; }
  const Token& advance() {
    const Token& token = peek();
    if (pos_ + 1 < tokens_.size()) ++pos_;
    return token;
  }
  bool accept(TokenKind kind) {
    if (!at(kind)) return false;
    advance();
    return true;
  }
  bool accept_word(std::string_view word) {
    if (!at(TokenKind::Identifier) || peek().text != word) return false;
    advance();
    return true;
  }
  const Token& expect(TokenKind kind, std::string_view where) {
    if (!at(kind)) {
      fail(peek(), "expected " + std::string(spell_quoted(kind)) + " " + std::string(where) +
                       ", found " + describe(peek()));
    }
    return advance();
  }
  void expect_word(std::string_view word, std::string_view where) {
    if (!accept_word(word)) {
      fail(peek(), "expected '" + std::string(word) + "' " + std::string(where) + ", found " +
                       describe(peek()));
    }
  }
  const Token& identifier(std::string_view what) {
    const Token& token = peek();
    if (token.kind != TokenKind::Identifier)
      fail(token, "expected " + std::string(what) + ", found " + describe(token));
    if (is_keyword(token.text))
      fail(token, "the keyword " + quoted(token.text) + " cannot be " + std::string(what));
    return advance();
  }

  static std::string spell_quoted(TokenKind kind) {
    const std::string_view text = spell(kind);
    if (kind == TokenKind::Identifier || kind == TokenKind::String || kind == TokenKind::Integer)
      return std::string(text);
    return "'" + std::string(text) + "'";
  }
  static std::string describe(const Token& token) {
    if (token.kind == TokenKind::EndOfFile) return "the end of the file";
    if (token.kind == TokenKind::String) return "\"" + std::string(token.text) + "\"";
    return quoted(token.text);
  }

  [[noreturn]] void fail(const Token& token, const std::string& message) {
    diagnostics_.error(token.range, message);
    throw SyntaxError{};
  }

  [[nodiscard]] bool at_top_level_word() const {
    if (!at(TokenKind::Identifier)) return false;
    static constexpr std::array<std::string_view, 12> kStarts = {
        "module", "const", "formula",       "global",           "label", "rewards", "init",
        "dtmc",   "mdp",   "probabilistic", "nondeterministic", "system"};
    return std::find(kStarts.begin(), kStarts.end(), peek().text) != kStarts.end();
  }

  // After an error in a command or reward: past the next ';' (or up to 'endmodule').
  void skip_past(TokenKind end, bool stop_at_endmodule) {
    depth_ = 0;
    while (!at(TokenKind::EndOfFile)) {
      if (accept(end)) return;
      if (stop_at_endmodule && at(TokenKind::Identifier) && peek().text == "endmodule") return;
      if (at_top_level_word() || (at(TokenKind::Identifier) && peek().text == "endrewards")) return;
      advance();
    }
  }

  // After an error at the top level: to the start of the next item.
  void skip_past_item() {
    depth_ = 0;
    advance();
    while (!at(TokenKind::EndOfFile) && !at_top_level_word()) {
      if (at(TokenKind::Identifier) &&
          (peek().text == "endmodule" || peek().text == "endrewards" || peek().text == "endinit")) {
        advance();
        return;
      }
      if (accept(TokenKind::Semicolon) && !in_block_hint()) return;
      advance();
    }
  }
  // Whether the tokens ahead look like the inside of a module (more commands before
  // 'endmodule'): then skipping stops at 'endmodule', not at the first ';'.
  [[nodiscard]] bool in_block_hint() const { return at(TokenKind::LeftBracket); }

  const std::vector<Token>& tokens_;
  DiagnosticEngine& diagnostics_;
  std::size_t pos_ = 0;
  int depth_ = 0;
  ast::Program program_;
};

}  // namespace

ast::Program parse(const std::vector<Token>& tokens, DiagnosticEngine& diagnostics) {
  return Parser(tokens, diagnostics).run();
}

}  // namespace oasis::prism
