#pragma once
// Types PRISM expressions and lowers them to the model IR's expressions. Operators PRISM has
// and the IR lacks are spelt out (a => b is !a | b; a <=> b is a = b over booleans; a boolean
// variable x is x = 1). Constant sub-expressions are folded exactly, as the .oasis checker
// folds them: 1/3 stays 1/3.

#include <cstddef>
#include <functional>
#include <optional>
#include <string_view>

#include "model/expression.hpp"
#include "prism/ast.hpp"

namespace oasis::prism {

// A lowered expression grows when formulas are expanded into it; past this many nodes it is
// refused, so that formulas that use each other twice over cannot take exponential memory.
inline constexpr std::size_t kMaxExpressionNodes = 1'000'000;

std::size_t count_nodes(const model::Expression& expr);

class ExpressionLowering {
 public:
  // Resolves a name (a variable, constant or formula) to its expression; nullopt after
  // reporting that it means nothing (or that its own definition failed). Extension nodes (the
  // property language's) are resolved by it too.
  using Resolve = std::function<std::optional<model::Expression>(const ast::Expr& name)>;

  ExpressionLowering(DiagnosticEngine& diagnostics, std::size_t max_number_bits, Resolve resolve)
      : diagnostics_(diagnostics),
        max_number_bits_(max_number_bits),
        resolve_(std::move(resolve)) {}

  // nullopt after reporting an error.
  std::optional<model::Expression> lower(const ast::Expr& expr);
  // The same, and the result must have type `wanted` (an int is accepted for a number).
  // `what` names it in the message: "the guard", "a probability".
  std::optional<model::Expression> lower_as(const ast::Expr& expr, model::Type wanted,
                                            std::string_view what);

 private:
  std::optional<model::Expression> lower_node(const ast::Expr& expr);
  std::optional<model::Expression> literal(const ast::Expr& expr);
  std::optional<model::Expression> unary(const ast::Expr& expr);
  std::optional<model::Expression> binary(const ast::Expr& expr);
  std::optional<model::Expression> conditional(const ast::Expr& expr);
  std::optional<model::Expression> call(const ast::Expr& expr);
  std::optional<model::Expression> fold(model::Expression expr);
  bool check_operand(const model::Expression& operand, bool numeric, std::string_view op);

  DiagnosticEngine& diagnostics_;
  std::size_t max_number_bits_;
  Resolve resolve_;
  std::size_t nodes_ = 0;
};

}  // namespace oasis::prism
