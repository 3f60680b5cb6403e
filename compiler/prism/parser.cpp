#include "prism/parser.hpp"

#include <algorithm>
#include <array>
#include <string>
#include <utility>

#include "prism/expression_parser.hpp"
#include "support/limits.hpp"
#include "support/text.hpp"

namespace oasis::prism {
namespace {

// Model types PRISM has that oasis does not explore, named in the refusal.
constexpr std::array<std::string_view, 9> kRefusedTypes = {
    "ctmc", "stochastic", "pta", "pomdp", "popta", "smg", "csg", "tsg", "ma"};

class Parser : public ExpressionParser {
 public:
  Parser(const std::vector<Token>& tokens, DiagnosticEngine& diagnostics)
      : ExpressionParser(tokens, diagnostics) {}

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

  ast::Program program_;
};

}  // namespace

ast::Program parse(const std::vector<Token>& tokens, DiagnosticEngine& diagnostics) {
  return Parser(tokens, diagnostics).run();
}

}  // namespace oasis::prism
