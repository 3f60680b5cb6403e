#include "verify/controller_check.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <stdexcept>
#include <string>
#include <utility>

#include "support/rational.hpp"
#include "support/text.hpp"
#include "verify/controller_simulation.hpp"
#include "verify/number_text.hpp"

namespace oasis::verify {
namespace {

// One structural item. `blocks`: the file's shape disagrees with the spec's, so the
// simulation cannot read it (a differing double alone does not block).
struct Verdict {
  CatalogCheck check;
  bool blocks = false;
};

Verdict holds(const char* item, std::string text) {
  return {{item, std::move(text), true}, false};
}

Verdict fails(const char* item, std::string text, bool blocks) {
  return {{item, std::move(text), false}, blocks};
}

std::string quote(const std::string& name) {
  return "\"" + name + "\"";
}

std::string at(const std::string& path, std::size_t i) {
  return path + "[" + std::to_string(i) + "]";
}

std::string joined(const std::vector<std::string>& names) {
  std::string text;
  for (const std::string& name : names)
    text += (text.empty() ? "" : ", ") + name;
  return text;
}

// "is 0.7777777777777777, not 0.7777777777777778 (the nearest double to 7/9)", or "" when
// `value` is the nearest double to `exact`.
std::string double_difference(double value, const Rational& exact) {
  const double nearest = to_double(exact);
  if (value == nearest) return "";
  return " is " + shortest_double(value) + ", not " + shortest_double(nearest) +
         " (the nearest double to " + to_string(exact) + ")";
}

// ---- the model and the grid ----------------------------------------------------------------

Verdict check_model(const model::ModelIR& ir, const ControllerFile& file) {
  if (file.model != ir.name)
    return fails("model",
                 "the file is of model " + quote(file.model) + ", the spec's is " + quote(ir.name),
                 true);
  std::vector<std::string> names;
  for (const model::ContinuousVariable& variable : ir.continuous)
    names.push_back(variable.name);
  if (file.variables != names)
    return fails(
        "model",
        "variables are (" + joined(file.variables) + "), the spec's (" + joined(names) + ")", true);
  return holds("model", ir.name + ", variables " + joined(names));
}

// The first problem of the grid's shape, or "".
std::string grid_shape_problem(const model::ModelIR& ir, const ControllerFile& file) {
  if (file.grid.size() != ir.continuous.size())
    return "the file has " + std::to_string(file.grid.size()) + " axes, the spec " +
           std::to_string(ir.continuous.size()) + " variables";
  for (std::size_t i = 0; i < file.grid.size(); ++i) {
    const ControllerAxis& axis = file.grid[i];
    const std::string path = at("grid", i);
    if (axis.cells != ir.grid_cells[i])
      return path + ".cells is " + std::to_string(axis.cells) + ", but the spec's grid gives " +
             ir.continuous[i].name + " " + std::to_string(ir.grid_cells[i]) + " cells";
    if (axis.breaks.size() != axis.cells + 1)
      return path + ".breaks has " + std::to_string(axis.breaks.size()) +
             " entries, not cells + 1 = " + std::to_string(axis.cells + 1);
    for (std::size_t k = 1; k < axis.breaks.size(); ++k)
      if (!(axis.breaks[k] > axis.breaks[k - 1]))
        return at(path + ".breaks", k) + " is not above " + at(path + ".breaks", k - 1);
  }
  return "";
}

Verdict check_grid(const model::ModelIR& ir, const ControllerFile& file) {
  if (std::string problem = grid_shape_problem(ir, file); !problem.empty())
    return fails("grid", problem, true);
  std::string first;
  std::size_t differing = 0;
  std::size_t total = 0;
  std::string sizes;
  for (std::size_t i = 0; i < file.grid.size(); ++i) {
    const model::ContinuousVariable& variable = ir.continuous[i];
    const std::vector<double>& breaks = file.grid[i].breaks;
    const Rational cells(static_cast<unsigned long>(ir.grid_cells[i]));
    sizes += (i == 0 ? "" : " x ") + std::to_string(ir.grid_cells[i]);
    for (std::size_t k = 0; k < breaks.size(); ++k, ++total) {
      // low + k (high - low) / cells, exactly, then rounded once.
      const Rational exact = variable.low + Rational(static_cast<unsigned long>(k)) *
                                                (variable.high - variable.low) / cells;
      const std::string difference = double_difference(breaks[k], exact);
      if (difference.empty()) continue;
      if (differing++ == 0) first = at(at("grid", i) + ".breaks", k) + difference;
    }
  }
  if (differing > 0)
    return fails("grid",
                 first + "; " + std::to_string(differing) + " of the " + std::to_string(total) +
                     " breakpoints are not the nearest doubles to the spec's",
                 false);
  return holds("grid", sizes + " cells, every breakpoint the nearest double to the spec's");
}

// ---- inputs and actions ---------------------------------------------------------------------

struct ExpectedAction {
  model::ActionIndex action = 0;
  std::vector<Rational> inputs;
};

// Every declared action with dynamics times every combination of the inputs, the last fastest.
std::vector<ExpectedAction> expected_actions(const model::ModelIR& ir) {
  std::size_t combinations = 1;
  for (const model::InputVariable& input : ir.inputs)
    combinations *= input.values.size();
  std::vector<ExpectedAction> actions;
  const auto& maps = ir.contexts.front().maps;
  for (model::ActionIndex a = 0; a < maps.size(); ++a) {
    if (!maps[a]) continue;
    for (std::size_t c = 0; c < combinations; ++c) {
      ExpectedAction expected{a, std::vector<Rational>(ir.inputs.size())};
      for (std::size_t i = ir.inputs.size(), rest = c; i-- > 0;) {
        expected.inputs[i] = ir.inputs[i].values[rest % ir.inputs[i].values.size()];
        rest /= ir.inputs[i].values.size();
      }
      actions.push_back(std::move(expected));
    }
  }
  return actions;
}

// The first differing value of `values` against `exact` at `path`, or "" (sizes equal).
std::string first_value_difference(const std::vector<double>& values,
                                   const std::vector<Rational>& exact, const std::string& path) {
  for (std::size_t j = 0; j < values.size(); ++j)
    if (std::string difference = double_difference(values[j], exact[j]); !difference.empty())
      return at(path, j) + difference;
  return "";
}

Verdict check_inputs(const model::ModelIR& ir, const ControllerFile& file) {
  if (file.inputs.size() != ir.inputs.size())
    return fails("actions",
                 "the file has " + std::to_string(file.inputs.size()) + " inputs, the spec " +
                     std::to_string(ir.inputs.size()),
                 true);
  for (std::size_t i = 0; i < ir.inputs.size(); ++i) {
    const std::string path = at("inputs", i);
    const ControllerInput& input = file.inputs[i];
    if (input.name != ir.inputs[i].name)
      return fails(
          "actions",
          path + ".name is " + quote(input.name) + ", the spec's " + quote(ir.inputs[i].name),
          true);
    if (input.values.size() != ir.inputs[i].values.size())
      return fails("actions",
                   path + ".values has " + std::to_string(input.values.size()) +
                       " values, the spec's input " + std::to_string(ir.inputs[i].values.size()),
                   true);
    if (std::string d = first_value_difference(input.values, ir.inputs[i].values, path + ".values");
        !d.empty())
      return fails("actions", d, false);
  }
  return holds("actions", "");
}

Verdict check_actions(const model::ModelIR& ir, const ControllerFile& file) {
  if (Verdict inputs = check_inputs(ir, file); !inputs.check.ok) return inputs;
  const std::vector<ExpectedAction> expected = expected_actions(ir);
  if (file.actions.size() != expected.size())
    return fails("actions",
                 "the file has " + std::to_string(file.actions.size()) +
                     " actions; the spec's actions with dynamics and its inputs' values give " +
                     std::to_string(expected.size()),
                 true);
  std::string value_difference;
  for (std::size_t a = 0; a < expected.size(); ++a) {
    const std::string path = at("actions", a);
    const ControllerAction& action = file.actions[a];
    const std::string& name = ir.actions[expected[a].action];
    if (action.action != name)
      return fails("actions",
                   path + ".action is " + quote(action.action) + ", expected " + quote(name) +
                       " (declared actions with dynamics in order, "
                       "each with every combination of the inputs)",
                   true);
    if (action.inputs.size() != expected[a].inputs.size())
      return fails("actions",
                   path + ".inputs has " + std::to_string(action.inputs.size()) +
                       " values, the spec " + std::to_string(expected[a].inputs.size()) + " inputs",
                   true);
    if (value_difference.empty())
      value_difference =
          first_value_difference(action.inputs, expected[a].inputs, path + ".inputs");
  }
  if (!value_difference.empty())
    return fails("actions", value_difference + " (the last input varies fastest)", false);
  return holds("actions", std::to_string(expected.size()) +
                              " actions: each declared action with dynamics with each "
                              "combination of the inputs' values, the last input fastest");
}

// ---- the objective, the bounds, the controller ------------------------------------------------

std::string objective_text(const std::string& kind, const std::optional<std::uint64_t>& steps,
                           bool exactly) {
  if (!steps) return kind + ", unbounded";
  const std::string n = std::to_string(*steps);
  if (exactly) return kind + " at step " + n;
  return kind + (kind == "safety" ? " for " : " within ") + n + " steps";
}

Verdict check_objective(const model::ModelIR& ir, const ControllerFile& file) {
  const model::GuaranteeObjective& objective = *ir.guarantee;
  const std::string kind =
      objective.kind == model::GuaranteeObjective::Kind::Safety ? "safety" : "reach-avoid";
  const std::string expected = objective_text(kind, objective.steps, objective.exactly_at_step);
  const std::string found =
      objective_text(file.objective.kind, file.objective.steps, file.objective.exactly_at_step);
  if (file.objective.kind != kind || file.objective.steps != objective.steps ||
      file.objective.exactly_at_step != objective.exactly_at_step)
    return fails("objective", "the file's is " + found + ", the spec's " + expected, true);
  return holds("objective", expected + ", as the spec states");
}

// The first index where `bad` holds and how many there are.
template <typename Bad>
std::pair<std::size_t, std::size_t> first_and_count(std::size_t n, Bad bad) {
  std::size_t first = n;
  std::size_t count = 0;
  for (std::size_t c = 0; c < n; ++c) {
    if (!bad(c)) continue;
    if (count++ == 0) first = c;
  }
  return {first, count};
}

Verdict check_bounds(const ControllerFile& file, std::size_t cells) {
  for (const auto& [name, values] : {std::pair{"lower", &file.lower}, {"upper", &file.upper}})
    if (values->size() != cells)
      return fails("bounds",
                   std::string(name) + " has " + std::to_string(values->size()) +
                       " entries, the grid " + std::to_string(cells) + " cells",
                   true);
  const std::vector<double>& lower = file.lower;
  const std::vector<double>& upper = file.upper;
  const auto [first, count] = first_and_count(cells, [&](std::size_t c) {
    return !(0 <= lower[c] && lower[c] <= upper[c] && upper[c] <= 1);
  });
  if (count > 0)
    return fails("bounds",
                 "not 0 <= lower <= upper <= 1 at cell " + std::to_string(first) + ": " +
                     at("lower", first) + " = " + number_text(lower[first]) + ", " +
                     at("upper", first) + " = " + number_text(upper[first]) + " (" +
                     std::to_string(count) + (count == 1 ? " cell)" : " cells)"),
                 false);
  return holds("bounds", std::to_string(cells) + " cells, 0 <= lower <= upper <= 1");
}

Verdict check_table(const ControllerFile& file, const model::GuaranteeObjective& objective,
                    std::size_t cells, std::size_t actions) {
  const bool bounded = objective.steps.has_value();
  if (file.per_step != bounded)
    return fails("controller",
                 bounded ? "one array, but the objective is bounded: one array per step expected"
                         : "an array per step, but the objective is unbounded: one array expected",
                 true);
  const std::size_t rows = bounded ? *objective.steps : 1;
  if (file.controller.size() != rows)
    return fails("controller",
                 "has " + std::to_string(file.controller.size()) + " arrays, the objective " +
                     std::to_string(rows) + " steps",
                 true);
  for (std::size_t k = 0; k < rows; ++k) {
    const std::vector<std::uint64_t>& row = file.controller[k];
    const std::string path = bounded ? at("controller", k) : "controller";
    if (row.size() != cells)
      return fails("controller",
                   path + " has " + std::to_string(row.size()) + " entries, the grid " +
                       std::to_string(cells) + " cells",
                   true);
    for (std::size_t c = 0; c < cells; ++c)
      if (row[c] >= actions)
        return fails("controller",
                     at(path, c) + " is " + std::to_string(row[c]) + ", but there are " +
                         std::to_string(actions) + " actions",
                     true);
  }
  return holds("controller",
               "an action index below " + std::to_string(actions) + " per cell" +
                   (bounded ? " for each of the " + std::to_string(rows) + " steps" : ""));
}

// ---- Monte-Carlo ----------------------------------------------------------------------------

std::string short_number(double value) {
  char text[32];
  std::snprintf(text, sizeof text, "%.3g", value);
  return text;
}

std::string point_text(const model::ModelIR& ir, const std::vector<double>& point) {
  std::vector<std::string> names;
  std::vector<std::string> values;
  for (std::size_t i = 0; i < point.size(); ++i) {
    names.push_back(ir.continuous[i].name);
    values.push_back(number_text(point[i]));
  }
  if (point.size() == 1) return names[0] + " = " + values[0];
  return "(" + joined(names) + ") = (" + joined(values) + ")";
}

std::string runs_note(const RunCounts& counts, std::uint64_t max_steps) {
  std::string note;
  if (counts.left_box > 0)
    note += "; " + std::to_string(counts.left_box) +
            " runs left the grid's box while in the safe set, counted as failures";
  if (counts.unfinished > 0)
    note += "; " + std::to_string(counts.unfinished) + " runs undecided after " +
            std::to_string(max_steps) + " steps, counted as failures";
  return note;
}

// The line of a cell whose estimate is outside [lower - t, upper + t], or nullopt.
std::optional<CatalogCheck> cell_verdict(const model::ModelIR& ir, const ControllerFile& file,
                                         std::size_t cell, const std::vector<double>& point,
                                         const RunCounts& counts, double margin,
                                         std::uint64_t max_steps) {
  const double estimate = static_cast<double>(counts.successes) / static_cast<double>(counts.runs);
  const double lower = file.lower[cell];
  const double upper = file.upper[cell];
  const bool below = estimate < lower - margin;
  if (!below && !(estimate > upper + margin)) return std::nullopt;
  return CatalogCheck{
      "cell " + std::to_string(cell),
      "from " + point_text(ir, point) + ": estimated " + number_text(estimate) + " (" +
          std::to_string(counts.successes) + " of " + std::to_string(counts.runs) + " runs), " +
          (below ? "below lower - t" : "above upper + t") + " for [lower, upper] = [" +
          number_text(lower) + ", " + number_text(upper) + "], t = " + short_number(margin) +
          runs_note(counts, max_steps),
      false};
}

std::vector<CatalogCheck> monte_carlo(const model::ModelIR& ir, const ControllerFile& file,
                                      const MonteCarloSettings& settings) {
  SimulatedSystem system;
  try {
    system = simulated_system(ir);
  } catch (const std::invalid_argument& e) {
    return {{"Monte-Carlo", std::string("not run: ") + e.what(), false}};
  }
  std::vector<std::vector<double>> breaks;
  for (const ControllerAxis& axis : file.grid)
    breaks.push_back(axis.breaks);
  const GridLocator grid(std::move(breaks));
  const std::vector<std::size_t> tested =
      cells_to_test(file.lower, file.upper, settings.cells, settings.seed);
  const double margin = hoeffding_margin(tested.size(), settings.samples, settings.confidence);
  std::vector<CatalogCheck> checks;
  RunCounts total;
  for (const std::size_t cell : tested) {
    NoiseSource noise(settings.seed, cell);  // each cell its own stream: order does not matter
    const std::vector<double> point = grid.random_point(cell, noise);
    const RunCounts counts = simulate_runs(system, grid, file.controller, point, settings.samples,
                                           settings.max_steps, noise);
    total.left_box += counts.left_box;
    total.unfinished += counts.unfinished;
    if (auto failing = cell_verdict(ir, file, cell, point, counts, margin, settings.max_steps))
      checks.push_back(std::move(*failing));
  }
  const std::string summary =
      std::to_string(tested.size()) + " cells x " + std::to_string(settings.samples) +
      " runs, margin " + short_number(margin) + " at confidence " +
      shortest_double(settings.confidence) + ": " +
      (checks.empty() ? std::string("all within their bounds")
                      : std::to_string(checks.size()) + " of " + std::to_string(tested.size()) +
                            " cells outside their bounds") +
      runs_note(total, settings.max_steps);
  checks.push_back({"Monte-Carlo", summary, checks.empty()});
  return checks;
}

}  // namespace

double hoeffding_margin(std::uint64_t cells, std::uint64_t samples, double confidence) {
  const double delta = 1 - confidence;
  return std::sqrt(std::log(2 * static_cast<double>(cells) / delta) /
                   (2 * static_cast<double>(samples)));
}

std::vector<std::size_t> cells_to_test(const std::vector<double>& lower,
                                       const std::vector<double>& upper, std::uint64_t count,
                                       std::uint64_t seed) {
  const std::size_t n = lower.size();
  std::vector<std::size_t> chosen;
  if (count >= n) {
    for (std::size_t c = 0; c < n; ++c)
      chosen.push_back(c);
    return chosen;
  }
  // Its own stream, apart from the cells' (streams 0 .. n - 1).
  NoiseSource noise(seed, ~std::uint64_t{0});
  std::vector<bool> taken(n, false);
  // Up to `want` more cells of `pool`, by a partial Fisher-Yates shuffle.
  const auto take = [&](std::vector<std::size_t> pool, std::size_t want) {
    for (std::size_t i = 0, added = 0; i < pool.size() && added < want; ++i) {
      std::swap(pool[i], pool[i + noise.below(pool.size() - i)]);
      if (taken[pool[i]]) continue;
      taken[pool[i]] = true;
      chosen.push_back(pool[i]);
      ++added;
    }
  };
  std::vector<std::size_t> claims_some;  // lower > 0.05: the lower bound says something
  std::vector<std::size_t> rules_out;    // upper < 0.95: the upper bound says something
  std::vector<std::size_t> every(n);
  for (std::size_t c = 0; c < n; ++c) {
    if (lower[c] > 0.05) claims_some.push_back(c);
    if (upper[c] < 0.95) rules_out.push_back(c);
    every[c] = c;
  }
  take(std::move(claims_some), count / 3);
  take(std::move(rules_out), count / 3);
  take(std::move(every), count - chosen.size());
  std::sort(chosen.begin(), chosen.end());
  return chosen;
}

std::vector<CatalogCheck> check_controller(const model::ModelIR& ir, const ControllerFile& file,
                                           const MonteCarloSettings& settings) {
  if (ir.kind != model::ModelKind::Continuous || !ir.guarantee || ir.contexts.empty())
    return {
        {"objective", "the spec states no 'objective', so it has no controller to check", false}};
  std::size_t cells = 1;  // the spec's
  for (const std::uint64_t count : ir.grid_cells)
    cells *= count;
  std::vector<Verdict> verdicts = {
      check_model(ir, file),     check_grid(ir, file),
      check_actions(ir, file),   check_objective(ir, file),
      check_bounds(file, cells), check_table(file, *ir.guarantee, cells, file.actions.size())};
  std::vector<CatalogCheck> checks;
  bool simulable = true;
  for (Verdict& verdict : verdicts) {
    simulable = simulable && !verdict.blocks;
    checks.push_back(std::move(verdict.check));
  }
  if (!simulable) {
    checks.push_back({"Monte-Carlo", "not run: the file's shape does not match the spec", false});
    return checks;
  }
  for (CatalogCheck& check : monte_carlo(ir, file, settings))
    checks.push_back(std::move(check));
  return checks;
}

}  // namespace oasis::verify
