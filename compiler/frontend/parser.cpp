#include "frontend/parser.hpp"

#include <algorithm>
#include <string>
#include <utility>

#include "support/text.hpp"

namespace oasis::frontend {
namespace {

using namespace ast;

// Thrown after a syntax error has been reported; caught where parsing can resume.
struct SyntaxError {};

SourceRange range_of(const Token& token) {
  return SourceRange{token.location, token.length() == 0 ? 1 : token.length()};
}

class Parser {
 public:
  Parser(FileId file, const std::vector<Token>& tokens, DiagnosticEngine& diagnostics)
      : tokens_(tokens), diagnostics_(diagnostics) {
    result_.file = file;
  }

  SpecFile run() {
    while (!at(TokenKind::EndOfFile) && !diagnostics_.should_stop()) {
      try {
        top_level_item();
      } catch (const SyntaxError&) {
        skip_to_top_level();
      }
    }
    return std::move(result_);
  }

 private:
  // ---- token access -----------------------------------------------------------------------

  [[nodiscard]] const Token& peek(std::size_t ahead = 0) const {
    const std::size_t i = pos_ + ahead;
    return i < tokens_.size() ? tokens_[i] : tokens_.back();
  }
  [[nodiscard]] bool at(TokenKind kind) const { return peek().is(kind); }
  const Token& advance() {
    const Token& token = peek();
    if (pos_ + 1 < tokens_.size()) ++pos_;
    previous_ = &token;
    return token;
  }
  // Contextual keywords are identifiers with a given spelling.
  [[nodiscard]] bool at_word(std::string_view word) const {
    return at(TokenKind::Identifier) && peek().text == word;
  }
  bool accept_word(std::string_view word) {
    if (!at_word(word)) return false;
    advance();
    return true;
  }
  const Token& expect_word(std::string_view word, std::string_view context) {
    if (!at_word(word)) {
      fail(peek(), "expected '" + std::string(word) + "' " + std::string(context) + ", found " +
                       found(peek()));
    }
    return advance();
  }

  bool accept(TokenKind kind) {
    if (!at(kind)) return false;
    advance();
    return true;
  }
  [[nodiscard]] SourceRange previous_range() const {
    return previous_ ? range_of(*previous_) : range_of(peek());
  }

  [[noreturn]] void fail(const Token& token, const std::string& message) {
    // An Invalid token was already reported by the lexer: say nothing more about it. Nor
    // about a token that already has an error: recovery that cannot advance (at the end of
    // the file, every enclosing block's missing '}') would only echo the first message.
    if (!token.is(TokenKind::Invalid) && &token != last_failed_) {
      diagnostics_.error(range_of(token), message);
    }
    last_failed_ = &token;
    throw SyntaxError{};
  }

  static std::string found(const Token& token) {
    if (token.is(TokenKind::EndOfFile)) return "end of file";
    return quoted(token.text);
  }

  const Token& expect(TokenKind kind, std::string_view context = {}) {
    if (!at(kind)) {
      std::string message = "expected " + std::string(describe(kind));
      if (!context.empty()) message += " " + std::string(context);
      fail(peek(), message + ", found " + found(peek()));
    }
    return advance();
  }

  Name expect_name(std::string_view what) {
    if (!at(TokenKind::Identifier)) {
      std::string message = "expected " + std::string(what) + ", found " + found(peek());
      if (peek().kind >= TokenKind::KwMdp && peek().kind <= TokenKind::KwFalse) {
        message += " (a keyword cannot be used as a name)";
      }
      fail(peek(), message);
    }
    const Token& token = advance();
    return Name{token.text, range_of(token)};
  }

  // ---- recovery ---------------------------------------------------------------------------

  // Skips the rest of a statement: past the next ';' at this nesting level, or up to the '}'
  // that closes the enclosing block.
  void skip_statement() {
    int depth = 0;
    while (!at(TokenKind::EndOfFile)) {
      if (at(TokenKind::LeftBrace)) ++depth;
      if (at(TokenKind::RightBrace)) {
        if (depth == 0) return;
        --depth;
        if (depth == 0) {
          advance();
          return;
        }
      }
      if (at(TokenKind::Semicolon) && depth == 0) {
        advance();
        return;
      }
      advance();
    }
  }

