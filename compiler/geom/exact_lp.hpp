#pragma once
// Exact linear programs over rationals, solved by CGAL's exact simplex (QP_solver). This is
// the only place the compiler includes CGAL: everything else passes rationals in and gets
// rationals out.

#include <span>
#include <vector>

#include "geom/half_space.hpp"

namespace oasis::geom {

enum class LpStatus { Optimal, Infeasible, Unbounded };

struct LpSolution {
  LpStatus status = LpStatus::Infeasible;
  Point point;     // an optimal point (Optimal only)
  Rational value;  // objective · point (Optimal only)
};

// maximise objective · x subject to every constraint, x free in R^n (n = objective.size()).
// Exact: the optimum is the true rational optimum, not a rounded one.
LpSolution maximize(std::span<const HalfSpace> constraints, std::span<const Rational> objective);

}  // namespace oasis::geom
