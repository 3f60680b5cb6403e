#pragma once
// A closed half-space {x : normal · x <= bound} in exact rationals: the one constraint shape
// of the polytope path (polytopes, BSP splits, linear programs).

#include <cstddef>
#include <vector>

#include "support/rational.hpp"

namespace oasis::geom {

using Point = std::vector<Rational>;

struct HalfSpace {
  std::vector<Rational> normal;
  Rational bound;

  friend bool operator==(const HalfSpace&, const HalfSpace&) = default;
};

// normal · point.
Rational dot(const std::vector<Rational>& normal, const Point& point);

// The same half-space scaled by a positive factor so that its first non-zero coefficient is
// +1 or -1: equal half-spaces then compare equal. A zero normal is left as it is.
HalfSpace normalized(const HalfSpace& half_space);

// The closure of the complement, {x : normal · x >= bound}, as a half-space.
HalfSpace opposite(const HalfSpace& half_space);

// True when the normal is zero (the constraint is a constant: always or never true).
bool is_constant(const HalfSpace& half_space);

}  // namespace oasis::geom