  void skip_to_top_level() {
    while (!at(TokenKind::EndOfFile) && !at(TokenKind::KwMdp) && !at(TokenKind::KwCatalog) &&
           !at(TokenKind::KwImport)) {
      advance();
    }
  }

  // ---- top level --------------------------------------------------------------------------

  void top_level_item() {
    if (at(TokenKind::KwMdp)) {
      result_.mdps.push_back(mdp());
    } else if (at(TokenKind::KwCatalog)) {
      result_.catalogs.push_back(catalog());
    } else if (at(TokenKind::KwImport)) {
      result_.imports.push_back(import());
    } else {
      fail(peek(), "expected 'mdp', 'import' or 'catalog', found " + found(peek()));
    }
  }

  // A string token's text without its quotes; its range keeps them.
  Name expect_string(std::string_view context) {
    const Token& token = expect(TokenKind::String, context);
    return Name{token.text.substr(1, token.text.size() - 2), range_of(token)};
  }

  ImportDecl import() {
    ImportDecl decl;
    const SourceRange start = range_of(advance());
    decl.path = expect_string("after 'import' (the PRISM program's file, as in \"robot.nm\")");
    if (at(TokenKind::LeftBrace)) {
      block([&] { import_item(decl); });
    } else {
      expect(TokenKind::Semicolon, "or '{' after the imported file");
    }
    decl.range = span(start, previous_range());
    return decl;
  }

  void import_item(ImportDecl& decl) {
    switch (peek().kind) {
      case TokenKind::KwConst:
        decl.constants.push_back(constant());
        return;
      case TokenKind::KwDiscount:
      case TokenKind::KwHorizon: {
        std::optional<Setting>& target = at(TokenKind::KwDiscount) ? decl.discount : decl.horizon;
        if (target) fail(peek(), "the import already has a '" + std::string(peek().text) + "'");
        target = setting();
        return;
      }
      default:
        fail(peek(),
             "expected 'const', 'discount' or 'horizon' in an import, found " + found(peek()));
    }
  }

  // Parses `{ item* }`, calling `item` for each statement, with recovery per statement.
  template <typename Item>
  void block(Item&& item) {
    expect(TokenKind::LeftBrace);
    while (!at(TokenKind::RightBrace) && !at(TokenKind::EndOfFile) && !diagnostics_.should_stop()) {
      try {
        item();
      } catch (const SyntaxError&) {
        skip_statement();
      }
    }
    expect(TokenKind::RightBrace, "to close the block");
  }

  MdpDecl mdp() {
    MdpDecl decl;
    const SourceRange start = range_of(advance());
    decl.name = expect_name("a model name after 'mdp'");
    block([&] { mdp_item(decl); });
    decl.range = span(start, previous_range());
    return decl;
  }

  void mdp_item(MdpDecl& decl) {
    const Token& token = peek();
    switch (token.kind) {
      case TokenKind::KwStates:
        advance();
        name_list(decl.states, "a state name");
        return;
      case TokenKind::KwActions:
        advance();
        name_list(decl.actions, "an action name");
        return;
      case TokenKind::KwInit:
        advance();
        name_list(decl.initial, "an initial state");
        return;
      case TokenKind::KwConst:
        decl.constants.push_back(constant());
        return;
      case TokenKind::KwVar:
      case TokenKind::KwContinuous:
        decl.variables.push_back(variable());
        return;
      case TokenKind::KwRegion:
        decl.regions.push_back(region());
        return;
      case TokenKind::KwDefault:
        missing_transitions(decl);
        return;
      case TokenKind::KwDiscount:
        decl.discount = setting();
        return;
      case TokenKind::KwHorizon:
        decl.horizon = setting();
        return;
      case TokenKind::KwPeriod:
        decl.period = setting();
        return;
      default:
        // `epsilon` and `max_cells` are contextual: a state may be called so (`epsilon, a ->`).
        if ((at_word("epsilon") || at_word("max_cells")) && !peek(1).is(TokenKind::Comma)) {
          std::optional<Setting>& target = at_word("epsilon") ? decl.epsilon : decl.max_cells;
          if (target) fail(peek(), "the model already has a '" + std::string(peek().text) + "'");
          target = setting();
          return;
        }
        // `input`, `objective` and `grid` are contextual too (continuous models).
        if (!peek(1).is(TokenKind::Comma)) {
          if (at_word("input")) {
            decl.inputs.push_back(input());
            return;
          }
          if (at_word("objective")) {
            if (decl.objective) fail(peek(), "the model already has an 'objective'");
            decl.objective = objective();
            return;
          }
          if (at_word("grid")) {
            if (decl.grid) fail(peek(), "the model already has a 'grid'");
            decl.grid = grid();
            return;
          }
        }
        if (!behaviour_item(decl.behaviour)) {
          fail(token,
               "expected a model item (states, actions, var, a transition, reward, ...), "
               "found " +
                   found(token));
        }
    }
  }

