// The interval MDP of a continuous model with an objective, checked from the other side: its
// rows contain the true successor distributions (recomputed here in long double from the
// spec's numbers), and its robust values and bounds agree with a brute-force evaluation of
// the same interval MDP that enumerates every vertex of every row's set of distributions.

#include <algorithm>
#include <cmath>
#include <functional>
#include <random>
#include <stdexcept>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "../../support/spec_models.hpp"
#include "guarantee/end_components.hpp"
#include "guarantee/interval_mdp.hpp"
#include "guarantee/objective_cells.hpp"
#include "guarantee/robust_value.hpp"
#include "guarantee/row_classes.hpp"
#include "guarantee/synthesis.hpp"

namespace oasis::guarantee {
namespace {

// Two axes, one uniform and one Gaussian disturbance, two actions that mix the axes: rows of a
// handful of entries per axis, small enough to enumerate every vertex.
std::string small_spec(const std::string& objective) {
  return "mdp t {\n"
         "  continuous x : [0 .. 4];\n"
         "  continuous y : [0 .. 4];\n"
         "  actions left, right;\n"
         "  disturbance x in [-0.6 .. 0.6];\n"
         "  disturbance y ~ gaussian(0, 0.3);\n"
         "  dynamics [left] { x' = 0.9 * x + 0.1 * y; y' = y - 0.5; }\n"
         "  dynamics [right] { x' = 0.9 * x + 0.5; y' = 0.8 * y + 0.6; }\n"
         "  region goal = x >= 3 & y >= 3;\n"
         "  region keep = x >= 0 & x <= 4 & y >= 0.5 & y <= 4;\n" +
         objective + "\n  grid x : 4, y : 5;\n}\n";
}

struct Abstraction {
  model::ModelIR ir;
  IntervalMdp mdp;
  ObjectiveCells cells;
};

Abstraction abstraction(const std::string& objective) {
  Abstraction a;
  a.ir = test::check_spec_text_ir(small_spec(objective));
  a.mdp = build_interval_mdp(a.ir, BuildOptions{});
  a.cells = objective_cells(*a.ir.guarantee, a.ir, a.mdp.grid);
  return a;
}

// ---- independent probabilities --------------------------------------------------------------

long double normal_cdf(long double z) {
  return 0.5L * std::erfc(-z / std::sqrt(2.0L));
}

// P(m + w in [low, high]) for the test spec's disturbance on `axis`.
long double exact_mass(std::size_t axis, long double m, long double low, long double high) {
  if (axis == 0) {
    const long double from = std::max(low, m - 0.6L);
    const long double to = std::min(high, m + 0.6L);
    return std::max(0.0L, to - from) / 1.2L;
  }
  return normal_cdf((high - m) / 0.3L) - normal_cdf((low - m) / 0.3L);
}

long double exact_mean(std::size_t action, std::size_t axis, long double x, long double y) {
  if (action == 0) return axis == 0 ? 0.9L * x + 0.1L * y : y - 0.5L;
  return axis == 0 ? 0.9L * x + 0.5L : 0.8L * y + 0.6L;
}

TEST(IntervalRows, ContainTheTrueDistributionOfEveryPointOfTheCell) {
  const Abstraction a = abstraction("objective reach goal steps 3;");
  const UniformGrid& grid = a.mdp.grid;
  std::mt19937_64 random(7);
  std::uniform_real_distribution<double> unit(0, 1);
  for (std::size_t cell = 0; cell < grid.cells; ++cell) {
    for (std::size_t action = 0; action < a.mdp.actions.size(); ++action) {
      const AxisSlice* row = a.mdp.row(cell, action);
      for (int sample = 0; sample < 50; ++sample) {
        std::vector<long double> point(2);
        for (std::size_t i = 0; i < 2; ++i) {
          const std::size_t k = grid.coordinate(cell, i);
          const double u = sample == 0 ? 0 : sample == 1 ? 1 : unit(random);
          point[i] = grid.breaks[i][k] + u * (grid.breaks[i][k + 1] - grid.breaks[i][k]);
        }
        for (std::size_t axis = 0; axis < 2; ++axis) {
          const AxisSlice& slice = row[axis];
          const long double m = exact_mean(action, axis, point[0], point[1]);
          const auto& breaks = grid.breaks[axis];
          long double listed = 0;
          for (std::size_t k = 0; k + 1 < breaks.size(); ++k) {
            const long double p = exact_mass(axis, m, breaks[k], breaks[k + 1]);
            if (k < slice.first || k >= slice.first + slice.count) {
              EXPECT_LE(p, slice.truncated) << "cell " << cell << " axis " << axis << " k " << k;
              continue;
            }
            listed += p;
            EXPECT_GE(p, a.mdp.lower[slice.offset + k - slice.first] - 1e-15L);
            EXPECT_LE(p, a.mdp.upper[slice.offset + k - slice.first] + 1e-15L);
          }
          const long double outside = exact_mass(axis, m, -INFINITY, breaks.front()) +
                                      exact_mass(axis, m, breaks.back(), INFINITY);
          EXPECT_GE(outside, slice.outside_lower - 1e-15L);
          EXPECT_LE(outside, slice.outside_upper + 1e-15L);
          EXPECT_NEAR(static_cast<double>(listed + outside), 1.0, slice.truncated + 1e-12);
        }
      }
    }
  }
}

// ---- brute force ------------------------------------------------------------------------------

// The outcomes of one axis: entries, then outside and truncated.
struct Outcome {
  double lower;
  double upper;
};

std::vector<Outcome> outcomes(const IntervalMdp& mdp, const AxisSlice& slice) {
  std::vector<Outcome> list;
  for (std::uint32_t k = 0; k < slice.count; ++k)
    list.push_back({mdp.lower[slice.offset + k], mdp.upper[slice.offset + k]});
  list.push_back({slice.outside_lower, slice.outside_upper});
  list.push_back({0, slice.truncated});
  return list;
}

// The extreme of sum p_k v_k over the vertices of {lower <= p <= upper, sum p = 1}: every
// vertex has all coordinates but one at a bound, so trying each free coordinate with each
// choice of bounds for the others finds them all.
double vertex_extreme(const std::vector<Outcome>& list, const std::vector<double>& values,
                      bool maximise) {
  const std::size_t n = list.size();
  double best = maximise ? -1 : 2;
  for (std::size_t free = 0; free < n; ++free) {
    for (std::uint64_t mask = 0; mask < (std::uint64_t{1} << (n - 1)); ++mask) {
      double mass = 0;
      double value = 0;
      std::size_t bit = 0;
      for (std::size_t k = 0; k < n; ++k) {
        if (k == free) continue;
        const double p = (mask >> bit++) & 1 ? list[k].upper : list[k].lower;
        mass += p;
        value += p * values[k];
      }
      const double rest = 1 - mass;
      if (rest < list[free].lower - 1e-12 || rest > list[free].upper + 1e-12) continue;
      value += rest * values[free];
      best = maximise ? std::max(best, value) : std::min(best, value);
    }
  }
  return best;
}

// The nested robust expectation, the outer axis enumerating its vertices over the inner axis's
// own extremes.
double brute_robust(const IntervalMdp& mdp, const AxisSlice* row, const std::vector<double>& v,
                    const RobustGame& game) {
  const UniformGrid& grid = mdp.grid;
  std::vector<double> outer_values;
  for (std::uint32_t j = 0; j < row[0].count; ++j) {
    const std::size_t base = (row[0].first + j) * grid.strides[0];
    std::vector<double> inner_values;
    for (std::uint32_t k = 0; k < row[1].count; ++k)
      inner_values.push_back(v[base + row[1].first + k]);
    inner_values.push_back(game.outside_value);
    inner_values.push_back(game.truncated_value);
    outer_values.push_back(vertex_extreme(outcomes(mdp, row[1]), inner_values, game.maximise));
  }
  outer_values.push_back(game.outside_value);
  outer_values.push_back(game.truncated_value);
  return vertex_extreme(outcomes(mdp, row[0]), outer_values, game.maximise);
}

TEST(RobustValue, MatchesVertexEnumeration) {
  const Abstraction a = abstraction("objective reach goal steps 3;");
  std::mt19937_64 random(11);
  std::uniform_real_distribution<double> unit(0, 1);
  RobustScratch scratch;
  for (int trial = 0; trial < 20; ++trial) {
    std::vector<double> values(a.mdp.grid.cells);
    for (double& v : values)
      v = trial == 0 ? 0.5 : unit(random);
    const ValueTable table(a.mdp.grid, values);
    for (const RobustGame game :
         {RobustGame{false, 0, 0}, RobustGame{true, 1, 1}, RobustGame{true, 0, 1}}) {
      for (std::size_t cell = 0; cell < a.mdp.grid.cells; ++cell) {
        for (std::size_t action = 0; action < a.mdp.actions.size(); ++action) {
          const AxisSlice* row = a.mdp.row(cell, action);
          const double fast = robust_value(a.mdp, row, table, game, scratch);
          const double brute = brute_robust(a.mdp, row, values, game);
          EXPECT_NEAR(fast, brute, 1e-12) << "cell " << cell << " action " << action;
        }
      }
    }
  }
}

TEST(RobustValue, TheChosenDistributionHasTheRobustValue) {
  const Abstraction a = abstraction("objective reach goal steps 3;");
  std::mt19937_64 random(5);
  std::uniform_real_distribution<double> unit(0, 1);
  RobustScratch scratch;
  ChosenRow chosen;
  for (int trial = 0; trial < 10; ++trial) {
    std::vector<double> values(a.mdp.grid.cells);
    for (double& v : values)
      v = unit(random);
    const ValueTable table(a.mdp.grid, values);
    for (const RobustGame game : {RobustGame{false, 0, 0}, RobustGame{true, 1, 1}}) {
      for (std::size_t cell = 0; cell < a.mdp.grid.cells; ++cell) {
        for (std::size_t action = 0; action < a.mdp.actions.size(); ++action) {
          const AxisSlice* row = a.mdp.row(cell, action);
          robust_choice(a.mdp, row, table, game, scratch, chosen);
          double expectation = chosen.constant;
          double mass = 0;
          for (std::size_t k = 0; k < chosen.cells.size(); ++k) {
            expectation += chosen.probabilities[k] * values[chosen.cells[k]];
            mass += chosen.probabilities[k];
          }
          EXPECT_NEAR(expectation, robust_value(a.mdp, row, table, game, scratch), 1e-12)
              << "cell " << cell << " action " << action;
          EXPECT_LE(mass, 1 + 1e-12);
        }
      }
    }
  }
}

// Backward induction or value iteration with the brute-force robust values.
struct BruteBounds {
  std::vector<double> lower;
  std::vector<double> upper;
};

BruteBounds brute_bounds(const Abstraction& a, std::uint64_t steps, bool reach, bool at_step) {
  const std::size_t cells = a.mdp.grid.cells;
  const auto target = [&](std::size_t c, bool up) {
    return (up ? a.cells.target_upper : a.cells.target_lower)[c] != 0;
  };
  const auto safe = [&](std::size_t c, bool up) {
    return (up ? a.cells.safe_upper : a.cells.safe_lower)[c] != 0;
  };
  BruteBounds out;
  for (const bool up : {false, true}) {
    const RobustGame game =
        up ? RobustGame{true, a.cells.outside_may_succeed ? 1.0 : 0.0, 1} : RobustGame{false, 0, 0};
    std::vector<double> v(cells);
    for (std::size_t c = 0; c < cells; ++c)
      v[c] = reach ? (target(c, up) ? 1 : 0) : (safe(c, up) ? 1 : 0);
    for (std::uint64_t k = 1; k <= steps; ++k) {
      std::vector<double> next(cells);
      for (std::size_t c = 0; c < cells; ++c) {
        if (reach && !at_step && target(c, up)) {
          next[c] = 1;
        } else if (!safe(c, up)) {
          next[c] = 0;
        } else {
          double best = 0;
          for (std::size_t action = 0; action < a.mdp.actions.size(); ++action)
            best = std::max(best, brute_robust(a.mdp, a.mdp.row(c, action), v, game));
          next[c] = best;
        }
      }
      v = next;
    }
    (up ? out.upper : out.lower) = v;
  }
  return out;
}

void expect_bounded_agree(const std::string& objective, std::uint64_t steps, bool reach,
                          bool at_step) {
  const Abstraction a = abstraction(objective);
  const Synthesis s = synthesise(a.mdp, *a.ir.guarantee, a.cells, SynthesisOptions{});
  const BruteBounds brute = brute_bounds(a, steps, reach, at_step);
  ASSERT_EQ(s.controller.size(), steps);
  for (std::size_t c = 0; c < a.mdp.grid.cells; ++c) {
    EXPECT_NEAR(s.lower[c], brute.lower[c], 1e-11) << objective << " cell " << c;
    EXPECT_NEAR(s.upper[c], brute.upper[c], 1e-11) << objective << " cell " << c;
    EXPECT_LE(0, s.lower[c]);
    EXPECT_LE(s.lower[c], s.upper[c]);
    EXPECT_LE(s.upper[c], 1);
  }
}

TEST(Synthesis, BoundedObjectivesMatchBruteForce) {
  expect_bounded_agree("objective reach goal while keep steps 4;", 4, true, false);
  expect_bounded_agree("objective reach goal while keep at 3;", 3, true, true);
  expect_bounded_agree("objective safety keep steps 5;", 5, false, false);
}

TEST(Synthesis, UnboundedBoundsEncloseTheBruteForceFixedPoints) {
  const Abstraction a = abstraction("objective reach goal while keep;");
  const Synthesis s = synthesise(a.mdp, *a.ir.guarantee, a.cells, SynthesisOptions{});
  ASSERT_EQ(s.controller.size(), 1u);
  // Long horizons from below (lower) and from above (upper) of the brute-force iteration.
  const BruteBounds below = brute_bounds(a, 300, true, false);
  for (std::size_t c = 0; c < a.mdp.grid.cells; ++c) {
    EXPECT_LE(0, s.lower[c]);
    EXPECT_LE(s.lower[c], s.upper[c]);
    EXPECT_LE(s.upper[c], 1);
    // The controller's bound cannot beat the optimum of the interval MDP, and comes close.
    EXPECT_LE(s.lower[c], below.lower[c] + 1e-9) << "cell " << c;
    EXPECT_GE(s.lower[c], below.lower[c] - 1e-6) << "cell " << c;
    // The 300-step upper value is a lower estimate of the unbounded one: the bound is above.
    EXPECT_GE(s.upper[c], below.upper[c] - 1e-9) << "cell " << c;
  }
}

// The value of a fixed controller on the interval MDP, from below: `steps` steps of the
// brute-force robust minimum under it, from the terminal indicator.
std::vector<double> brute_controller_value(const Abstraction& a,
                                           const std::vector<std::uint32_t>& policy,
                                           std::uint64_t steps) {
  const std::size_t cells = a.mdp.grid.cells;
  std::vector<double> v(cells);
  for (std::size_t c = 0; c < cells; ++c)
    v[c] = a.cells.target_lower[c] != 0 ? 1 : 0;
  for (std::uint64_t k = 0; k < steps; ++k) {
    std::vector<double> next(cells);
    for (std::size_t c = 0; c < cells; ++c) {
      if (a.cells.target_lower[c] != 0) {
        next[c] = 1;
      } else if (a.cells.safe_lower[c] == 0) {
        next[c] = 0;
      } else {
        next[c] = brute_robust(a.mdp, a.mdp.row(c, policy[c]), v, RobustGame{false, 0, 0});
      }
    }
    v = next;
  }
  return v;
}

// Both ways of guessing the unbounded bounds: policy iteration, or the sweeps alone.
SynthesisOptions unbounded_options(bool policy_iteration) {
  SynthesisOptions options;
  options.policy_iteration = policy_iteration;
  return options;
}

TEST(Synthesis, TheUnboundedLowerBoundIsWhatTheControllerAttains) {
  const Abstraction a = abstraction("objective reach goal while keep;");
  for (const bool policy_iteration : {true, false}) {
    const Synthesis s =
        synthesise(a.mdp, *a.ir.guarantee, a.cells, unbounded_options(policy_iteration));
    // The certificate, not an evaluation, gave the bound: that is the path checked here.
    EXPECT_EQ(s.lower_method, "certified: the controller has no trap");
    EXPECT_EQ(s.evaluation_sweeps, 0u);
    EXPECT_EQ(s.policy_rounds > 0, policy_iteration);
    // 600 steps leave nothing measurable of this small model's unbounded value.
    const std::vector<double> attained = brute_controller_value(a, s.controller[0], 600);
    for (std::size_t c = 0; c < a.mdp.grid.cells; ++c) {
      EXPECT_LE(s.lower[c], attained[c] + 1e-12) << "cell " << c;
      EXPECT_GE(s.lower[c], attained[c] - 1e-6) << "cell " << c;
    }
  }
}

TEST(Synthesis, TheUnboundedUpperBoundIsVerifiedAndTight) {
  const Abstraction a = abstraction("objective reach goal while keep;");
  // The upper game's least fixed point, from below, long enough to have converged.
  const BruteBounds below = brute_bounds(a, 600, true, false);
  for (const bool policy_iteration : {true, false}) {
    const Synthesis s =
        synthesise(a.mdp, *a.ir.guarantee, a.cells, unbounded_options(policy_iteration));
    EXPECT_EQ(s.upper_method, policy_iteration ? "policy iteration, verified and proven tight"
                                               : "a guess from below, verified");
    for (std::size_t c = 0; c < a.mdp.grid.cells; ++c) {
      EXPECT_GE(s.upper[c], below.upper[c] - 1e-12) << "cell " << c;
      EXPECT_LE(s.upper[c], below.upper[c] + 2e-6) << "cell " << c;
    }
  }
}

// A map that moves half a cell to the right, without noise: each row may stay in its cell,
// so the disturbance can hold the state short of the goal forever.
std::string stalling_spec() {
  return "mdp t {\n"
         "  continuous x : [0 .. 4];\n"
         "  continuous y : [0 .. 2];\n"
         "  actions go;\n"
         "  dynamics [go] { x' = x + 0.5; y' = y; }\n"
         "  region goal = x >= 3;\n"
         "  objective reach goal;\n"
         "  grid x : 4, y : 2;\n"
         "}\n";
}

TEST(EndComponents, AStallingMapIsATrapAndANoisyOneIsNot) {
  Abstraction stalling;
  stalling.ir = test::check_spec_text_ir(stalling_spec());
  stalling.mdp = build_interval_mdp(stalling.ir, BuildOptions{});
  std::vector<std::uint8_t> undecided(stalling.mdp.grid.cells);
  for (std::size_t c = 0; c < undecided.size(); ++c)
    undecided[c] = c / 2 < 3 ? 1 : 0;  // x cells 0, 1, 2 (y varies fastest); 3 is the goal
  const std::vector<std::uint32_t> go(undecided.size(), 0);
  EXPECT_EQ(greatest_trap(stalling.mdp, undecided, go), undecided);

  // The test model's Gaussian axis puts mass outside the box from every cell: no trap.
  const Abstraction noisy = abstraction("objective reach goal while keep;");
  const std::vector<std::uint8_t> all(noisy.mdp.grid.cells, 1);
  for (const std::uint32_t action : {0u, 1u}) {
    const std::vector<std::uint32_t> policy(all.size(), action);
    const std::vector<std::uint8_t> trap = greatest_trap(noisy.mdp, all, policy);
    EXPECT_TRUE(std::none_of(trap.begin(), trap.end(), [](std::uint8_t t) { return t != 0; }));
  }
}

TEST(Synthesis, AControllerWithATrapIsEvaluatedFromZero) {
  Abstraction a;
  a.ir = test::check_spec_text_ir(stalling_spec());
  a.mdp = build_interval_mdp(a.ir, BuildOptions{});
  a.cells = objective_cells(*a.ir.guarantee, a.ir, a.mdp.grid);
  const Synthesis s = synthesise(a.mdp, *a.ir.guarantee, a.cells, SynthesisOptions{});
  EXPECT_EQ(s.lower_method, "the controller evaluated from 0 (it has a trap)");
  for (std::size_t c = 0; c < a.mdp.grid.cells; ++c) {
    const bool goal = c / 2 == 3;
    // The disturbance can stall every run short of the goal; a kind one walks it there.
    EXPECT_EQ(s.lower[c], goal ? 1 : 0) << "cell " << c;
    EXPECT_EQ(s.upper[c], 1) << "cell " << c;
  }
}

TEST(Synthesis, NonlinearMapsGiveOrderedBoundsAndTargetsAreCertain) {
  const model::ModelIR ir = test::check_spec_text_ir(
      "mdp vdp {\n"
      "  continuous x1 : [-3 .. 3];\n"
      "  continuous x2 : [-3 .. 3];\n"
      "  input u in {-1, 0, 1};\n"
      "  actions push;\n"
      "  disturbance x1 ~ gaussian(0, 0.45);\n"
      "  disturbance x2 ~ gaussian(0, 0.45);\n"
      "  dynamics [push] { x1' = x1 + 0.1 * x2; x2' = x2 + 0.1 * ((1 - x1^2) * x2 - x1) + u; }\n"
      "  region target = x1 >= -1 & x1 <= 0 & x2 >= -2 & x2 <= -1;\n"
      "  objective reach target;\n"
      "  grid x1 : 6, x2 : 6;\n"
      "}\n");
  const IntervalMdp mdp = build_interval_mdp(ir, BuildOptions{});
  ASSERT_EQ(mdp.actions.size(), 3u);
  const ObjectiveCells cells = objective_cells(*ir.guarantee, ir, mdp.grid);
  const Synthesis s = synthesise(mdp, *ir.guarantee, cells, SynthesisOptions{});
  std::size_t targets = 0;
  for (std::size_t c = 0; c < mdp.grid.cells; ++c) {
    EXPECT_LE(0, s.lower[c]);
    EXPECT_LE(s.lower[c], s.upper[c]);
    EXPECT_LE(s.upper[c], 1);
    if (cells.target_lower[c]) {
      ++targets;
      EXPECT_EQ(s.lower[c], 1);
    }
  }
  EXPECT_EQ(targets, 1u);  // [-1, 0] x [-2, -1] is exactly one cell of the 1-wide grid
}

TEST(RowClasses, CellsAMapCannotTellApartHaveEqualRows) {
  // The test model's maps read both coordinates: every row differs.
  const Abstraction mixed = abstraction("objective reach goal steps 3;");
  EXPECT_EQ(distinct_rows(mixed.mdp), mixed.mdp.grid.cells);
  // Here the successor depends on y alone: the 4 cells of each y row share their rows.
  const model::ModelIR ir = test::check_spec_text_ir(
      "mdp t {\n"
      "  continuous x : [0 .. 4];\n"
      "  continuous y : [0 .. 4];\n"
      "  actions go;\n"
      "  disturbance x ~ gaussian(0, 0.3);\n"
      "  disturbance y ~ gaussian(0, 0.3);\n"
      "  dynamics [go] { x' = 0.5 * y + 1; y' = 0.5 * y + 1; }\n"
      "  region goal = x >= 3;\n"
      "  objective reach goal steps 2;\n"
      "  grid x : 4, y : 5;\n"
      "}\n");
  EXPECT_EQ(distinct_rows(build_interval_mdp(ir, BuildOptions{})), 5u);
}

TEST(IntervalMdp, ABudgetTooSmallForTheRowsIsRefusedBeforeBuilding) {
  const model::ModelIR ir = test::check_spec_text_ir(small_spec("objective reach goal steps 3;"));
  BuildOptions options;
  options.memory_budget = 1024;  // bytes: a handful of rows
  EXPECT_THROW(build_interval_mdp(ir, options), std::length_error);
  options.memory_budget = 1 << 30;
  EXPECT_NO_THROW(build_interval_mdp(ir, options));
}

}  // namespace
}  // namespace oasis::guarantee
