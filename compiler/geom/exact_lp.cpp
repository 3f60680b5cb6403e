#include "geom/exact_lp.hpp"

#include <CGAL/Gmpz.h>
#include <CGAL/QP_functions.h>
#include <CGAL/QP_models.h>

namespace oasis::geom {
namespace {

using Integer = CGAL::Gmpz;
using Program = CGAL::Quadratic_program<Integer>;

Integer to_cgal(const mpz_class& value) {
  return Integer(value.get_mpz_t());
}

Rational to_rational(const CGAL::Quotient<Integer>& value) {
  Rational result{mpz_class(value.numerator().mpz()), mpz_class(value.denominator().mpz())};
  result.canonicalize();
  return result;
}

// The least common multiple of the denominators: multiplying by it makes every entry an
// integer, which CGAL's solver takes exactly (its ring type is Gmpz).
mpz_class common_denominator(std::span<const Rational> values, const Rational* extra) {
  mpz_class multiple = 1;
  for (const Rational& value : values)
    mpz_lcm(multiple.get_mpz_t(), multiple.get_mpz_t(), value.get_den_mpz_t());
  if (extra) mpz_lcm(multiple.get_mpz_t(), multiple.get_mpz_t(), extra->get_den_mpz_t());
  return multiple;
}

mpz_class scaled(const Rational& value, const mpz_class& multiple) {
  return value.get_num() * (multiple / value.get_den());
}

}  // namespace

LpSolution maximize(std::span<const HalfSpace> constraints, std::span<const Rational> objective) {
  // CGAL minimises; all variables free (no bounds), every row "<=".
  Program program(CGAL::SMALLER, false, 0, false, 0);
  for (std::size_t i = 0; i < constraints.size(); ++i) {
    const HalfSpace& row = constraints[i];
    const mpz_class multiple = common_denominator(row.normal, &row.bound);
    for (std::size_t j = 0; j < row.normal.size(); ++j)
      if (sgn(row.normal[j]) != 0)
        program.set_a(static_cast<int>(j), static_cast<int>(i),
                      to_cgal(scaled(row.normal[j], multiple)));
    program.set_b(static_cast<int>(i), to_cgal(scaled(row.bound, multiple)));
  }
  // Scaling the objective by a positive integer does not move the optimum.
  const mpz_class multiple = common_denominator(objective, nullptr);
  for (std::size_t j = 0; j < objective.size(); ++j)
    program.set_c(static_cast<int>(j), to_cgal(-scaled(objective[j], multiple)));
  // A program without a row still needs its variables declared.
  if (constraints.empty() && !objective.empty())
    program.set_c(static_cast<int>(objective.size() - 1),
                  to_cgal(-scaled(objective.back(), multiple)));

  const CGAL::Quadratic_program_solution<Integer> solution =
      CGAL::solve_linear_program(program, Integer());
  LpSolution result;
  if (solution.is_infeasible()) return result;
  if (solution.is_unbounded()) {
    result.status = LpStatus::Unbounded;
    return result;
  }
  result.status = LpStatus::Optimal;
  result.point.assign(objective.size(), 0);
  std::size_t j = 0;
  for (auto value = solution.variable_values_begin();
       value != solution.variable_values_end() && j < objective.size(); ++value, ++j)
    result.point[j] = to_rational(*value);
  result.value = 0;
  for (std::size_t k = 0; k < objective.size(); ++k)
    result.value += objective[k] * result.point[k];
  return result;
}

}  // namespace oasis::geom