  // Items shared by models and contexts. Returns false when the next token starts none.
  bool behaviour_item(Behaviour& behaviour) {
    switch (peek().kind) {
      case TokenKind::LeftBracket:
        behaviour.commands.push_back(command());
        return true;
      case TokenKind::KwReward:
        behaviour.rewards.push_back(reward());
        return true;
      case TokenKind::KwDynamics:
        behaviour.dynamics.push_back(dynamics());
        return true;
      case TokenKind::KwDisturbance:
        behaviour.disturbances.push_back(disturbance());
        return true;
      case TokenKind::Identifier:
        behaviour.transitions.push_back(explicit_transition());
        return true;
      default:
        return false;
    }
  }

  void name_list(std::vector<Name>& names, std::string_view what) {
    do {
      names.push_back(expect_name(what));
    } while (accept(TokenKind::Comma));
    expect(TokenKind::Semicolon, "after the list");
  }

  ConstDecl constant() {
    ConstDecl decl;
    const SourceRange start = range_of(advance());
    decl.name = expect_name("a constant name");
    expect(TokenKind::Assign);
    decl.value = expression();
    expect(TokenKind::Semicolon);
    decl.range = span(start, previous_range());
    return decl;
  }

  VarDecl variable() {
    VarDecl decl;
    decl.continuous = at(TokenKind::KwContinuous);
    const SourceRange start = range_of(advance());
    decl.name = expect_name("a variable name");
    expect(TokenKind::Colon);
    expect(TokenKind::LeftBracket, "before the variable's range");
    decl.low = expression();
    expect(TokenKind::DotDot, "between the bounds");
    decl.high = expression();
    expect(TokenKind::RightBracket, "after the variable's range");
    if (at(TokenKind::KwInit)) {
      if (decl.continuous) fail(peek(), "continuous variables have no 'init' value");
      advance();
      decl.init = expression();
    }
    expect(TokenKind::Semicolon);
    decl.range = span(start, previous_range());
    return decl;
  }

  RegionDecl region() {
    RegionDecl decl;
    const SourceRange start = range_of(advance());
    decl.name = expect_name("a region name");
    expect(TokenKind::Assign);
    decl.constraint = expression();
    expect(TokenKind::Semicolon);
    decl.range = span(start, previous_range());
    return decl;
  }

  void missing_transitions(MdpDecl& decl) {
    const SourceRange start = range_of(advance());
    if (accept_word("self")) {
      decl.missing = MissingTransitions::SelfLoop;
    } else if (accept_word("disabled")) {
      decl.missing = MissingTransitions::Disabled;
    } else {
      fail(peek(), "expected 'self' or 'disabled' after 'default', found " + found(peek()));
    }
    expect(TokenKind::Semicolon);
    decl.missing_range = span(start, previous_range());
  }

  Setting setting() {
    Setting result;
    const SourceRange start = range_of(advance());
    result.value = expression();
    expect(TokenKind::Semicolon);
    result.range = span(start, previous_range());
    return result;
  }

  // ---- behaviour --------------------------------------------------------------------------

