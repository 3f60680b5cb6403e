// Dynamics whose coefficients are irrational constants (cos(0.1) * x): the front end rounds them
// to rationals and bounds the error over the domain (model::AffineDynamics::approximation), and
// the grid path's error bound grows by exactly that error times each axis's shift cost.

#include <cmath>
#include <string>

#include <gtest/gtest.h>

#include "../../support/spec_models.hpp"
#include "geom/grid_geometry.hpp"
#include "geom/grid_refinement.hpp"
#include "geom/relevance.hpp"
#include "model/affine.hpp"

namespace oasis {
namespace {

std::string rotation_spec(const std::string& c, const std::string& s) {
  return "mdp m {\n"
         "  continuous x : [0 .. 5];\n"
         "  continuous y : [-3 .. 3];\n"
         "  actions turn;\n"
         "  disturbance x in [-0.3 .. 0.3];\n"
         "  disturbance y in [-0.3 .. 0.3];\n"
         "  dynamics [turn] { x' = " +
         c + " * x + " + s + " * y; y' = -" + s + " * x + " + c +
         " * y; }\n"
         "  region near = x <= 1;\n"
         "  reward near : 1;\n"
         "}\n";
}

TEST(IrrationalCoefficients, AreRoundedWithABoundedError) {
  const model::ModelIR ir = test::check_spec_text_ir(rotation_spec("cos(0.1)", "sin(0.1)"));
  const model::AffineDynamics& step = *ir.contexts.front().dynamics[0];
  ASSERT_EQ(step.approximation.size(), 2u);
  EXPECT_NEAR(step.matrix[0][0].get_d(), std::cos(0.1), 1e-15);
  EXPECT_NEAR(step.matrix[0][1].get_d(), std::sin(0.1), 1e-15);
  EXPECT_NEAR(step.matrix[1][0].get_d(), -std::sin(0.1), 1e-15);
  for (const Rational& error : step.approximation) {
    EXPECT_GT(error, 0);      // cos(0.1) is irrational: the rounding cannot be exact
    EXPECT_LT(error, 1e-13);  // a few ulps of each coefficient times |x| <= 5
  }
  // The bound holds where it matters: the true map against the rounded one, at the corners.
  for (const double x : {0.0, 5.0}) {
    for (const double y : {-3.0, 3.0}) {
      const long double exact = std::cos(0.1L) * x + std::sin(0.1L) * y;
      const long double rounded = step.matrix[0][0].get_d() * static_cast<long double>(x) +
                                  step.matrix[0][1].get_d() * static_cast<long double>(y);
      EXPECT_LE(std::fabs(exact - rounded), step.approximation[0].get_d() + 1e-18L);
    }
  }
}

TEST(IrrationalCoefficients, ExactCoefficientsStayExact) {
  const model::ModelIR ir = test::check_spec_text_ir(rotation_spec("0.995", "0.0998"));
  EXPECT_TRUE(ir.contexts.front().dynamics[0]->approximation.empty());
}

TEST(IrrationalCoefficients, TheGridBoundAddsTheErrorTimesTheShiftCost) {
  const model::ModelIR ir = test::check_spec_text_ir(rotation_spec("cos(0.1)", "sin(0.1)"));
  std::string error;
  auto geometry = geom::grid_geometry(ir, 0, geom::analyse_relevance(ir, 0), error);
  ASSERT_TRUE(geometry) << error;
  geom::AxisDynamics exact = geometry->actions[0];
  exact.approximation.assign(exact.approximation.size(), Rational(0));
  const std::vector<Rational> half = {Rational(1, 10), Rational(1, 10)};
  const Rational with = geom::cell_error(geometry->actions[0], half);
  const Rational without = geom::cell_error(exact, half);
  // Uniform disturbances of width 0.6: a shift of the mean by e costs e / 0.6 per axis.
  const Rational expected =
      (geometry->actions[0].approximation[0] + geometry->actions[0].approximation[1]) /
      Rational(3, 5);
  EXPECT_EQ(with - without, expected);
}

TEST(IrrationalCoefficients, NonlinearMapsAndInputsStillNeedAnObjective) {
  const auto errors = test::spec_errors(rotation_spec("cos(x)", "sin(0.1)"));
  ASSERT_FALSE(errors.empty());
  EXPECT_NE(errors.front().find("are not affine"), std::string::npos) << errors.front();
}

}  // namespace
}  // namespace oasis
