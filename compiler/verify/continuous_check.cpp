#include "verify/continuous_check.hpp"

#include <algorithm>
#include <cmath>
#include <optional>
#include <random>

#include "oasis/rt/grid_locator.hpp"
#include "support/text.hpp"
#include "verify/guard_reading.hpp"
#include "verify/number_text.hpp"
#include "verify/policy_check.hpp"
#include "verify/polytope_cells_check.hpp"
#include "verify/row_distance.hpp"

namespace oasis::verify {
namespace {

using Problem = std::optional<std::string>;

// The relevant variables, by the rule of docs/geometry.md, computed here from the spec.
std::vector<std::uint32_t> relevant_variables(const model::ModelIR& ir, std::size_t context) {
  const std::size_t n = ir.continuous.size();
  std::vector<bool> relevant(n, false);
  for (const model::Reward& reward : ir.contexts[context].rewards) {
    const auto constraints = guard_constraints(reward.guard, n, ir.regions);
    for (const model::LinearConstraint& constraint :
         constraints.value_or(std::vector<model::LinearConstraint>{}))
      for (std::size_t v = 0; v < n; ++v)
        if (sgn(constraint.coefficients[v]) != 0) relevant[v] = true;
  }
  for (bool grew = true; grew;) {
    grew = false;
    for (const auto& dynamics : ir.contexts[context].dynamics) {
      for (std::size_t i = 0; dynamics && i < n; ++i) {
        if (!relevant[i]) continue;
        for (std::size_t j = 0; j < n; ++j) {
          if (!relevant[j] && sgn(dynamics->matrix[i][j]) != 0) relevant[j] = grew = true;
        }
      }
    }
  }
  std::vector<std::uint32_t> out;
  for (std::uint32_t v = 0; v < n; ++v)
    if (relevant[v]) out.push_back(v);
  return out;
}

struct Box {
  std::vector<double> low, high;  // per grid axis
};

Box cell_box(const rt::GridView& grid, std::uint64_t cell) {
  Box box;
  std::vector<std::uint32_t> index(grid.dimension);
  for (std::uint32_t i = grid.dimension; i-- > 0;) {
    const std::uint32_t intervals = grid.break_begin[i + 1] - grid.break_begin[i] - 1;
    index[i] = static_cast<std::uint32_t>(cell % intervals);
    cell /= intervals;
  }
  for (std::uint32_t i = 0; i < grid.dimension; ++i) {
    const double* t = grid.breaks + grid.break_begin[i];
    box.low.push_back(t[index[i]]);
    box.high.push_back(t[index[i] + 1]);
  }
  return box;
}

// 1 when the whole box satisfies the reward's condition, 0 when none of it does, nullopt
// when the condition cuts through it.
std::optional<bool> condition_on(const model::ModelIR& ir, const model::Reward& reward,
                                 const rt::GridView& grid, const Box& box) {
  const auto constraints = guard_constraints(reward.guard, ir.continuous.size(), ir.regions);
  if (!constraints) return std::nullopt;
  bool all = true;
  for (const model::LinearConstraint& constraint : *constraints) {
    double low = 0;
    double high = 0;
    for (std::uint32_t i = 0; i < grid.dimension; ++i) {
      const double c = to_double(constraint.coefficients[grid.axes[i]]);
      low += std::min(c * box.low[i], c * box.high[i]);
      high += std::max(c * box.low[i], c * box.high[i]);
    }
    const double bound = to_double(constraint.bound);
    const double slack = 1e-9 * std::max(1.0, std::fabs(bound));
    // min c.x >= b: at most a face of the box (measure zero) satisfies it.
    if (low > bound - slack) return false;
    if (high > bound + slack) all = false;  // some point does not
  }
  if (all) return true;
  return std::nullopt;
}

Problem check_rewards(const model::ModelIR& ir, std::size_t context, const rt::AbstractionView& abs,
                      std::uint64_t cells) {
  for (std::uint64_t cell = 0; cell < cells; ++cell) {
    const Box box = cell_box(abs.grid, cell);
    double total = 0;
    for (const model::Reward& reward : ir.contexts[context].rewards) {
      const std::optional<bool> holds = condition_on(ir, reward, abs.grid, box);
      if (!holds) return "a reward condition cuts through cell " + std::to_string(cell);
      if (*holds) total += to_double(reward.value.constant);
    }
    const double carried = abs.block_reward[abs.cell_block[cell]];
    if (std::fabs(carried - total) > 1e-12 * std::max(1.0, std::fabs(total)))
      return "cell " + std::to_string(cell) + " has reward " + number_text(total) +
             " but its block " + std::to_string(abs.cell_block[cell]) + " says " +
             number_text(carried);
  }
  if (abs.block_reward[abs.outside_block] != 0) return "the outside block's reward is not 0";
  return std::nullopt;
}

Problem check_domain(const model::ModelIR& ir, const rt::AbstractionView& abs) {
  for (std::uint32_t i = 0; i < abs.grid.dimension; ++i) {
    const model::ContinuousVariable& v = ir.continuous[abs.grid.axes[i]];
    const double* t = abs.grid.breaks + abs.grid.break_begin[i];
    const std::uint32_t last = abs.grid.break_begin[i + 1] - abs.grid.break_begin[i] - 1;
    if (t[0] != to_double(v.low) || t[last] != to_double(v.high))
      return "the grid of " + v.name + " spans [" + number_text(t[0]) + ", " +
             number_text(t[last]) + "], its domain is [" + number_text(to_double(v.low)) + ", " +
             number_text(to_double(v.high)) + "]";
  }
  return std::nullopt;
}

// Plain membership, for the locator's check: the boundary rule written out.
std::uint32_t member_cell(const rt::GridView& grid, const std::vector<double>& point) {
  std::uint64_t cell = 0;
  for (std::uint32_t i = 0; i < grid.dimension; ++i) {
    const double* t = grid.breaks + grid.break_begin[i];
    const std::uint32_t count = grid.break_begin[i + 1] - grid.break_begin[i];
    const double x = point[grid.axes[i]];
    std::uint32_t k = count;
    for (std::uint32_t j = 0; j + 1 < count; ++j)
      if (t[j] <= x && (x < t[j + 1] || j + 2 == count)) k = j;
    if (!(x >= t[0] && x <= t[count - 1]) || k == count) return rt::kOutsideCell;
    cell = cell * (count - 1) + k;
  }
  return static_cast<std::uint32_t>(cell);
}

Problem check_locator(const model::ModelIR& ir, const rt::AbstractionView& abs) {
  std::mt19937_64 random(1);
  std::vector<double> point(ir.continuous.size());
  for (int k = 0; k < 20000; ++k) {
    for (std::size_t v = 0; v < point.size(); ++v) {
      const double low = to_double(ir.continuous[v].low);
      const double high = to_double(ir.continuous[v].high);
      const double margin = 0.05 * (high - low);
      point[v] = std::uniform_real_distribution<double>(low - margin, high + margin)(random);
    }
    if (k % 4 == 0) {  // exactly on a breakpoint
      const std::uint32_t i = static_cast<std::uint32_t>(random() % abs.grid.dimension);
      const std::uint32_t count = abs.grid.break_begin[i + 1] - abs.grid.break_begin[i];
      point[abs.grid.axes[i]] = abs.grid.breaks[abs.grid.break_begin[i] + random() % count];
    }
    if (rt::locate_cell(abs.grid, point.data(), point.size()) != member_cell(abs.grid, point))
      return "the locator and plain membership disagree at a point";
  }
  return std::nullopt;
}

// The standard normal distribution function, written here apart from compiler/geom's.
double normal_cdf(double z) {
  return 0.5 * std::erfc(-z / std::sqrt(2.0));
}

// P(low <= Z < high) for a standard normal Z, taken on the side of 0 where the values are
// small, so that a far tail keeps its digits.
double normal_between(double low, double high) {
  if (low > 0) return normal_cdf(-low) - normal_cdf(-high);
  return normal_cdf(high) - normal_cdf(low);
}

// The probability of each interval of one grid axis for a successor coordinate `image` + w.
std::vector<double> axis_probabilities(const model::DisturbanceModel& w, double image,
                                       const double* t, std::uint32_t count) {
  using Kind = model::DisturbanceModel::Kind;
  const bool spread = w.kind == Kind::Bounded && w.first < w.second;
  const double low = image + (w.kind == Kind::Bounded ? to_double(w.first) : 0);
  const double high = spread ? image + to_double(w.second) : low;
  std::vector<double> p;
  for (std::uint32_t k = 0; k + 1 < count; ++k) {
    if (w.kind == Kind::Gaussian) {
      const double mean = image + to_double(w.first);
      const double deviation = to_double(w.second);
      p.push_back(normal_between((t[k] - mean) / deviation, (t[k + 1] - mean) / deviation));
    } else if (spread) {
      p.push_back(std::max(0.0, std::min(high, t[k + 1]) - std::max(low, t[k])) / (high - low));
    } else {  // a point: intervals are half-open, the last closed at the domain's edge
      const bool last = k + 2 == count;
      p.push_back(t[k] <= low && (low < t[k + 1] || (last && low == t[k + 1])) ? 1.0 : 0.0);
    }
  }
  return p;
}

// The successor distribution over cells (and outside, the last entry) from `x` under action
// a, from the spec's dynamics on the grid's axes: per axis uniform on an interval, Gaussian
// (in doubles, to about 1e-15) or a point; axes independent.
std::vector<double> successor_cells(const model::ModelIR& ir, std::size_t context,
                                    std::size_t action, const rt::GridView& grid,
                                    const std::vector<double>& x, std::uint64_t cells) {
  const model::AffineDynamics& dynamics = *ir.contexts[context].dynamics[action];
  std::vector<std::vector<double>> axis(grid.dimension);
  for (std::uint32_t i = 0; i < grid.dimension; ++i) {
    const std::uint32_t v = grid.axes[i];
    double image = to_double(dynamics.offset[v]);
    for (std::uint32_t j = 0; j < grid.dimension; ++j)
      image += to_double(dynamics.matrix[v][grid.axes[j]]) * x[j];
    axis[i] = axis_probabilities(dynamics.disturbance[v], image, grid.breaks + grid.break_begin[i],
                                 grid.break_begin[i + 1] - grid.break_begin[i]);
  }
  std::vector<double> p(cells + 1, 0);
  double inside = 0;
  for (std::uint64_t cell = 0; cell < cells; ++cell) {
    std::uint64_t rest = cell;
    double mass = 1;
    for (std::uint32_t i = grid.dimension; i-- > 0 && mass > 0;) {
      const std::uint64_t n = axis[i].size();
      mass *= axis[i][rest % n];
      rest /= n;
    }
    p[cell] = mass;
    inside += mass;
  }
  p[cells] = std::max(0.0, 1 - inside);
  return p;
}

Problem check_rows(const model::ModelIR& ir, std::size_t context, const rt::AbstractionView& abs,
                   std::uint64_t cells, std::uint32_t actions) {
  const std::uint64_t stride = std::max<std::uint64_t>(1, cells / 24);
  for (std::uint64_t cell = 0; cell < cells; cell += stride) {
    const Box box = cell_box(abs.grid, cell);
    const std::uint32_t block = abs.cell_block[cell];
    const std::uint32_t d = abs.grid.dimension;
    // The centre, and points a hair inside the corners: a corner itself lies on faces of
    // other cells, and under dynamics without a disturbance its image is a single point that
    // may sit on a face the rest of the cell's image only touches (a set of measure zero,
    // docs/geometry.md), as polytope_cells_check.cpp does for polygons.
    for (std::uint32_t corner = 0; corner <= (1U << d); ++corner) {
      std::vector<double> x(d);
      for (std::uint32_t i = 0; i < d; ++i) {
        const double centre = (box.low[i] + box.high[i]) / 2;
        const double end = ((corner >> i) & 1U) != 0 ? box.high[i] : box.low[i];
        x[i] = corner == (1U << d) ? centre : end + 1e-7 * (centre - end);
      }
      for (std::uint32_t a = 0; a < actions; ++a) {
        const std::vector<double> p = successor_cells(ir, context, a, abs.grid, x, cells);
        std::vector<double> by_block(abs.num_blocks, 0);
        for (std::uint64_t c = 0; c < cells; ++c)
          by_block[abs.cell_block[c]] += p[c];
        by_block[abs.outside_block] += p[cells];
        const std::size_t row = std::size_t{block} * actions + a;
        for (auto e = abs.quotient.choice_begin[row]; e < abs.quotient.choice_begin[row + 1]; ++e)
          by_block[abs.quotient.target[e]] -= abs.quotient.probability[e];
        const double variation = total_variation(by_block);
        if (variation > abs.epsilon + 1e-9)
          return row_too_far(cell, ir.actions[a], variation, abs.epsilon);
      }
    }
  }
  return std::nullopt;
}

Problem check_policy(const model::ModelIR& ir, const rt::AbstractionView& abs,
                     std::uint32_t actions, std::string& summary) {
  NumericQuotient quotient;
  quotient.blocks = abs.num_blocks;
  quotient.actions = actions;
  for (std::uint32_t z = 0; z < abs.num_blocks; ++z) {
    quotient.state_reward.push_back(abs.block_reward[z]);
    for (std::uint32_t a = 0; a < actions; ++a) {
      const std::size_t row = std::size_t{z} * actions + a;
      std::vector<std::pair<std::uint32_t, double>> to;
      for (auto e = abs.quotient.choice_begin[row]; e < abs.quotient.choice_begin[row + 1]; ++e)
        to.emplace_back(abs.quotient.target[e], abs.quotient.probability[e]);
      quotient.enabled.push_back(to.empty() ? 0 : 1);
      quotient.to.push_back(std::move(to));
      quotient.reward.push_back(abs.block_reward[z]);  // continuous rewards are state rewards
    }
  }
  return check_policy_and_values(quotient, abs.policy, abs.value, objective_of(ir.objective),
                                 summary);
}

// Polytope cells (a BSP in the catalog): verify/polytope_cells_check.hpp, then the policy.
CatalogCheck check_polytope_abstraction(const model::ModelIR& ir, std::size_t context,
                                        const rt::AbstractionView& abs, std::uint32_t actions,
                                        CatalogCheck check) {
  const bool rows = abs.quotient.choice_begin != nullptr;
  PolytopeCellsVerdict cells = check_polytope_cells(ir, context, abs, actions, rows);
  Problem problem = check_domain(ir, abs);
  if (!problem) problem = cells.problem;
  std::string summary;
  if (!problem && rows) problem = check_policy(ir, abs, actions, summary);
  if (problem) {
    check.verdict = "FAILED: " + *problem;
    return check;
  }
  check.ok = true;
  check.verdict = "attends to its relevant variables; " + cells.summary + "; " +
                  std::to_string(abs.num_blocks) + " blocks" +
                  (rows ? "; policy " + summary + ", values ok"
                        : "; rows and policy not checked: the file has no transition rows "
                          "(compile --with-transitions)");
  return check;
}

CatalogCheck check_abstraction(const model::ModelIR& ir, std::size_t context,
                               const rt::AbstractionView& abs, std::uint32_t actions) {
  CatalogCheck check{"context " + ir.contexts[context].name, "", false};
  const std::vector<std::uint32_t> relevant = relevant_variables(ir, context);
  if (!std::equal(relevant.begin(), relevant.end(), abs.grid.axes,
                  abs.grid.axes + abs.grid.dimension) ||
      relevant.size() != abs.grid.dimension) {
    check.verdict = "FAILED: the grid's variables are not the ones the context attends to";
    return check;
  }
  if (abs.bsp.num_nodes != 0) return check_polytope_abstraction(ir, context, abs, actions, check);
  const std::uint64_t cells = rt::grid_cells(abs.grid);
  Problem problem = check_domain(ir, abs);
  if (!problem) problem = check_rewards(ir, context, abs, cells);
  if (!problem) problem = check_locator(ir, abs);
  const bool rows = abs.quotient.choice_begin != nullptr;
  std::string summary;
  if (!problem && rows) problem = check_rows(ir, context, abs, cells, actions);
  if (!problem && rows) problem = check_policy(ir, abs, actions, summary);
  if (problem) {
    check.verdict = "FAILED: " + *problem;
    return check;
  }
  check.ok = true;
  check.verdict = "attends to its relevant variables; " + std::to_string(cells) + " cells, " +
                  std::to_string(abs.num_blocks) + " blocks; domain, rewards, locator ok" +
                  (rows ? "; rows within epsilon " + number_text(abs.epsilon) +
                              " at sampled cells' centres and next to their vertices; policy " +
                              summary + ", values ok"
                        : "; rows and policy not checked: the file has no transition rows "
                          "(compile --with-transitions)");
  return check;
}

// The catalog's position noise and reward source against the spec's observation block: the
// same objects, each over the same variables with sigma(d)'s coefficients and the detection
// probability the nearest doubles to the spec's numbers.
Problem check_position_noise(const model::ModelIR& ir, const rt::CatalogView& catalog) {
  const model::ObservationSpec& spec = ir.observation;
  const rt::ObservationModel& obs = catalog.observation;
  const rt::RewardSource source = spec.reward_follows_observed ? rt::RewardSource::kObservedState
                                                               : rt::RewardSource::kTrueState;
  if (obs.reward_source != source) return "the reward follows another state than the spec says";
  const rt::PositionNoise& noise = obs.position;
  if (noise.num_objects != spec.objects.size())
    return "the catalog has " + std::to_string(noise.num_objects) + " measured objects, the spec " +
           std::to_string(spec.objects.size());
  for (std::uint32_t k = 0; k < noise.num_objects; ++k) {
    const model::MeasuredObject& object = spec.objects[k];
    const std::string which = "object '" + object.name + "'";
    for (std::uint32_t v = 0; v < catalog.state_dimension; ++v) {
      const bool in_spec =
          std::find(object.variables.begin(), object.variables.end(), v) != object.variables.end();
      if (in_spec != (noise.object_of[v] == k))
        return which + ": variable '" + ir.continuous[v].name + "' " +
               (in_spec ? "is not measured by it in the catalog" : "is not in the spec's object");
    }
    for (std::size_t c = 0; c < 3; ++c)
      if (noise.sigma[3 * k + c] != to_double(object.sigma[c]))
        return which + ": sigma(d) coefficient " + std::to_string(c) + " differs";
    if (noise.detection[k] != to_double(object.detection))
      return which + ": the detection probability differs";
  }
  return std::nullopt;
}

}  // namespace

std::vector<CatalogCheck> check_continuous_catalog(const model::ModelIR& ir,
                                                   const rt::CatalogView& catalog) {
  std::vector<CatalogCheck> checks;
  Problem names;
  if (ir.name != catalog.name) names = "the catalog is named " + quoted(catalog.name);
  if (!names && (catalog.num_actions != ir.actions.size() ||
                 catalog.state_dimension != ir.continuous.size() ||
                 catalog.num_abstractions != ir.contexts.size()))
    names = "the catalog's actions, variables or abstractions do not match the spec's";
  for (std::uint32_t a = 0; !names && a < catalog.num_actions; ++a)
    if (ir.actions[a] != catalog.action_names[a])
      names = "action " + std::to_string(a) + " differs";
  for (std::uint32_t v = 0; !names && catalog.variable_names && v < catalog.state_dimension; ++v)
    if (ir.continuous[v].name != catalog.variable_names[v])
      names = "variable " + std::to_string(v) + " differs";
  for (std::uint32_t i = 0; !names && i < catalog.num_abstractions; ++i)
    if (ir.contexts[i].name != catalog.abstractions[i].context)
      names = "abstraction " + std::to_string(i) + " is for another context";
  checks.push_back({"names", names ? "FAILED: " + *names : "ok", !names});
  if (names) return checks;
  Problem switching;
  const std::size_t n = catalog.num_abstractions;
  for (std::size_t k = 0; !switching && k < n * n; ++k)
    if (std::fabs(catalog.switching[k] - to_double(ir.switching.matrix[k])) > 1e-15)
      switching = "switching[" + std::to_string(k / n) + "][" + std::to_string(k % n) + "] differs";
  for (std::size_t i = 0; !switching && i < n; ++i)
    if (std::fabs(catalog.prior[i] - to_double(ir.switching.prior[i])) > 1e-15)
      switching = "prior[" + std::to_string(i) + "] differs";
  checks.push_back({"switching and prior", switching ? "FAILED: " + *switching : "ok", !switching});
  const Problem observation = check_position_noise(ir, catalog);
  checks.push_back({"observation model",
                    observation ? "FAILED: " + *observation
                    : ir.observation.objects.empty()
                        ? std::string("none")
                        : std::to_string(ir.observation.objects.size()) +
                              " measured objects, sigma(d) and detection as the spec says",
                    !observation});
  for (std::size_t c = 0; c < n; ++c)
    checks.push_back(check_abstraction(ir, c, catalog.abstractions[c], catalog.num_actions));
  return checks;
}

}  // namespace oasis::verify