  ExplicitTransition explicit_transition() {
    ExplicitTransition transition;
    transition.state = expect_name("a state name");
    expect(TokenKind::Comma, "between the state and the action");
    transition.action = expect_name("an action name");
    expect(TokenKind::Arrow);
    transition.distribution = distribution(/*updates=*/false);
    expect(TokenKind::Semicolon, "after the distribution");
    transition.range = span(transition.state.range, previous_range());
    return transition;
  }

  Command command() {
    Command result;
    const SourceRange start = range_of(advance());
    result.action = expect_name("an action name");
    expect(TokenKind::RightBracket);
    result.guard = expression();
    expect(TokenKind::Arrow);
    result.distribution = distribution(/*updates=*/true);
    expect(TokenKind::Semicolon, "after the distribution");
    result.range = span(start, previous_range());
    return result;
  }

  RewardItem reward() {
    RewardItem item;
    const SourceRange start = range_of(advance());
    if (accept(TokenKind::LeftBracket)) {
      item.action = expect_name("an action name");
      expect(TokenKind::RightBracket);
    }
    item.guard = expression();
    expect(TokenKind::Colon, "between the reward's condition and its value");
    item.value = expression();
    expect(TokenKind::Semicolon);
    item.range = span(start, previous_range());
    return item;
  }

  Dynamics dynamics() {
    Dynamics result;
    const SourceRange start = range_of(advance());
    expect(TokenKind::LeftBracket);
    result.action = expect_name("an action name");
    expect(TokenKind::RightBracket);
    block([&] {
      if (at(TokenKind::KwDisturbance)) {
        result.disturbances.push_back(disturbance());
        return;
      }
      result.equations.push_back(assignment());
      expect(TokenKind::Semicolon);
    });
    result.range = span(start, previous_range());
    return result;
  }

  Disturbance disturbance() {
    Disturbance result;
    const SourceRange start = range_of(advance());
    result.variable = expect_name("a variable name");
    if (accept_word("in")) {
      expect(TokenKind::LeftBracket);
      result.first = expression();
      expect(TokenKind::DotDot, "between the bounds");
      result.second = expression();
      expect(TokenKind::RightBracket);
    } else if (accept(TokenKind::Tilde)) {
      result.gaussian = true;
      expect_word("gaussian", "after '~'");
      expect(TokenKind::LeftParen);
      result.first = expression();
      expect(TokenKind::Comma, "between the mean and the standard deviation");
      result.second = expression();
      expect(TokenKind::RightParen);
    } else {
      fail(peek(), "expected 'in [lo .. hi]' or '~ gaussian(mean, sd)', found " + found(peek()));
    }
    expect(TokenKind::Semicolon);
    result.range = span(start, previous_range());
    return result;
  }

  // `input u in [lo .. hi] step s;` or `input u in {v1, v2, ...};`
  InputDecl input() {
    InputDecl result;
    const SourceRange start = range_of(advance());
    result.name = expect_name("an input name");
    expect_word("in", "after the input's name");
    if (accept(TokenKind::LeftBrace)) {
      do {
        result.values.push_back(expression());
      } while (accept(TokenKind::Comma));
      expect(TokenKind::RightBrace, "after the input's values");
    } else {
      expect(TokenKind::LeftBracket, "before the input's range (or '{' before a list)");
      result.low = expression();
      expect(TokenKind::DotDot, "between the bounds");
      result.high = expression();
      expect(TokenKind::RightBracket, "after the input's range");
      expect_word("step", "after the input's range");
      result.step = expression();
    }
    expect(TokenKind::Semicolon);
    result.range = span(start, previous_range());
    return result;
  }

