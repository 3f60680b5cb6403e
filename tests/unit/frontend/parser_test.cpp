// Unit tests of the spec parser (compiler/frontend/parser.cpp): the AST shape of every construct,
// expression precedence, syntax errors with their file:line:col and recovery after them, and
// the nesting limit.

#include "frontend/parser.hpp"

#include <sstream>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "frontend/lexer.hpp"

namespace oasis::frontend {
namespace {

using ast::ExprKind;

// Lexes and parses `text` as "parse.oasis". The sources stay alive for the AST's views.
struct Parsed {
  explicit Parsed(std::string text) : diagnostics(sources, out, 100) {
    file = sources.add("parse.oasis", std::move(text));
    tokens = lex(file, diagnostics);
    tree = parse(file, tokens, diagnostics);
  }

  [[nodiscard]] std::string output() const { return out.str(); }
  [[nodiscard]] std::size_t errors() const { return diagnostics.error_count(); }
  [[nodiscard]] bool reported(const std::string& text) const {
    return output().find(text) != std::string::npos;
  }
  // "line:col" of a source offset, for checking AST ranges.
  [[nodiscard]] std::string where(SourceRange range) const {
    const LineColumn lc = sources.file(file).line_column(range.begin.offset);
    return std::to_string(lc.line) + ":" + std::to_string(lc.column);
  }
  // The source text a range covers.
  [[nodiscard]] std::string_view text_of(SourceRange range) const {
    return sources.file(file).text().substr(range.begin.offset, range.length);
  }

