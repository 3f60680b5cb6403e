#pragma once
// Checks an AST expression against the scope: resolves names, infers types (bool, int,
// number), folds constant sub-expressions exactly, and refuses what the place it appears in
// does not allow (state variables in a constant, continuous variables in a guard, ...).

#include <cstddef>
#include <optional>
#include <string_view>

#include "frontend/ast.hpp"
#include "frontend/scope.hpp"
#include "model/expression.hpp"

namespace oasis::frontend {

// What an expression may refer to where it appears.
struct ExpressionRules {
  bool discrete_state = false;      // discrete variables and explicit state names
  bool continuous = false;          // continuous variables
  bool regions = false;             // region names
  bool dynamics = false;            // inputs and the functions of dynamics (sin, exp, ...)
  std::string_view place = "here";  // for messages: "in a constant", "in a guard", ...
};

class ExpressionChecker {
 public:
  // No number written or folded may have a numerator or denominator longer than
  // `max_number_bits` (support/limits.hpp): each one is checked where it is made, so that a
  // chain of constants squaring each other stops with an error instead of exhausting memory.
  ExpressionChecker(const Scope& scope, DiagnosticEngine& diagnostics, std::size_t max_number_bits)
      : scope_(scope), diagnostics_(diagnostics), max_number_bits_(max_number_bits) {}

  // nullopt when an error was reported.
  std::optional<model::Expression> check(const ast::Expr& expr, const ExpressionRules& rules);

  // Checks and requires the result to have `type` (Real accepts Int).
  std::optional<model::Expression> check_typed(const ast::Expr& expr, const ExpressionRules& rules,
                                               model::Type type, std::string_view what);

  // A constant number (constant folding must succeed) that a catalog can carry as a double
  // (support/double_range.hpp: an error beyond the double range, a warning when subnormal).
  // `what` is used in messages.
  std::optional<Rational> constant_number(const ast::Expr& expr, std::string_view what);
  // The probability of a branch `p: target` of a listed distribution: a constant number in
  // [0, 1], or 1 when the branch gives none. nullopt when an error was reported.
  std::optional<Rational> branch_probability(const ast::Branch& branch);
  // A constant integer that fits in 64 bits.
  std::optional<std::int64_t> constant_integer(const ast::Expr& expr, std::string_view what);

 private:
  std::optional<model::Expression> name(const ast::Expr& expr, const ExpressionRules& rules);
  std::optional<model::Expression> unary(const ast::Expr& expr, const ExpressionRules& rules);
  std::optional<model::Expression> binary(const ast::Expr& expr, const ExpressionRules& rules);
  std::optional<model::Expression> call(const ast::Expr& expr, const ExpressionRules& rules);
  std::optional<model::Expression> power(model::Expression expr);
  std::optional<model::Expression> fold(model::Expression expr);
  std::optional<Rational> constant_value(const ast::Expr& expr, std::string_view what);
  bool expect_type(const model::Expression& expr, model::Type type, std::string_view context);
  // False after reporting a number longer than max_number_bits_ at `where`.
  bool check_number_size(const Rational& value, SourceRange where);

  const Scope& scope_;
  DiagnosticEngine& diagnostics_;
  std::size_t max_number_bits_;
};

// `const NAME = expr;`: checks the value, which must fold to a constant, and declares the name
// in `scope` (the scope `expressions` reads), marked failed when the value has an error so that
// its uses say nothing more. The value when both the value and the name were sound.
std::optional<model::Expression> declare_constant(const ast::ConstDecl& constant, Scope& scope,
                                                  ExpressionChecker& expressions,
                                                  DiagnosticEngine& diagnostics);

}  // namespace oasis::frontend