  // `objective safety S steps N;` or `objective reach T [while S] [steps N | at N];`
  ObjectiveDecl objective() {
    ObjectiveDecl result;
    const SourceRange start = range_of(advance());
    if (accept_word("safety")) {
      result.safe = expression();
      expect_word("steps", "after the safe set (write 'objective safety S steps N;')");
      result.steps = expression();
    } else if (accept_word("reach")) {
      result.reach = true;
      result.target = expression();
      if (accept_word("while")) result.safe = expression();
      if (accept_word("steps")) {
        result.steps = expression();
      } else if (accept_word("at")) {
        result.steps = expression();
        result.exactly_at_step = true;
      }
    } else {
      fail(peek(), "expected 'safety' or 'reach' after 'objective', found " + found(peek()));
    }
    expect(TokenKind::Semicolon);
    result.range = span(start, previous_range());
    return result;
  }

  // `grid x : 50, y : 50;`
  GridDecl grid() {
    GridDecl result;
    const SourceRange start = range_of(advance());
    do {
      Name variable = expect_name("a continuous variable");
      expect(TokenKind::Colon, "after the variable (write 'grid x : 50, y : 50;')");
      result.cells.emplace_back(variable, expression());
    } while (accept(TokenKind::Comma));
    expect(TokenKind::Semicolon);
    result.range = span(start, previous_range());
    return result;
  }

  // `x' = e` (without the parentheses of an update).
  Assignment assignment() {
    Assignment result;
    result.variable = expect_name("a variable name");
    expect(TokenKind::Prime, "after the variable (write x' = ...)");
    expect(TokenKind::Assign);
    result.value = expression();
    result.range = span(result.variable.range, previous_range());
    return result;
  }

  // p1 : t1 + p2 : t2 + ...  A single term may leave out its probability.
  Distribution distribution(bool updates) {
    Distribution result;
    const SourceRange start = range_of(peek());
    do {
      result.branches.push_back(branch(updates));
    } while (accept(TokenKind::Plus));
    result.range = span(start, previous_range());
    return result;
  }

  [[nodiscard]] bool branch_without_probability(bool updates) const {
    if (updates) {
      if (at(TokenKind::KwTrue)) return !peek(1).is(TokenKind::Colon);
      // `(x = e)` is a mistyped update, not a probability: reading it as one would answer
      // "use '=='" instead of asking for the prime. No expression has '=' after a name.
      return at(TokenKind::LeftParen) && peek(1).is(TokenKind::Identifier) &&
             (peek(2).is(TokenKind::Prime) || peek(2).is(TokenKind::Assign));
    }
    if (!at(TokenKind::Identifier)) return false;
    const TokenKind next = peek(1).kind;
    return next == TokenKind::Semicolon || next == TokenKind::Plus ||
           next == TokenKind::RightBrace || next == TokenKind::EndOfFile;
  }

  Branch branch(bool updates) {
    Branch result;
    const SourceRange start = range_of(peek());
    if (!branch_without_probability(updates)) {
      result.probability = expression();
      expect(TokenKind::Colon, "between the probability and its outcome");
    }
    if (updates) {
      update_list(result.updates);
    } else {
      result.target = expect_name("a state name");
    }
    result.range = span(start, previous_range());
    return result;
  }

  // `true` or `(x' = e) & (y' = e)`.
  void update_list(std::vector<Assignment>& updates) {
    if (accept(TokenKind::KwTrue)) return;
    do {
      expect(TokenKind::LeftParen, "before an update (write (x' = e) or true)");
      updates.push_back(assignment());
      expect(TokenKind::RightParen, "after the update");
    } while (accept(TokenKind::And));
  }

  // ---- catalog ----------------------------------------------------------------------------

  CatalogDecl catalog() {
    CatalogDecl decl;
    const SourceRange start = range_of(advance());
    if (at(TokenKind::Identifier)) decl.name = expect_name("a catalog name");
    block([&] { catalog_item(decl); });
    decl.range = span(start, previous_range());
    return decl;
  }

  void catalog_item(CatalogDecl& decl) {
    switch (peek().kind) {
      case TokenKind::KwContext:
        decl.contexts.push_back(context());
        return;
      case TokenKind::KwSwitching:
        if (decl.switching) fail(peek(), "the catalog already has a switching model");
        decl.switching = switching();
        return;
      case TokenKind::KwPrior:
        if (decl.prior) fail(peek(), "the catalog already has a prior");
        decl.prior = prior();
        return;
      default:
        // `observation` and `property` are contextual, like `epsilon`: no other catalog item
        // starts with a name.
        if (at_word("observation")) {
          if (decl.observation) fail(peek(), "the catalog already has an observation model");
          decl.observation = observation();
          return;
        }
        if (accept_word("property")) {
          decl.properties.push_back(property());
          return;
        }
        fail(peek(),
             "expected 'context', 'switching', 'prior', 'observation' or 'property', found " +
                 found(peek()));
    }
  }

