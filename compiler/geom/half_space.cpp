#include "geom/half_space.hpp"

#include <algorithm>

namespace oasis::geom {

Rational dot(const std::vector<Rational>& normal, const Point& point) {
  Rational total = 0;
  for (std::size_t i = 0; i < normal.size(); ++i)
    if (sgn(normal[i]) != 0) total += normal[i] * point[i];
  return total;
}

HalfSpace normalized(const HalfSpace& half_space) {
  const auto first = std::find_if(half_space.normal.begin(), half_space.normal.end(),
                                  [](const Rational& c) { return sgn(c) != 0; });
  if (first == half_space.normal.end()) return half_space;
  const Rational scale = abs(*first);
  HalfSpace result = half_space;
  for (Rational& c : result.normal)
    c /= scale;
  result.bound /= scale;
  return result;
}

HalfSpace opposite(const HalfSpace& half_space) {
  HalfSpace result = half_space;
  for (Rational& c : result.normal)
    c = -c;
  result.bound = -result.bound;
  return result;
}

bool is_constant(const HalfSpace& half_space) {
  return std::all_of(half_space.normal.begin(), half_space.normal.end(),
                     [](const Rational& c) { return sgn(c) == 0; });
}

}  // namespace oasis::geom
