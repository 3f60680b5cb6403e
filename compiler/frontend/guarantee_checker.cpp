#include "frontend/guarantee_checker.hpp"

#include <set>
#include <string>
#include <utility>

#include "model/affine.hpp"
#include "model/enclosure.hpp"
#include "support/text.hpp"

namespace oasis::frontend {
namespace {

using model::Type;

// Large enough for any input grid a tool of the field uses (AMYTISS goes to thousands), small
// enough that the product of a few inputs stays a sane number of actions.
constexpr std::int64_t kMaxInputValues = 10'000;
constexpr std::int64_t kMaxCellsPerAxis = 1'000'000;
constexpr std::uint64_t kMaxGridCells = 10'000'000'000;
// Every combination of the inputs' values is an action of every cell: beyond this, no grid
// would fit in memory, and the domain check (one enclosure per combination) would not end.
constexpr std::uint64_t kMaxInputCombinations = 100'000;
constexpr std::int64_t kMaxSteps = 1'000'000;

std::optional<std::vector<Rational>> input_range(const ast::InputDecl& input,
                                                 ExpressionChecker& expressions,
                                                 DiagnosticEngine& diagnostics) {
  auto low = expressions.constant_number(*input.low, "a lower bound");
  auto high = expressions.constant_number(*input.high, "an upper bound");
  auto step = expressions.constant_number(*input.step, "a step");
  if (!low || !high || !step) return std::nullopt;
  if (*low > *high) {
    diagnostics.error(input.range,
                      "empty input range: " + describe(*low) + " is above " + describe(*high));
    return std::nullopt;
  }
  if (*step <= 0) {
    diagnostics.error(input.step->range, "the step must be positive, not " + describe(*step));
    return std::nullopt;
  }
  const Rational span = (*high - *low) / *step;
  mpz_class steps;
  mpz_fdiv_q(steps.get_mpz_t(), span.get_num_mpz_t(), span.get_den_mpz_t());
  if (steps >= kMaxInputValues) {
    diagnostics.error(input.range, "the input takes more than " + std::to_string(kMaxInputValues) +
                                       " values: use a larger step");
    return std::nullopt;
  }
  std::vector<Rational> values;
  for (long k = 0; k <= steps.get_si(); ++k)
    values.push_back(*low + Rational(k) * *step);
  return values;
}

std::optional<std::vector<Rational>> input_list(const ast::InputDecl& input,
                                                ExpressionChecker& expressions,
                                                DiagnosticEngine& diagnostics) {
  std::vector<Rational> values;
  std::set<Rational> seen;
  for (const ast::ExprPtr& expr : input.values) {
    auto value = expressions.constant_number(*expr, "an input value");
    if (!value) return std::nullopt;
    if (!seen.insert(*value).second) {
      diagnostics.error(expr->range, "the value " + describe(*value) + " is listed twice");
      return std::nullopt;
    }
    values.push_back(std::move(*value));
  }
  if (static_cast<std::int64_t>(values.size()) > kMaxInputValues) {
    diagnostics.error(input.range,
                      "an input takes at most " + std::to_string(kMaxInputValues) + " values");
    return std::nullopt;
  }
  return values;
}

// A set of an objective: a conjunction of regions and linear inequalities.
std::optional<std::vector<model::LinearConstraint>> objective_set(const ast::Expr& expr,
                                                                  const model::ModelIR& ir,
                                                                  ExpressionChecker& expressions,
                                                                  DiagnosticEngine& diagnostics) {
  const ExpressionRules rules{.continuous = true, .regions = true, .place = "in an objective"};
  auto condition = expressions.check_typed(expr, rules, Type::Bool, "an objective's set");
  if (!condition) return std::nullopt;
  auto constraints = model::polyhedral_constraints(*condition, ir.continuous.size(), ir.regions);
  if (!constraints) {
    diagnostics.error(expr.range,
                      "an objective's set must be a conjunction ('&') of regions and linear "
                      "inequalities");
  }
  return constraints;
}

void check_objective_item(const ast::ObjectiveDecl& decl, model::ModelIR& ir,
                          ExpressionChecker& expressions, DiagnosticEngine& diagnostics) {
  model::GuaranteeObjective objective;
  objective.kind = decl.reach ? model::GuaranteeObjective::Kind::ReachAvoid
                              : model::GuaranteeObjective::Kind::Safety;
  objective.range = decl.range;
  objective.exactly_at_step = decl.exactly_at_step;
  bool ok = true;
  if (decl.target) {
    auto target = objective_set(*decl.target, ir, expressions, diagnostics);
    ok = ok && target;
    if (target) objective.target = std::move(*target);
  }
  if (decl.safe) {
    auto safe = objective_set(*decl.safe, ir, expressions, diagnostics);
    ok = ok && safe;
    if (safe) objective.safe = std::move(*safe);
  }
  if (decl.steps) {
    auto steps = expressions.constant_integer(*decl.steps, "a number of steps");
    if (steps && (*steps < 1 || *steps > kMaxSteps)) {
      diagnostics.error(decl.steps->range, "the number of steps must be from 1 to 10^6");
      steps.reset();
    }
    ok = ok && steps;
    if (steps) objective.steps = static_cast<std::uint64_t>(*steps);
  }
  if (ok) ir.guarantee = std::move(objective);
}

void check_grid(const ast::GridDecl& grid, model::ModelIR& ir, const Scope& scope,
                ExpressionChecker& expressions, DiagnosticEngine& diagnostics) {
  std::vector<std::int64_t> cells(ir.continuous.size(), 0);
  for (const auto& [name, count_expr] : grid.cells) {
    const auto* entry = scope.find(name.text);
    if (entry == nullptr || entry->value.kind != SymbolKind::ContinuousVariable) {
      diagnostics.error(name.range, "unknown continuous variable " + quoted(name.text));
      return;
    }
    auto count = expressions.constant_integer(*count_expr, "a number of cells");
    if (!count) return;
    if (*count < 1 || *count > kMaxCellsPerAxis) {
      diagnostics.error(count_expr->range, "cells per variable must be from 1 to 10^6");
      return;
    }
    if (cells[entry->value.index] != 0) {
      diagnostics.error(name.range, "variable " + quoted(name.text) + " is listed twice");
      return;
    }
    cells[entry->value.index] = *count;
  }
  for (std::size_t i = 0; i < cells.size(); ++i) {
    if (cells[i] == 0) {
      diagnostics.error(grid.range, "the grid gives no cells for " + quoted(ir.continuous[i].name) +
                                        " (list every continuous variable)");
      return;
    }
  }
  // The product must stay a count memory could ever hold (and must not overflow 64 bits).
  std::uint64_t total = 1;
  for (const std::int64_t n : cells) {
    total *= static_cast<std::uint64_t>(n);
    if (total > kMaxGridCells) {
      diagnostics.error(grid.range, "the grid has more than 10^10 cells");
      return;
    }
  }
  ir.grid_cells.assign(cells.begin(), cells.end());
  ir.grid_range = grid.range;
}

// Dynamics the catalog path cannot abstract: not affine, or reading an input.
void refuse_nonlinear_catalog(const model::ModelIR& ir, DiagnosticEngine& diagnostics) {
  for (const model::ContextIR& context : ir.contexts) {
    for (std::size_t a = 0; a < context.maps.size(); ++a) {
      if (!context.maps[a] || context.dynamics[a]) continue;
      diagnostics.error(context.maps[a]->range,
                        "the dynamics of action " + quoted(ir.actions[a]) +
                            " are not affine (or read an input): a catalog abstracts affine "
                            "dynamics only; state an 'objective' to abstract them with "
                            "guarantees (docs/guarantees.md)");
      return;
    }
  }
}

// Settings of the catalog path that mean nothing on the objective's grid.
void refuse_catalog_settings(const ast::SpecFile& spec, const ast::MdpDecl& mdp,
                             DiagnosticEngine& diagnostics) {
  if (!spec.catalogs.empty()) {
    diagnostics.error(mdp.objective->range,
                      "an objective with guarantees is solved on the model alone: a spec states "
                      "an 'objective' or a 'catalog', not both");
  }
  for (const auto* setting : {&mdp.epsilon, &mdp.max_cells, &mdp.discount, &mdp.horizon}) {
    if (*setting) {
      diagnostics.error((*setting)->range,
                        "this setting is for catalogs; an objective's abstraction is set by "
                        "'grid' and its horizon by 'steps'");
    }
  }
}

// Boxes evaluated per action and input combination before a refusal is believed: enough to
// split a domain into pieces a thousandth of its width along each axis of a 2-D model.
constexpr std::size_t kDomainCheckBoxes = 4096;

// Every map must be enclosable on the domain (docs/guarantees.md, "Enclosures"): refused at the
// expression that fails, with the box where it does.
void check_enclosable(const model::ModelIR& ir, DiagnosticEngine& diagnostics) {
  std::vector<model::Interval> domain;
  for (const model::ContinuousVariable& variable : ir.continuous) {
    domain.push_back(
        model::hull(model::from_rational(variable.low), model::from_rational(variable.high)));
  }
  std::vector<std::vector<model::Interval>> inputs;
  for (const model::InputVariable& input : ir.inputs) {
    std::vector<model::Interval> values;
    for (const Rational& value : input.values)
      values.push_back(model::from_rational(value));
    inputs.push_back(std::move(values));
  }
  for (const model::ContextIR& context : ir.contexts) {
    for (const auto& map : context.maps) {
      if (!map) continue;
      if (auto error = model::find_domain_error(map->next, domain, inputs, kDomainCheckBoxes)) {
        diagnostics.error(error->where, error->what());
        return;
      }
    }
  }
}

}  // namespace

void declare_inputs(const ast::MdpDecl& mdp, model::ModelIR& ir, Scope& scope,
                    ExpressionChecker& expressions, DiagnosticEngine& diagnostics) {
  std::uint64_t combinations = 1;
  for (const ast::InputDecl& input : mdp.inputs) {
    if (ir.kind != model::ModelKind::Continuous) {
      diagnostics.error(input.range, "inputs belong to models with continuous variables");
      return;
    }
    auto values = input.step ? input_range(input, expressions, diagnostics)
                             : input_list(input, expressions, diagnostics);
    if (!values) continue;
    combinations *= values->size();
    if (combinations > kMaxInputCombinations) {
      diagnostics.error(input.range, "the inputs combine into more than " +
                                         std::to_string(kMaxInputCombinations) +
                                         " values per action: use larger steps");
      return;
    }
    const auto index = static_cast<std::uint32_t>(ir.inputs.size());
    Symbol symbol{SymbolKind::Input, index, Type::Real, 0, input.name.range};
    if (scope.declare(input.name.text, input.name.range, std::move(symbol), "name", diagnostics)) {
      ir.inputs.push_back({std::string(input.name.text), std::move(*values), input.range});
    }
  }
}

void check_guarantee(const ast::SpecFile& spec, const ast::MdpDecl& mdp, model::ModelIR& ir,
                     const Scope& scope, ExpressionChecker& expressions,
                     DiagnosticEngine& diagnostics) {
  if (!mdp.objective) {
    if (mdp.grid) {
      diagnostics.error(mdp.grid->range,
                        "'grid' sets the cells of an objective's abstraction; "
                        "this model states no 'objective'");
    }
    if (ir.kind == model::ModelKind::Continuous) refuse_nonlinear_catalog(ir, diagnostics);
    return;
  }
  if (ir.kind != model::ModelKind::Continuous) {
    diagnostics.error(mdp.objective->range,
                      "objectives with guarantees belong to models with continuous variables "
                      "(a discrete model's questions are PRISM properties: docs/properties.md)");
    return;
  }
  refuse_catalog_settings(spec, mdp, diagnostics);
  if (!mdp.grid) {
    diagnostics.error(mdp.objective->range,
                      "an objective is solved on a grid: add 'grid x : 50, ...;' with the cells "
                      "of every continuous variable");
    return;
  }
  check_objective_item(*mdp.objective, ir, expressions, diagnostics);
  check_grid(*mdp.grid, ir, scope, expressions, diagnostics);
  if (!diagnostics.has_errors()) check_enclosable(ir, diagnostics);
}

}  // namespace oasis::frontend