  // After `property`: `NAME = TEXT;` (the lexer took TEXT whole, see PropertyText).
  PropertyDecl property() {
    PropertyDecl decl;
    decl.name = expect_name("a property name after 'property'");
    expect(TokenKind::Assign, "after the property's name");
    if (!at(TokenKind::PropertyText) || peek().text.empty())
      fail(peek(), "expected a PRISM property such as 'Pmax=? [F \"goal\"]' after '='");
    decl.text = range_of(advance());
    expect(TokenKind::Semicolon, "after the property");
    return decl;
  }

  ObservationDecl observation() {
    ObservationDecl decl;
    decl.keyword = range_of(advance());
    block([&] { observation_item(decl); });
    decl.range = span(decl.keyword, previous_range());
    return decl;
  }

  // `state noise p;`, `state confusion { s -> distribution; ... }`, `reward follows true;`,
  // `reward follows observed;` or `object NAME (x, y) { ... }`.
  void observation_item(ObservationDecl& decl) {
    const SourceRange start = range_of(peek());
    if (accept_word("object")) {
      decl.objects.push_back(measured_object(start));
      return;
    }
    if (accept_word("state")) {
      if (decl.noise || decl.confusion)
        fail(*previous_, "the observation model already has a state model");
      if (accept_word("noise")) {
        decl.noise = expression();
        expect(TokenKind::Semicolon);
        return;
      }
      if (!accept_word("confusion"))
        fail(peek(), "expected 'noise' or 'confusion' after 'state', found " + found(peek()));
      decl.confusion = start;
      block([&] {
        Name from = expect_name("a state name");
        expect(TokenKind::Arrow);
        Distribution row = distribution(/*updates=*/false);
        expect(TokenKind::Semicolon);
        decl.rows.emplace_back(from, std::move(row));
      });
      decl.confusion = span(start, previous_range());
      return;
    }
    if (accept(TokenKind::KwReward)) {
      if (decl.reward_follows)
        fail(*previous_, "the observation model already says what the reward follows");
      expect_word("follows", "after 'reward'");
      if (!at(TokenKind::KwTrue) && !at_word("observed"))
        fail(peek(),
             "expected 'true' or 'observed' after 'reward follows', found " + found(peek()));
      const Token& which = advance();
      decl.reward_follows = Name{which.text, range_of(which)};
      expect(TokenKind::Semicolon);
      return;
    }
    fail(peek(),
         "expected 'state noise', 'state confusion', 'object' or 'reward follows' in an "
         "observation model, found " +
             found(peek()));
  }

  // After `object`: `NAME (x, y) { noise EXPR; detection EXPR; }`.
  ObjectDecl measured_object(SourceRange start) {
    ObjectDecl object;
    object.name = expect_name("an object name after 'object'");
    expect(TokenKind::LeftParen, "before the object's variables");
    do {
      object.variables.push_back(expect_name("a continuous variable"));
    } while (accept(TokenKind::Comma));
    expect(TokenKind::RightParen, "after the object's variables");
    block([&] {
      const Token& item = peek();
      ExprPtr* target = accept_word("noise")       ? &object.noise
                        : accept_word("detection") ? &object.detection
                                                   : nullptr;
      if (target == nullptr)
        fail(peek(), "expected 'noise' or 'detection' in an object, found " + found(peek()));
      if (*target) fail(item, "the object already has a " + std::string(item.text));
      *target = expression();
      expect(TokenKind::Semicolon);
    });
    object.range = span(start, previous_range());
    return object;
  }

