// The pieces of verify's Monte-Carlo check of a controller file, each against hand values:
// the double evaluator on every operation of dynamics (and its refusals), the noise source
// (its transforms, determinism and streams), the grid locator's boundary rule, and how a run
// ends for each kind of objective (deterministic maps, so every end is known exactly).

#include "verify/controller_simulation.hpp"

#include <cmath>
#include <limits>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "../../support/spec_models.hpp"
#include "verify/map_evaluation.hpp"

namespace oasis {
namespace {

using model::Expression;
using model::Op;
using verify::DoubleProgram;

Expression constant(const Rational& value) {
  return Expression::make_constant(value, model::Type::Real, {});
}

Expression leaf(Op op, std::uint32_t slot) {
  Expression e;
  e.op = op;
  e.type = model::Type::Real;
  e.slot = slot;
  return e;
}

Expression x(std::uint32_t slot) {
  return leaf(Op::ContinuousVariable, slot);
}
Expression u(std::uint32_t slot) {
  return leaf(Op::InputVariable, slot);
}

Expression node(Op op, std::vector<Expression> operands) {
  Expression e;
  e.op = op;
  e.type = model::Type::Real;
  e.operands = std::move(operands);
  return e;
}

// At x = (0.5, -2), u = (3).
double at_point(const Expression& e) {
  const std::vector<double> state = {0.5, -2};
  const std::vector<double> inputs = {3};
  return DoubleProgram::compile(e, 2, 1).evaluate(state, inputs);
}

TEST(MapEvaluation, EveryOperationOfDynamics) {
  EXPECT_EQ(at_point(constant(Rational(1, 3))), 1.0 / 3.0);  // nearest double
  EXPECT_EQ(at_point(constant(Rational(-7, 9))), -7.0 / 9.0);
  EXPECT_EQ(at_point(x(0)), 0.5);
  EXPECT_EQ(at_point(x(1)), -2);
  EXPECT_EQ(at_point(u(0)), 3);
  EXPECT_EQ(at_point(node(Op::Negate, {x(1)})), 2);
  EXPECT_EQ(at_point(node(Op::Add, {x(0), x(1)})), -1.5);
  EXPECT_EQ(at_point(node(Op::Add, {x(0), x(1), u(0)})), 1.5);
  EXPECT_EQ(at_point(node(Op::Subtract, {x(0), x(1)})), 2.5);
  EXPECT_EQ(at_point(node(Op::Multiply, {x(1), u(0)})), -6);
  EXPECT_EQ(at_point(node(Op::Divide, {x(0), x(1)})), -0.25);
  EXPECT_EQ(at_point(node(Op::Divide, {constant(1), u(0)})), 1.0 / 3.0);
  EXPECT_EQ(at_point(node(Op::Power, {x(1), constant(3)})), -8);
  EXPECT_EQ(at_point(node(Op::Power, {x(1), constant(-2)})), 0.25);
  EXPECT_EQ(at_point(node(Op::Power, {x(0), constant(0)})), 1);
  EXPECT_EQ(at_point(node(Op::Min, {x(0), x(1), u(0)})), -2);
  EXPECT_EQ(at_point(node(Op::Max, {x(0), x(1), u(0)})), 3);
  EXPECT_EQ(at_point(node(Op::Abs, {x(1)})), 2);
  // The functions, against their values to 16 digits.
  const double tolerance = 4e-16;
  EXPECT_NEAR(at_point(node(Op::Sin, {x(0)})), 0.479425538604203, tolerance);
  EXPECT_NEAR(at_point(node(Op::Cos, {x(0)})), 0.8775825618903728, tolerance);
  EXPECT_NEAR(at_point(node(Op::Tan, {x(0)})), 0.5463024898437905, tolerance);
  EXPECT_NEAR(at_point(node(Op::Atan, {x(1)})), -1.1071487177940904, 2 * tolerance);
  EXPECT_NEAR(at_point(node(Op::Exp, {x(0)})), 1.6487212707001282, 2 * tolerance);
  EXPECT_NEAR(at_point(node(Op::Log, {u(0)})), 1.0986122886681098, 2 * tolerance);
  EXPECT_NEAR(at_point(node(Op::Sqrt, {u(0)})), 1.7320508075688772, 2 * tolerance);
}

TEST(MapEvaluation, NestedExpressionsFromASpec) {
  // The Van der Pol map, through the front end: x2' at (0.5, -2) with u = 3 is
  // -2 + 0.1 * ((1 - 0.25) * -2 - 0.5) + 3 = 0.8.
  const model::ModelIR ir = test::check_spec_text_ir(R"(
    mdp vdp {
      continuous x1 : [-5 .. 5];
      continuous x2 : [-5 .. 5];
      input u in {-1, 3};
      actions push;
      dynamics [push] {
        x1' = x1 + 0.1 * x2;
        x2' = x2 + 0.1 * ((1 - x1^2) * x2 - x1) + u;
      }
      region target = x1 >= 0;
      objective reach target steps 3;
      grid x1 : 4, x2 : 4;
    })");
  ASSERT_EQ(ir.contexts.size(), 1U);
  const model::MapDynamics& map = *ir.contexts[0].maps[0];
  const std::vector<double> state = {0.5, -2};
  const std::vector<double> inputs = {3};
  EXPECT_NEAR(DoubleProgram::compile(map.next[0], 2, 1).evaluate(state, inputs), 0.3, 1e-15);
  EXPECT_NEAR(DoubleProgram::compile(map.next[1], 2, 1).evaluate(state, inputs), 0.8, 1e-15);
}

TEST(MapEvaluation, IntegerPowerMultipliesOut) {
  EXPECT_EQ(verify::integer_power(1.1, 2), 1.1 * 1.1);
  EXPECT_EQ(verify::integer_power(-3, 5), -243);
  EXPECT_EQ(verify::integer_power(2, -3), 0.125);
  EXPECT_EQ(verify::integer_power(2, std::numeric_limits<std::int64_t>::min()), 0);
}

TEST(MapEvaluation, RefusesWhatDynamicsNeverHold) {
  const auto refused = [](const Expression& e) {
    try {
      (void)DoubleProgram::compile(e, 2, 1);
    } catch (const std::invalid_argument& error) {
      return std::string(error.what());
    }
    return std::string("accepted");
  };
  EXPECT_NE(refused(node(Op::Less, {x(0), x(1)})).find("dynamics do not hold"), std::string::npos);
  EXPECT_NE(refused(node(Op::Power, {x(0), x(1)})).find("not an integer constant"),
            std::string::npos);
  EXPECT_NE(refused(node(Op::Power, {x(0), constant(Rational(1, 2))})).find("integer constant"),
            std::string::npos);
  EXPECT_NE(refused(x(2)).find("out of range"), std::string::npos);
  EXPECT_NE(refused(u(1)).find("out of range"), std::string::npos);
  EXPECT_NE(refused(node(Op::Subtract, {x(0)})).find("1 operands"), std::string::npos);
}

TEST(NoiseSource, TransformsAreDeterministicAndRoughlyRight) {
  verify::NoiseSource a(7, 3);
  verify::NoiseSource b(7, 3);
  verify::NoiseSource other(7, 4);
  bool streams_differ = false;
  double sum = 0;
  double squares = 0;
  constexpr int kDraws = 200000;
  for (int i = 0; i < kDraws; ++i) {
    const double z = a.standard_normal();
    EXPECT_EQ(z, b.standard_normal());
    streams_differ = streams_differ || z != other.standard_normal();
    sum += z;
    squares += z * z;
  }
  EXPECT_TRUE(streams_differ);
  // Mean 0 and variance 1 within 10 standard errors (about 0.022 and 0.032).
  EXPECT_NEAR(sum / kDraws, 0, 0.03);
  EXPECT_NEAR(squares / kDraws, 1, 0.04);
  double uniform_sum = 0;
  for (int i = 0; i < kDraws; ++i) {
    const double v = a.uniform();
    ASSERT_GE(v, 0);
    ASSERT_LT(v, 1);
    uniform_sum += v;
  }
  EXPECT_NEAR(uniform_sum / kDraws, 0.5, 0.01);
  for (int i = 0; i < 1000; ++i)
    ASSERT_LT(a.below(3), 3U);
  const verify::AxisDisturbance bounded{model::DisturbanceModel::Kind::Bounded, -0.25, 0.5};
  for (int i = 0; i < 1000; ++i) {
    const double w = verify::sample(bounded, a);
    ASSERT_GE(w, -0.25);
    ASSERT_LE(w, 0.5);
  }
  EXPECT_EQ(verify::sample({}, a), 0);
}

TEST(GridLocator, IntervalsAreHalfOpenButTheLast) {
  const verify::GridLocator grid({{0, 1, 2}, {0, 0.5, 1}});
  using Point = std::vector<double>;
  EXPECT_EQ(grid.cells(), 4U);
  EXPECT_EQ(grid.cell_of(Point{0, 0}), 0U);
  EXPECT_EQ(grid.cell_of(Point{0.99, 0.5}), 1U);  // the last axis varies fastest
  EXPECT_EQ(grid.cell_of(Point{1, 0.49}), 2U);
  EXPECT_EQ(grid.cell_of(Point{2, 1}), 3U);  // the last interval is closed
  EXPECT_EQ(grid.cell_of(Point{2.0000001, 1}), std::nullopt);
  EXPECT_EQ(grid.cell_of(Point{-1e-300, 0}), std::nullopt);
  EXPECT_EQ(grid.cell_of(Point{std::nan(""), 0}), std::nullopt);
  verify::NoiseSource noise(1, 1);
  for (std::size_t cell = 0; cell < 4; ++cell)
    for (int i = 0; i < 100; ++i)
      ASSERT_EQ(grid.cell_of(grid.random_point(cell, noise)), cell);
}

// x' = x + 1 without noise on [0, 4] (4 cells), from x = 0.5; one action.
verify::RunEnd run_end(const std::string& objective, std::uint64_t max_steps = 100,
                       const std::string& map = "x + 1") {
  const model::ModelIR ir = test::check_spec_text_ir(
      "mdp line { continuous x : [0 .. 4]; actions go; dynamics [go] { x' = " + map +
      "; } region low = x <= 2.8; region mid = x <= 1.8; region wide = x <= 10; region high = x >= "
      "3; "
      "region far = x >= 5; " +
      objective + " grid x : 4; }");
  const verify::SimulatedSystem system = verify::simulated_system(ir);
  const verify::GridLocator grid({{0, 1, 2, 3, 4}});
  const verify::ControllerRows rows(system.steps.value_or(1), std::vector<std::uint64_t>(4, 0));
  verify::NoiseSource noise(1, 0);
  const std::vector<double> start = {0.5};
  return verify::simulate_run(system, grid, rows, start, max_steps, noise);
}

TEST(ControllerSimulation, HowARunEnds) {
  using verify::RunEnd;
  // x_k = 0.5 + k.
  EXPECT_EQ(run_end("objective safety low steps 2;"), RunEnd::Success);   // 2.5 <= 2.8
  EXPECT_EQ(run_end("objective safety low steps 3;"), RunEnd::Failure);   // 3.5
  EXPECT_EQ(run_end("objective safety wide steps 3;"), RunEnd::Success);  // in the box
  EXPECT_EQ(run_end("objective safety wide steps 4;"), RunEnd::LeftBox);  // 4.5: in S, no cell
  EXPECT_EQ(run_end("objective reach high;"), RunEnd::Success);           // x_3 = 3.5
  EXPECT_EQ(run_end("objective reach high steps 3;"), RunEnd::Success);
  EXPECT_EQ(run_end("objective reach high steps 2;"), RunEnd::Failure);
  EXPECT_EQ(run_end("objective reach high while low;"), RunEnd::Success);  // S before T
  EXPECT_EQ(run_end("objective reach high while mid;"), RunEnd::Failure);  // 2.5 leaves S
  EXPECT_EQ(run_end("objective reach high at 3;"), RunEnd::Success);
  EXPECT_EQ(run_end("objective reach high at 2;"), RunEnd::Failure);
  // Leaving the box: the domain left (S unstated), or S still holding (pessimistic).
  EXPECT_EQ(run_end("objective reach far;"), RunEnd::Failure);  // 4.5
  EXPECT_EQ(run_end("objective reach far while wide;"), RunEnd::LeftBox);
  // T reached outside the box (x_2 = 5.5): reached all the same.
  EXPECT_EQ(run_end("objective reach far;", 100, "x + 2.5"), RunEnd::Success);
  // Standing still, never reaching: undecided at the cap.
  EXPECT_EQ(run_end("objective reach high;", 50, "x"), RunEnd::Unfinished);
  EXPECT_EQ(run_end("objective reach high steps 50;", 10, "x"), RunEnd::Failure);
}

}  // namespace
}  // namespace oasis