  SourceManager sources;
  std::ostringstream out;
  DiagnosticEngine diagnostics;
  FileId file = 0;
  std::vector<Token> tokens;
  ast::SpecFile tree;
};

std::string op_spelling(TokenKind kind) {
  const std::string_view quoted = describe(kind);
  return std::string(quoted.substr(1, quoted.size() - 2));
}

// The expression as an S-expression: `(+ 1 (* 2 3))`, `min(x, 1)`.
std::string sexpr(const ast::Expr& expr) {
  switch (expr.kind) {
    case ExprKind::Number:
    case ExprKind::Boolean:
    case ExprKind::Name:
      return std::string(expr.text);
    case ExprKind::Unary:
      return "(" + op_spelling(expr.op) + " " + sexpr(*expr.operands[0]) + ")";
    case ExprKind::Binary:
      return "(" + op_spelling(expr.op) + " " + sexpr(*expr.operands[0]) + " " +
             sexpr(*expr.operands[1]) + ")";
    case ExprKind::Call: {
      std::string text = std::string(expr.text) + "(";
      for (std::size_t i = 0; i < expr.operands.size(); ++i) {
        if (i > 0) text += ", ";
        text += sexpr(*expr.operands[i]);
      }
      return text + ")";
    }
  }
  return "?";
}

// Parses `expression` as the value of a constant and returns its S-expression, or the
// diagnostics when it does not parse.
std::string parse_expression(const std::string& expression) {
  Parsed parsed("mdp m { const c = " + expression + "; }");
  if (parsed.errors() != 0) return "error: " + parsed.output();
  if (parsed.tree.mdps.size() != 1 || parsed.tree.mdps[0].constants.size() != 1) return "?";
  return sexpr(*parsed.tree.mdps[0].constants[0].value);
}

std::vector<std::string> names(const std::vector<ast::Name>& list) {
  std::vector<std::string> result;
  for (const ast::Name& name : list)
    result.emplace_back(name.text);
  return result;
}

std::string repeat(std::string_view text, int times) {
  std::string result;
  for (int i = 0; i < times; ++i)
    result += text;
  return result;
}

// ---- constructs -----------------------------------------------------------------------------

TEST(Parser, EmptyFileHasNoItems) {
  Parsed parsed("  // nothing\n");
  EXPECT_EQ(parsed.errors(), 0U);
  EXPECT_TRUE(parsed.tree.mdps.empty());
  EXPECT_TRUE(parsed.tree.catalogs.empty());
  EXPECT_EQ(parsed.tree.file, parsed.file);
}

TEST(Parser, ExplicitModelSkeleton) {
  Parsed parsed(
      "mdp robot {\n"
      "  states s1, s2, s3;\n"
      "  actions L, R;\n"
      "  init s2, s3;\n"
      "}\n");
  ASSERT_EQ(parsed.errors(), 0U) << parsed.output();
  ASSERT_EQ(parsed.tree.mdps.size(), 1U);
  const ast::MdpDecl& mdp = parsed.tree.mdps[0];
  EXPECT_EQ(mdp.name.text, "robot");
  EXPECT_EQ(parsed.where(mdp.name.range), "1:5");
  EXPECT_EQ(names(mdp.states), (std::vector<std::string>{"s1", "s2", "s3"}));
  EXPECT_EQ(names(mdp.actions), (std::vector<std::string>{"L", "R"}));
  EXPECT_EQ(names(mdp.initial), (std::vector<std::string>{"s2", "s3"}));
  EXPECT_EQ(parsed.where(mdp.states[1].range), "2:14");
  EXPECT_EQ(mdp.missing, ast::MissingTransitions::Error);
  EXPECT_FALSE(mdp.missing_range);
  // The model's range runs from 'mdp' to its closing brace.
  EXPECT_EQ(mdp.range.begin.offset, 0U);
  EXPECT_EQ(parsed.text_of(mdp.range).back(), '}');
}

TEST(Parser, ConstantsAndVariables) {
  Parsed parsed(
      "mdp m {\n"
      "  const N = 4;\n"
      "  var x : [0 .. N - 1] init 2;\n"
      "  var y : [0..3];\n"
      "  actions a;\n"
      "}\n");
  ASSERT_EQ(parsed.errors(), 0U) << parsed.output();
  const ast::MdpDecl& mdp = parsed.tree.mdps[0];
  ASSERT_EQ(mdp.constants.size(), 1U);
  EXPECT_EQ(mdp.constants[0].name.text, "N");
  EXPECT_EQ(sexpr(*mdp.constants[0].value), "4");
  EXPECT_EQ(parsed.text_of(mdp.constants[0].range), "const N = 4;");
  ASSERT_EQ(mdp.variables.size(), 2U);
  const ast::VarDecl& x = mdp.variables[0];
  EXPECT_EQ(x.name.text, "x");
  EXPECT_FALSE(x.continuous);
  EXPECT_EQ(sexpr(*x.low), "0");
  EXPECT_EQ(sexpr(*x.high), "(- N 1)");
  ASSERT_TRUE(x.init);
  EXPECT_EQ(sexpr(*x.init), "2");
  EXPECT_EQ(parsed.text_of(x.range), "var x : [0 .. N - 1] init 2;");
  const ast::VarDecl& y = mdp.variables[1];
  EXPECT_EQ(sexpr(*y.low), "0");
  EXPECT_EQ(sexpr(*y.high), "3");
  EXPECT_EQ(y.init, nullptr);  // the lower bound
}

TEST(Parser, ContinuousVariablesAndRegions) {
  Parsed parsed(
      "mdp m {\n"
      "  continuous x : [-1.5 .. 2];\n"
      "  region near = x >= -0.5 & x <= 0.5;\n"
      "}\n");
  ASSERT_EQ(parsed.errors(), 0U) << parsed.output();
  const ast::MdpDecl& mdp = parsed.tree.mdps[0];
  ASSERT_EQ(mdp.variables.size(), 1U);
  EXPECT_TRUE(mdp.variables[0].continuous);
  EXPECT_EQ(sexpr(*mdp.variables[0].low), "(- 1.5)");
  EXPECT_EQ(sexpr(*mdp.variables[0].high), "2");
  EXPECT_EQ(mdp.variables[0].init, nullptr);
  ASSERT_EQ(mdp.regions.size(), 1U);
  EXPECT_EQ(mdp.regions[0].name.text, "near");
  EXPECT_EQ(sexpr(*mdp.regions[0].constraint), "(& (>= x (- 0.5)) (<= x 0.5))");
}

TEST(Parser, MissingTransitionPolicies) {
  Parsed self("mdp m { default self; }");
  ASSERT_EQ(self.errors(), 0U) << self.output();
  EXPECT_EQ(self.tree.mdps[0].missing, ast::MissingTransitions::SelfLoop);
  ASSERT_TRUE(self.tree.mdps[0].missing_range);
  EXPECT_EQ(self.text_of(*self.tree.mdps[0].missing_range), "default self;");

  Parsed disabled("mdp m { default disabled; }");
  ASSERT_EQ(disabled.errors(), 0U) << disabled.output();
  EXPECT_EQ(disabled.tree.mdps[0].missing, ast::MissingTransitions::Disabled);
}

TEST(Parser, Settings) {
  Parsed parsed("mdp m { discount 0.9; horizon 10 * 2; period 1/5; }");
  ASSERT_EQ(parsed.errors(), 0U) << parsed.output();
  const ast::MdpDecl& mdp = parsed.tree.mdps[0];
  ASSERT_TRUE(mdp.discount && mdp.horizon && mdp.period);
  EXPECT_EQ(sexpr(*mdp.discount->value), "0.9");
  EXPECT_EQ(sexpr(*mdp.horizon->value), "(* 10 2)");
  EXPECT_EQ(sexpr(*mdp.period->value), "(/ 1 5)");
  EXPECT_EQ(parsed.text_of(mdp.horizon->range), "horizon 10 * 2;");
}

TEST(Parser, ExplicitTransitions) {
  Parsed parsed(
      "mdp m {\n"
      "  s1, L -> s1;\n"
      "  s2, R -> 1/2: s1 + 0.5: s3;\n"
      "}\n");
  ASSERT_EQ(parsed.errors(), 0U) << parsed.output();
  const auto& transitions = parsed.tree.mdps[0].behaviour.transitions;
  ASSERT_EQ(transitions.size(), 2U);

  EXPECT_EQ(transitions[0].state.text, "s1");
  EXPECT_EQ(transitions[0].action.text, "L");
  ASSERT_EQ(transitions[0].distribution.branches.size(), 1U);
  const ast::Branch& certain = transitions[0].distribution.branches[0];
  EXPECT_EQ(certain.probability, nullptr);  // a single certain outcome
  ASSERT_TRUE(certain.target);
  EXPECT_EQ(certain.target->text, "s1");
  EXPECT_TRUE(certain.updates.empty());

  const auto& branches = transitions[1].distribution.branches;
  ASSERT_EQ(branches.size(), 2U);
  EXPECT_EQ(sexpr(*branches[0].probability), "(/ 1 2)");
  EXPECT_EQ(branches[0].target->text, "s1");
  EXPECT_EQ(sexpr(*branches[1].probability), "0.5");
  EXPECT_EQ(branches[1].target->text, "s3");
  EXPECT_EQ(parsed.text_of(transitions[1].distribution.range), "1/2: s1 + 0.5: s3");
  EXPECT_EQ(parsed.text_of(transitions[1].range), "s2, R -> 1/2: s1 + 0.5: s3;");
  EXPECT_EQ(parsed.where(transitions[1].range), "3:3");
}

TEST(Parser, FactoredCommands) {
  Parsed parsed(
      "mdp m {\n"
      "  [go] x < 3 & y == 0 -> 0.9: (x' = x + 1) & (y' = 0) + 0.1: true;\n"
      "  [stay] true -> true;\n"
      "  [reset] x >= 3 -> (x' = 0);\n"
      "  [p] x > 0 -> x / 10: (x' = x - 1) + (10 - x) / 10: true;\n"
      "}\n");
  ASSERT_EQ(parsed.errors(), 0U) << parsed.output();
  const auto& commands = parsed.tree.mdps[0].behaviour.commands;
  ASSERT_EQ(commands.size(), 4U);

  EXPECT_EQ(commands[0].action.text, "go");
  EXPECT_EQ(sexpr(*commands[0].guard), "(& (< x 3) (== y 0))");
  const auto& go = commands[0].distribution.branches;
  ASSERT_EQ(go.size(), 2U);
  EXPECT_EQ(sexpr(*go[0].probability), "0.9");
  ASSERT_EQ(go[0].updates.size(), 2U);
  EXPECT_EQ(go[0].updates[0].variable.text, "x");
  EXPECT_EQ(sexpr(*go[0].updates[0].value), "(+ x 1)");
  EXPECT_EQ(parsed.text_of(go[0].updates[0].range), "x' = x + 1");
  EXPECT_EQ(go[0].updates[1].variable.text, "y");
  EXPECT_EQ(sexpr(*go[0].updates[1].value), "0");
  EXPECT_FALSE(go[0].target);
  EXPECT_EQ(sexpr(*go[1].probability), "0.1");
  EXPECT_TRUE(go[1].updates.empty());  // `true`: nothing changes

  // `true` without a probability is a certain "nothing changes".
  ASSERT_EQ(commands[1].distribution.branches.size(), 1U);
  EXPECT_EQ(commands[1].distribution.branches[0].probability, nullptr);
  EXPECT_TRUE(commands[1].distribution.branches[0].updates.empty());

  // A single update without a probability.
  ASSERT_EQ(commands[2].distribution.branches.size(), 1U);
  EXPECT_EQ(commands[2].distribution.branches[0].probability, nullptr);
  EXPECT_EQ(commands[2].distribution.branches[0].updates.size(), 1U);

  // State-dependent probabilities are expressions like any other.
  const auto& p = commands[3].distribution.branches;
  ASSERT_EQ(p.size(), 2U);
  EXPECT_EQ(sexpr(*p[0].probability), "(/ x 10)");
  EXPECT_EQ(sexpr(*p[1].probability), "(/ (- 10 x) 10)");
}

TEST(Parser, TrueWithProbabilityIsAProbability) {
  // `true: (x' = 1)` would make `true` the probability; the checker refuses it, the parser
  // only has to read it as written.
  Parsed parsed("mdp m { [a] true -> true: (x' = 1); }");
  ASSERT_EQ(parsed.errors(), 0U) << parsed.output();
  const auto& branch = parsed.tree.mdps[0].behaviour.commands[0].distribution.branches[0];
  ASSERT_NE(branch.probability, nullptr);
  EXPECT_EQ(sexpr(*branch.probability), "true");
  EXPECT_EQ(branch.updates.size(), 1U);
}

TEST(Parser, Rewards) {
  Parsed parsed(
      "mdp m {\n"
      "  reward s3 : 1;\n"
      "  reward [go] x > 1 : -0.5 * x;\n"
      "}\n");
  ASSERT_EQ(parsed.errors(), 0U) << parsed.output();
  const auto& rewards = parsed.tree.mdps[0].behaviour.rewards;
  ASSERT_EQ(rewards.size(), 2U);
  EXPECT_FALSE(rewards[0].action);
  EXPECT_EQ(sexpr(*rewards[0].guard), "s3");
  EXPECT_EQ(sexpr(*rewards[0].value), "1");
  ASSERT_TRUE(rewards[1].action);
  EXPECT_EQ(rewards[1].action->text, "go");
  EXPECT_EQ(sexpr(*rewards[1].guard), "(> x 1)");
  EXPECT_EQ(sexpr(*rewards[1].value), "(* (- 0.5) x)");
  EXPECT_EQ(parsed.text_of(rewards[1].range), "reward [go] x > 1 : -0.5 * x;");
}

TEST(Parser, DynamicsAndDisturbances) {
  Parsed parsed(
      "mdp m {\n"
      "  disturbance x in [-0.3 .. 0.3];\n"
      "  dynamics [stop] { }\n"
      "  dynamics [go] {\n"
      "    x' = 2 * x + y;  y' = y - 0.1;\n"
      "    disturbance y ~ gaussian(0, 0.05);\n"
      "  }\n"
      "}\n");
  ASSERT_EQ(parsed.errors(), 0U) << parsed.output();
  const ast::Behaviour& behaviour = parsed.tree.mdps[0].behaviour;
  ASSERT_EQ(behaviour.disturbances.size(), 1U);
  const ast::Disturbance& bounded = behaviour.disturbances[0];
  EXPECT_EQ(bounded.variable.text, "x");
  EXPECT_FALSE(bounded.gaussian);
  EXPECT_EQ(sexpr(*bounded.first), "(- 0.3)");
  EXPECT_EQ(sexpr(*bounded.second), "0.3");

  ASSERT_EQ(behaviour.dynamics.size(), 2U);
  EXPECT_EQ(behaviour.dynamics[0].action.text, "stop");
  EXPECT_TRUE(behaviour.dynamics[0].equations.empty());
  EXPECT_TRUE(behaviour.dynamics[0].disturbances.empty());
  const ast::Dynamics& go = behaviour.dynamics[1];
  EXPECT_EQ(go.action.text, "go");
  ASSERT_EQ(go.equations.size(), 2U);
  EXPECT_EQ(go.equations[0].variable.text, "x");
  EXPECT_EQ(sexpr(*go.equations[0].value), "(+ (* 2 x) y)");
  EXPECT_EQ(go.equations[1].variable.text, "y");
  EXPECT_EQ(sexpr(*go.equations[1].value), "(- y 0.1)");
  ASSERT_EQ(go.disturbances.size(), 1U);
  EXPECT_TRUE(go.disturbances[0].gaussian);
  EXPECT_EQ(sexpr(*go.disturbances[0].first), "0");
  EXPECT_EQ(sexpr(*go.disturbances[0].second), "0.05");
}

TEST(Parser, CatalogWithEveryKindOfContext) {
  Parsed parsed(
      "mdp m { states a; }\n"
      "catalog weather {\n"
      "  context calm = base;\n"
      "  context windy {\n"
      "    a, go -> a;\n"
      "    [go] true -> true;\n"
      "    reward a : 2;\n"
      "    dynamics [go] { }\n"
      "    disturbance x in [0 .. 1];\n"
      "  }\n"
      "  switching stay 0.8;\n"
      "  prior uniform;\n"
      "}\n");
  ASSERT_EQ(parsed.errors(), 0U) << parsed.output();
  ASSERT_EQ(parsed.tree.catalogs.size(), 1U);
  const ast::CatalogDecl& catalog = parsed.tree.catalogs[0];
  ASSERT_TRUE(catalog.name);
  EXPECT_EQ(catalog.name->text, "weather");
  ASSERT_EQ(catalog.contexts.size(), 2U);
  EXPECT_EQ(catalog.contexts[0].name.text, "calm");
  EXPECT_TRUE(catalog.contexts[0].is_base);
  const ast::ContextDecl& windy = catalog.contexts[1];
  EXPECT_EQ(windy.name.text, "windy");
  EXPECT_FALSE(windy.is_base);
  EXPECT_EQ(windy.behaviour.transitions.size(), 1U);
  EXPECT_EQ(windy.behaviour.commands.size(), 1U);
  EXPECT_EQ(windy.behaviour.rewards.size(), 1U);
  EXPECT_EQ(windy.behaviour.dynamics.size(), 1U);
  EXPECT_EQ(windy.behaviour.disturbances.size(), 1U);
  ASSERT_TRUE(catalog.switching);
  ASSERT_NE(catalog.switching->stay, nullptr);
  EXPECT_EQ(sexpr(*catalog.switching->stay), "0.8");
  EXPECT_TRUE(catalog.switching->rows.empty());
  ASSERT_TRUE(catalog.prior);
  EXPECT_TRUE(catalog.prior->uniform);
}

TEST(Parser, SwitchingRowsAndPriorDistribution) {
  Parsed parsed(
      "catalog {\n"
      "  context one = base;\n"
      "  context two = base;\n"
      "  switching {\n"
      "    one -> 0.8: one + 0.2: two;\n"
      "    two -> two;\n"
      "  }\n"
      "  prior 1/4: one + 3/4: two;\n"
      "}\n");
  ASSERT_EQ(parsed.errors(), 0U) << parsed.output();
  const ast::CatalogDecl& catalog = parsed.tree.catalogs[0];
  EXPECT_FALSE(catalog.name);
  ASSERT_TRUE(catalog.switching);
  EXPECT_EQ(catalog.switching->stay, nullptr);
  ASSERT_EQ(catalog.switching->rows.size(), 2U);
  EXPECT_EQ(catalog.switching->rows[0].first.text, "one");
  const auto& row = catalog.switching->rows[0].second.branches;
  ASSERT_EQ(row.size(), 2U);
  EXPECT_EQ(sexpr(*row[0].probability), "0.8");
  EXPECT_EQ(row[0].target->text, "one");
  EXPECT_EQ(row[1].target->text, "two");
  EXPECT_EQ(catalog.switching->rows[1].second.branches[0].probability, nullptr);
  ASSERT_TRUE(catalog.prior);
  EXPECT_FALSE(catalog.prior->uniform);
  ASSERT_EQ(catalog.prior->distribution.branches.size(), 2U);
  EXPECT_EQ(sexpr(*catalog.prior->distribution.branches[1].probability), "(/ 3 4)");
}

TEST(Parser, SeveralModelsAndCatalogsAreKeptForTheChecker) {
  Parsed parsed("mdp a { } catalog { } mdp b { } catalog c { }");
  ASSERT_EQ(parsed.errors(), 0U) << parsed.output();
  EXPECT_EQ(parsed.tree.mdps.size(), 2U);
  EXPECT_EQ(parsed.tree.catalogs.size(), 2U);
}

TEST(Parser, ContextualWordsCanBeNames) {
  Parsed parsed(
      "mdp m {\n"
      "  states self, in, stay, base, uniform, gaussian, disabled;\n"
      "  actions self;\n"
      "  default self;\n"
      "  self, self -> in;\n"
      "}\n"
      "catalog { context stay = base; switching stay 1; prior uniform; }\n");
  ASSERT_EQ(parsed.errors(), 0U) << parsed.output();
  EXPECT_EQ(parsed.tree.mdps[0].states.size(), 7U);
  EXPECT_EQ(parsed.tree.mdps[0].missing, ast::MissingTransitions::SelfLoop);
  EXPECT_EQ(parsed.tree.mdps[0].behaviour.transitions[0].distribution.branches[0].target->text,
            "in");
  EXPECT_EQ(parsed.tree.catalogs[0].contexts[0].name.text, "stay");
}

TEST(Parser, ShippedSpecsParseCleanly) {
  for (const char* name : {"discrete_tracking", "go1_treat"}) {
    SourceManager sources;
    std::ostringstream out;
    DiagnosticEngine diagnostics(sources, out);
    MappedFile contents;
    std::string reason;
    const std::string path = std::string(OASIS_SOURCE_DIR) + "/specs/" + name + ".oasis";
    ASSERT_TRUE(contents.open(path, 1 << 20, reason)) << reason;
    const FileId file = sources.add(path, std::move(contents));
    const auto tokens = lex(file, diagnostics);
    const ast::SpecFile tree = parse(file, tokens, diagnostics);
    EXPECT_EQ(diagnostics.error_count(), 0U) << out.str();
    EXPECT_EQ(tree.mdps.size(), 1U);
    EXPECT_EQ(tree.catalogs.size(), 1U);
  }
}

// ---- expressions ----------------------------------------------------------------------------

TEST(ParserExpressions, Atoms) {
  EXPECT_EQ(parse_expression("42"), "42");
  EXPECT_EQ(parse_expression("0.125"), "0.125");
  EXPECT_EQ(parse_expression("true"), "true");
  EXPECT_EQ(parse_expression("false"), "false");
  EXPECT_EQ(parse_expression("x"), "x");
  EXPECT_EQ(parse_expression("f()"), "f()");
  EXPECT_EQ(parse_expression("min(x, 1, y + 2)"), "min(x, 1, (+ y 2))");
  EXPECT_EQ(parse_expression("max(min(a, b), abs(-c))"), "max(min(a, b), abs((- c)))");
}

TEST(ParserExpressions, ArithmeticPrecedenceAndAssociativity) {
  EXPECT_EQ(parse_expression("1 + 2 * 3"), "(+ 1 (* 2 3))");
  EXPECT_EQ(parse_expression("1 * 2 + 3"), "(+ (* 1 2) 3)");
  EXPECT_EQ(parse_expression("(1 + 2) * 3"), "(* (+ 1 2) 3)");
  EXPECT_EQ(parse_expression("1 - 2 - 3"), "(- (- 1 2) 3)");
  EXPECT_EQ(parse_expression("8 / 4 / 2"), "(/ (/ 8 4) 2)");
  EXPECT_EQ(parse_expression("1 - 2 + 3"), "(+ (- 1 2) 3)");
  EXPECT_EQ(parse_expression("6 / 2 * 3"), "(* (/ 6 2) 3)");
  EXPECT_EQ(parse_expression("-x * 2"), "(* (- x) 2)");
  EXPECT_EQ(parse_expression("2 * -x"), "(* 2 (- x))");
  EXPECT_EQ(parse_expression("- -x"), "(- (- x))");
  EXPECT_EQ(parse_expression("1 - -1"), "(- 1 (- 1))");
}

TEST(ParserExpressions, LogicalPrecedence) {
  EXPECT_EQ(parse_expression("!a & b | c"), "(| (& (! a) b) c)");
  EXPECT_EQ(parse_expression("a | b & c"), "(| a (& b c))");
  EXPECT_EQ(parse_expression("a && b || c"), "(| (& a b) c)");
  EXPECT_EQ(parse_expression("a | b | c"), "(| (| a b) c)");
  EXPECT_EQ(parse_expression("!!a"), "(! (! a))");
  EXPECT_EQ(parse_expression("!(a | b)"), "(! (| a b))");
  // '!' binds looser than comparisons and arithmetic: `!x < 3` is `!(x < 3)`.
  EXPECT_EQ(parse_expression("!x < 3"), "(! (< x 3))");
  EXPECT_EQ(parse_expression("x + 1 < y * 2 & y != 0"), "(& (< (+ x 1) (* y 2)) (!= y 0))");
  EXPECT_EQ(parse_expression("a == b | c >= d"), "(| (== a b) (>= c d))");
}

TEST(ParserExpressions, EveryComparison) {
  for (const char* op : {"==", "!=", "<", "<=", ">", ">="}) {
    EXPECT_EQ(parse_expression(std::string("x ") + op + " 1"), std::string("(") + op + " x 1)");
  }
}

TEST(ParserExpressions, ChainedComparisonsAreRefused) {
  for (const char* chain : {"1 < 2 < 3", "a == b == c", "x <= y != z", "1 < x == true"}) {
    Parsed parsed(std::string("mdp m { const c = ") + chain + "; }");
    EXPECT_EQ(parsed.errors(), 1U) << chain;
    EXPECT_TRUE(parsed.reported("error: comparisons cannot be chained; combine them with '&'"))
        << chain << "\n"
        << parsed.output();
  }
}

TEST(ParserExpressions, ParenthesisedComparisonsMayBeCompared) {
  // Parentheses make the grouping explicit, so comparing two comparisons ("iff") is fine.
  EXPECT_EQ(parse_expression("(x < 1) == (y < 1)"), "(== (< x 1) (< y 1))");
  EXPECT_EQ(parse_expression("(a == b) != c"), "(!= (== a b) c)");
  EXPECT_EQ(parse_expression("a == (b == c)"), "(== a (== b c))");
}

TEST(ParserExpressions, SingleEqualsGetsAHint) {
  Parsed parsed("mdp m {\n  [a] x = 1 -> true;\n}\n");
  EXPECT_EQ(parsed.errors(), 1U);
  EXPECT_TRUE(
      parsed.reported("parse.oasis:2:9: error: '=' is not a comparison; use '==' to test equality"))
      << parsed.output();

  Parsed in_constant("mdp m { const c = 1 + 1 = 2; }");
  EXPECT_TRUE(in_constant.reported("use '==' to test equality")) << in_constant.output();
}

TEST(ParserExpressions, RangesCoverTheWholeExpression) {
  Parsed parsed("mdp m { const c = (1 + 2) * abs(x); }");
  ASSERT_EQ(parsed.errors(), 0U) << parsed.output();
  const ast::Expr& product = *parsed.tree.mdps[0].constants[0].value;
  EXPECT_EQ(parsed.text_of(product.range), "(1 + 2) * abs(x)");
  EXPECT_EQ(parsed.text_of(product.op_range), "*");
  EXPECT_EQ(parsed.text_of(product.operands[0]->range), "(1 + 2)");
  EXPECT_EQ(parsed.text_of(product.operands[1]->range), "abs(x)");
}

// ---- syntax errors and recovery -------------------------------------------------------------

TEST(ParserErrors, MessageHasFileLineColumn) {
  Parsed parsed(
      "mdp m {\n"
      "  states a, b\n"
      "  actions go;\n"
      "}\n");
  EXPECT_EQ(parsed.errors(), 1U);
  EXPECT_EQ(parsed.output(),
            "parse.oasis:3:3: error: expected ';' after the list, found 'actions'\n"
            "  actions go;\n"
            "  ^~~~~~~\n");
}

TEST(ParserErrors, RecoversToReportALaterErrorInTheSameFile) {
  Parsed parsed(
      "mdp m {\n"
      "  states a b;\n"
      "  actions go;\n"
      "  a, go -> ;\n"
      "  b, go -> a;\n"
      "}\n");
  EXPECT_EQ(parsed.errors(), 2U) << parsed.output();
  EXPECT_TRUE(parsed.reported("parse.oasis:2:12: error: expected ';' after the list, found 'b'"))
      << parsed.output();
  EXPECT_TRUE(parsed.reported("parse.oasis:4:12: error: expected an expression, found ';'"))
      << parsed.output();
  // The statements between and after the errors were still read.
  ASSERT_EQ(parsed.tree.mdps.size(), 1U);
  EXPECT_EQ(names(parsed.tree.mdps[0].actions), std::vector<std::string>{"go"});
  ASSERT_EQ(parsed.tree.mdps[0].behaviour.transitions.size(), 1U);
  EXPECT_EQ(parsed.tree.mdps[0].behaviour.transitions[0].state.text, "b");
}

TEST(ParserErrors, RecoversAcrossBlocks) {
  Parsed parsed(
      "mdp m {\n"
      "  dynamics [go] { x' = ; }\n"
      "  actions go;\n"
      "}\n"
      "catalog {\n"
      "  context c { reward : 1; }\n"
      "  prior uniform;\n"
      "}\n");
  EXPECT_EQ(parsed.errors(), 2U) << parsed.output();
  EXPECT_TRUE(parsed.reported("parse.oasis:2:24: error: expected an expression, found ';'"))
      << parsed.output();
  EXPECT_TRUE(parsed.reported("parse.oasis:6:22: error: expected an expression, found ':'"))
      << parsed.output();
  EXPECT_EQ(parsed.tree.mdps[0].actions.size(), 1U);
  ASSERT_EQ(parsed.tree.catalogs.size(), 1U);
  EXPECT_TRUE(parsed.tree.catalogs[0].prior);
}

TEST(ParserErrors, RecoversAtTopLevel) {
  Parsed parsed("garbage here; mdp m { states a; }");
  EXPECT_EQ(parsed.errors(), 1U);
  EXPECT_TRUE(parsed.reported(
      "parse.oasis:1:1: error: expected 'mdp', 'import' or 'catalog', found 'garbage'"))
      << parsed.output();
  ASSERT_EQ(parsed.tree.mdps.size(), 1U);
  EXPECT_EQ(parsed.tree.mdps[0].states.size(), 1U);
}

TEST(ParserErrors, UnclosedBlock) {
  Parsed parsed("mdp m {\n  states a;\n");
  EXPECT_EQ(parsed.errors(), 1U);
  EXPECT_TRUE(
      parsed.reported("parse.oasis:3:1: error: expected '}' to close the block, found end of file"))
      << parsed.output();
}

TEST(ParserErrors, UnclosedNestedBlocksGiveOneError) {
  // Each enclosing block meets the same end of file; that is one mistake, said once.
  for (const char* text : {"mdp m {\n  states a;\n  dynamics [a] {\n",
                           "catalog { context c { reward a : 1;", "mdp m { dynamics [a] { x' ="}) {
    Parsed parsed(text);
    EXPECT_EQ(parsed.errors(), 1U) << text << "\n" << parsed.output();
  }
}

TEST(ParserErrors, MissingModelName) {
  Parsed parsed("mdp { }");
  EXPECT_TRUE(parsed.reported("1:5: error: expected a model name after 'mdp', found '{'"))
      << parsed.output();
}

TEST(ParserErrors, KeywordAsAName) {
  Parsed parsed("mdp m { states a, context; }");
  EXPECT_EQ(parsed.errors(), 1U);
  EXPECT_TRUE(parsed.reported(
      "1:19: error: expected a state name, found 'context' (a keyword cannot be used as a name)"))
      << parsed.output();
}

TEST(ParserErrors, UnknownModelItem) {
  Parsed parsed("mdp m { 42; }");
  EXPECT_TRUE(parsed.reported(
      "error: expected a model item (states, actions, var, a transition, reward, ...), found "
      "'42'"))
      << parsed.output();
}

TEST(ParserErrors, BadDefault) {
  Parsed parsed("mdp m { default loop; }");
  EXPECT_TRUE(
      parsed.reported("1:17: error: expected 'self' or 'disabled' after 'default', "
                      "found 'loop'"))
      << parsed.output();
}

TEST(ParserErrors, ContinuousVariableWithInit) {
  Parsed parsed("mdp m { continuous x : [0 .. 1] init 0; }");
  EXPECT_EQ(parsed.errors(), 1U);
  EXPECT_TRUE(parsed.reported("1:33: error: continuous variables have no 'init' value"))
      << parsed.output();
}

TEST(ParserErrors, VariableRangeNeedsDots) {
  Parsed parsed("mdp m { var x : [0, 3]; }");
  EXPECT_TRUE(parsed.reported("error: expected '..' between the bounds, found ','"))
      << parsed.output();
}

TEST(ParserErrors, ExplicitTransitionNeedsAComma) {
  Parsed parsed("mdp m { a go -> b; }");
  EXPECT_TRUE(parsed.reported("error: expected ',' between the state and the action, found 'go'"))
      << parsed.output();
}

TEST(ParserErrors, UpdateNeedsAPrime) {
  Parsed parsed("mdp m { [a] true -> (x = 1); }");
  EXPECT_TRUE(
      parsed.reported("1:24: error: expected ''' after the variable (write x' = ...), found '='"))
      << parsed.output();
  Parsed bare("mdp m { [a] true -> x' = 1; }");
  // Without parentheses `x` reads as a probability, which needs a ':' after it.
  EXPECT_TRUE(
      bare.reported("1:22: error: expected ':' between the probability and its outcome, "
                    "found '''"))
      << bare.output();
}

TEST(ParserErrors, DuplicateSwitchingAndPrior) {
  Parsed parsed(
      "catalog {\n"
      "  context a = base;\n"
      "  switching stay 1;\n"
      "  switching stay 1;\n"
      "  prior uniform;\n"
      "  prior uniform;\n"
      "}\n");
  EXPECT_EQ(parsed.errors(), 2U);
  EXPECT_TRUE(parsed.reported("4:3: error: the catalog already has a switching model"))
      << parsed.output();
  EXPECT_TRUE(parsed.reported("6:3: error: the catalog already has a prior")) << parsed.output();
}

TEST(ParserErrors, BadCatalogItems) {
  Parsed parsed(
      "catalog {\n"
      "  states a;\n"
      "  context b = other;\n"
      "  context c { states x; }\n"
      "}\n");
  EXPECT_EQ(parsed.errors(), 3U) << parsed.output();
  EXPECT_TRUE(parsed.reported(
      "2:3: error: expected 'context', 'switching', 'prior', 'observation' or 'property', found "
      "'states'"))
      << parsed.output();
  EXPECT_TRUE(parsed.reported(
      "3:15: error: expected 'base' or 'rewards \"name\"' after '=', found 'other'"))
      << parsed.output();
  EXPECT_TRUE(parsed.reported(
      "4:15: error: expected a transition, command, reward or dynamics in a context, found "
      "'states'"))
      << parsed.output();
}

TEST(ParserErrors, BadDisturbances) {
  Parsed parsed(
      "mdp m {\n"
      "  disturbance x [0 .. 1];\n"
      "  disturbance y ~ normal(0, 1);\n"
      "}\n");
  EXPECT_EQ(parsed.errors(), 2U) << parsed.output();
  EXPECT_TRUE(
      parsed.reported("2:17: error: expected 'in [lo .. hi]' or '~ gaussian(mean, sd)', found '['"))
      << parsed.output();
  EXPECT_TRUE(parsed.reported("3:19: error: expected 'gaussian' after '~', found 'normal'"))
      << parsed.output();
}

TEST(ParserErrors, TooManyArguments) {
  std::string args = "1";
  for (int i = 0; i < 16; ++i)
    args += ", 1";  // 17 arguments
  Parsed parsed("mdp m { const c = max(" + args + "); }");
  EXPECT_EQ(parsed.errors(), 1U);
  EXPECT_TRUE(parsed.reported("error: too many arguments")) << parsed.output();
  std::string sixteen = "1";
  for (int i = 0; i < 15; ++i)
    sixteen += ", 1";
  EXPECT_EQ(parse_expression("max(" + sixteen + ")").substr(0, 4), "max(");
}

TEST(ParserErrors, UnclosedParenthesisAndCall) {
  Parsed paren("mdp m { const c = (1 + 2; }");
  EXPECT_TRUE(paren.reported("error: expected ')' to close the parenthesis, found ';'"))
      << paren.output();
  Parsed call("mdp m { const c = min(1, 2; }");
  EXPECT_TRUE(call.reported("error: expected ')' to close the argument list, found ';'"))
      << call.output();
}

TEST(ParserErrors, LexerErrorsAreNotRepeated) {
  // The lexer reports the '@'; the parser, meeting the Invalid token, stays quiet about it.
  Parsed parsed("mdp m { states a, @; actions go; }");
  EXPECT_EQ(parsed.errors(), 1U) << parsed.output();
  EXPECT_TRUE(parsed.reported("1:19: error: unexpected character '@'")) << parsed.output();
  EXPECT_EQ(parsed.tree.mdps[0].actions.size(), 1U);
}

TEST(ParserErrors, EndOfFileInsideAnItem) {
  for (const char* text : {"mdp", "mdp m", "mdp m {", "mdp m { states", "mdp m { states a,",
                           "mdp m { [a", "mdp m { [a] x <", "mdp m { a, b -> 1/2:",
                           "catalog { switching {", "catalog { context c = "}) {
    Parsed parsed(text);
    EXPECT_GE(parsed.errors(), 1U) << text;
    EXPECT_TRUE(parsed.reported("found end of file")) << text << "\n" << parsed.output();
  }
}

// ---- nesting limit --------------------------------------------------------------------------

TEST(ParserNesting, ModerateNestingIsFine) {
  const std::string deep = repeat("(", 150) + "1" + repeat(")", 150);
  EXPECT_EQ(parse_expression(deep), "1");
  EXPECT_EQ(parse_expression(repeat("-", 150) + "1").size(), 150U * 3 + 1 + 150);
  std::string sum = "1";
  for (int i = 0; i < 150; ++i)
    sum += " + 1";
  EXPECT_EQ(parse_expression(sum).substr(0, 3), "(+ ");
}

TEST(ParserNesting, DeepParenthesesGiveAnError) {
  for (int depth : {201, 1000, 100000}) {
    Parsed parsed("mdp m {\n  const c = " + repeat("(", depth) + "1" + repeat(")", depth) +
                  ";\n  actions go;\n}\n");
    EXPECT_EQ(parsed.errors(), 1U) << depth;
    EXPECT_TRUE(parsed.reported("error: expression is nested too deeply (the limit is 200 levels)"))
        << depth;
    // The parser recovered and read the statement after it.
    ASSERT_EQ(parsed.tree.mdps.size(), 1U);
    EXPECT_EQ(parsed.tree.mdps[0].actions.size(), 1U) << depth;
  }
}

TEST(ParserNesting, DeepUnaryOperatorsGiveAnError) {
  for (const char* op : {"-", "!", "abs("}) {
    Parsed parsed("mdp m { const c = " + repeat(op, 5000) + "1; actions go; }");
    EXPECT_EQ(parsed.errors(), 1U) << op;
    EXPECT_TRUE(parsed.reported("nested too deeply (the limit is 200 levels)"))
        << op << parsed.output();
    EXPECT_EQ(parsed.tree.mdps[0].actions.size(), 1U) << op;
  }
}

TEST(ParserNesting, LongLeftDeepChainGivesAnError) {
  // 1+1+...+1 with 5000 terms is a tree 5000 levels deep: refused like deep parentheses.
  std::string chain = "1";
  for (int i = 1; i < 5000; ++i)
    chain += "+1";
  Parsed parsed("mdp m {\n  const c = " + chain + ";\n  actions go;\n}\n");
  EXPECT_EQ(parsed.errors(), 1U) << parsed.output();
  EXPECT_TRUE(parsed.reported(
      "error: expression is too long or nested too deeply (the limit is 200 levels)"))
      << parsed.output();
  EXPECT_EQ(parsed.tree.mdps[0].actions.size(), 1U);

  for (const char* op : {"*", "&", "|", "-", "/"}) {
    std::string other = "x";
    for (int i = 1; i < 5000; ++i)
      other += std::string(op) + "x";
    Parsed again("mdp m { const c = " + other + "; }");
    EXPECT_EQ(again.errors(), 1U) << op;
    EXPECT_TRUE(again.reported("too long or nested too deeply")) << op;
  }
}

TEST(ParserNesting, LongDistributionIsNotAnExpression) {
  // Branches of a distribution are a list, not a nested expression: 5000 are fine.
  std::string distribution = "1/5000: a";
  for (int i = 1; i < 5000; ++i)
    distribution += " + 1/5000: a";
  Parsed parsed("mdp m { a, go -> " + distribution + "; }");
  EXPECT_EQ(parsed.errors(), 0U) << parsed.output().substr(0, 500);
  EXPECT_EQ(parsed.tree.mdps[0].behaviour.transitions[0].distribution.branches.size(), 5000U);
}

}  // namespace
}  // namespace oasis::frontend