  ContextDecl context() {
    ContextDecl decl;
    const SourceRange start = range_of(advance());
    decl.name = expect_name("a context name");
    if (accept(TokenKind::Assign)) {
      if (accept_word("rewards")) {
        decl.reward_structure = expect_string("after 'rewards' (a reward structure's name)");
      } else {
        expect_word("base", "or 'rewards \"name\"' after '='");
        decl.is_base = true;
      }
      expect(TokenKind::Semicolon);
    } else {
      block([&] {
        if (!behaviour_item(decl.behaviour)) {
          fail(peek(), "expected a transition, command, reward or dynamics in a context, found " +
                           found(peek()));
        }
      });
    }
    decl.range = span(start, previous_range());
    return decl;
  }

  SwitchingDecl switching() {
    SwitchingDecl decl;
    const SourceRange start = range_of(advance());
    if (accept_word("stay")) {
      decl.stay = expression();
      expect(TokenKind::Semicolon);
    } else {
      block([&] {
        Name from = expect_name("a context name");
        expect(TokenKind::Arrow);
        Distribution row = distribution(/*updates=*/false);
        expect(TokenKind::Semicolon);
        decl.rows.emplace_back(from, std::move(row));
      });
    }
    decl.range = span(start, previous_range());
    return decl;
  }

  PriorDecl prior() {
    PriorDecl decl;
    const SourceRange start = range_of(advance());
    if (accept_word("uniform")) {
      decl.uniform = true;
    } else {
      decl.distribution = distribution(/*updates=*/false);
    }
    expect(TokenKind::Semicolon);
    decl.range = span(start, previous_range());
    return decl;
  }

  // ---- expressions ------------------------------------------------------------------------
  // Precedence, loosest first: |, &, !, comparisons, + -, * /, unary -, ^.

  class NestingGuard {
   public:
    explicit NestingGuard(Parser& parser) : parser_(parser) {
      if (++parser_.nesting_ > kMaxNesting) {
        --parser_.nesting_;
        parser_.fail(parser_.peek(), "expression is nested too deeply (the limit is " +
                                         std::to_string(kMaxNesting) + " levels)");
      }
    }
    NestingGuard(const NestingGuard&) = delete;
    NestingGuard& operator=(const NestingGuard&) = delete;
    ~NestingGuard() { --parser_.nesting_; }

   private:
    Parser& parser_;
  };

  ExprPtr expression() {
    NestingGuard guard(*this);
    return binary_level(1);
  }

  static int precedence(TokenKind kind) {
    switch (kind) {
      case TokenKind::Or:
        return 1;
      case TokenKind::And:
        return 2;
      case TokenKind::Equal:
      case TokenKind::NotEqual:
      case TokenKind::Less:
      case TokenKind::LessEqual:
      case TokenKind::Greater:
      case TokenKind::GreaterEqual:
        return 4;
      case TokenKind::Plus:
      case TokenKind::Minus:
        return 5;
      case TokenKind::Star:
      case TokenKind::Slash:
        return 6;
      default:
        return 0;
    }
  }

  ExprPtr binary_level(int level) {
    if (level == 3) return not_level();
    if (level > 6) return unary();
    ExprPtr left = binary_level(level + 1);
    // Whether this loop has already read a comparison. Asking whether `left` is one would
    // also refuse `(a < b) == c`, where the parentheses make the grouping explicit.
    bool compared = false;
    while (precedence(peek().kind) == level) {
      if (level == 4 && compared) {
        fail(peek(), "comparisons cannot be chained; combine them with '&'");
      }
      compared = true;
      const Token& op = advance();
      ExprPtr right = binary_level(level + 1);
      left = make_binary(op, std::move(left), std::move(right));
      check_depth(*left, op);
    }
    if (level == 4 && at(TokenKind::Assign)) {
      fail(peek(), "'=' is not a comparison; use '==' to test equality");
    }
    return left;
  }

  ExprPtr not_level() {
    if (at(TokenKind::Not)) {
      NestingGuard guard(*this);
      const Token& op = advance();
      ExprPtr operand = not_level();
      ExprPtr result = make_unary(op, std::move(operand));
      check_depth(*result, op);
      return result;
    }
    return binary_level(4);
  }

