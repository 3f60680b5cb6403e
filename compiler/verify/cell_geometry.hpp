#pragma once
// The verifier's own reading of a continuous abstraction's cells (shares no code with
// compiler/geom): each BSP leaf's path of half-spaces from the root, and, in one and two
// dimensions, cells as convex polygons in doubles.

#include <cstdint>
#include <utility>
#include <vector>

#include "oasis/rt/catalog_view.hpp"

namespace oasis::verify {

// a.x <= c over the abstraction's axes, with the side a cell lies on: `below` keeps
// a.x <= c, otherwise a.x > c (the boundary rule).
struct PathStep {
  std::vector<double> normal;
  double bound = 0;
  bool below = true;
};

// Every cell's path from the root, by walking the BSP's arrays.
std::vector<std::vector<PathStep>> cell_paths(const rt::AbstractionView& abs);

double dot(const std::vector<double>& a, const double* x);
// True when `x` (over the abstraction's axes) is on the cell's side of every step.
bool on_path(const std::vector<PathStep>& path, const double* x);

// ---- one and two dimensions: cells as polygons (a 1-D cell is a polygon with y in [0, 1]) --

using Point2 = std::pair<double, double>;

// Sutherland-Hodgman: the part of a convex polygon with ax x + ay y <= c.
std::vector<Point2> clip(const std::vector<Point2>& polygon, double ax, double ay, double c);
double area(const std::vector<Point2>& polygon);
std::vector<Point2> rectangle(double x0, double x1, double y0, double y1);
// The closure of a cell: the domain clipped by its path (strict sides taken as closed).
std::vector<Point2> cell_polygon(const std::vector<Point2>& domain,
                                 const std::vector<PathStep>& path);

}  // namespace oasis::verify