  ExprPtr unary() {
    if (at(TokenKind::Minus)) {
      NestingGuard guard(*this);
      const Token& op = advance();
      ExprPtr operand = unary();
      ExprPtr result = make_unary(op, std::move(operand));
      check_depth(*result, op);
      return result;
    }
    return power();
  }

  // `a ^ b` binds tighter than unary minus (-x^2 is -(x^2)) and groups to the right.
  ExprPtr power() {
    ExprPtr base = primary();
    if (!at(TokenKind::Caret)) return base;
    NestingGuard guard(*this);
    const Token& op = advance();
    ExprPtr exponent = unary();
    ExprPtr result = make_binary(op, std::move(base), std::move(exponent));
    check_depth(*result, op);
    return result;
  }

  ExprPtr primary() {
    const Token& token = peek();
    auto expr = std::make_unique<Expr>();
    expr->range = range_of(token);
    expr->text = token.text;
    switch (token.kind) {
      case TokenKind::Number:
        advance();
        expr->kind = ExprKind::Number;
        return expr;
      case TokenKind::KwTrue:
      case TokenKind::KwFalse:
        advance();
        expr->kind = ExprKind::Boolean;
        return expr;
      case TokenKind::Identifier:
        advance();
        expr->kind = ExprKind::Name;
        if (at(TokenKind::LeftParen)) call_arguments(*expr);
        return expr;
      case TokenKind::LeftParen: {
        advance();
        ExprPtr inner = expression();
        expect(TokenKind::RightParen, "to close the parenthesis");
        ++inner->depth;
        inner->range = span(expr->range, previous_range());
        return inner;
      }
      default:
        fail(token, "expected an expression, found " + found(token));
    }
  }

  void call_arguments(Expr& call) {
    call.kind = ExprKind::Call;
    advance();
    if (!at(TokenKind::RightParen)) {
      do {
        call.operands.push_back(expression());
        call.depth = std::max(call.depth, 1 + call.operands.back()->depth);
        if (call.operands.size() > 16) fail(peek(), "too many arguments");
      } while (accept(TokenKind::Comma));
    }
    expect(TokenKind::RightParen, "to close the argument list");
    call.range = span(call.range, previous_range());
  }

  // A left-deep chain such as 1+1+...+1 is as deep as it is long; every later pass recurses
  // over the tree, so its depth is bounded like parenthesis nesting.
  void check_depth(const Expr& expr, const Token& op) {
    if (expr.depth > kMaxNesting) {
      fail(op, "expression is too long or nested too deeply (the limit is " +
                   std::to_string(kMaxNesting) + " levels)");
    }
  }

  static ExprPtr make_binary(const Token& op, ExprPtr left, ExprPtr right) {
    auto expr = std::make_unique<Expr>();
    expr->kind = ExprKind::Binary;
    expr->op = op.kind;
    expr->op_range = range_of(op);
    expr->range = span(left->range, right->range);
    expr->depth = 1 + std::max(left->depth, right->depth);
    expr->operands.push_back(std::move(left));
    expr->operands.push_back(std::move(right));
    return expr;
  }

  static ExprPtr make_unary(const Token& op, ExprPtr operand) {
    auto expr = std::make_unique<Expr>();
    expr->kind = ExprKind::Unary;
    expr->op = op.kind;
    expr->op_range = range_of(op);
    expr->range = span(range_of(op), operand->range);
    expr->depth = 1 + operand->depth;
    expr->operands.push_back(std::move(operand));
    return expr;
  }

  const std::vector<Token>& tokens_;
  DiagnosticEngine& diagnostics_;
  std::size_t pos_ = 0;
  const Token* previous_ = nullptr;
  int nesting_ = 0;
  const Token* last_failed_ = nullptr;  // the token of the last syntax error
  SpecFile result_;
};

}  // namespace

ast::SpecFile parse(FileId file, const std::vector<Token>& tokens, DiagnosticEngine& diagnostics) {
  return Parser(file, tokens, diagnostics).run();
}

}  // namespace oasis::frontend
