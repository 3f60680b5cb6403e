#include "verify/cell_geometry.hpp"

#include <cmath>

namespace oasis::verify {

std::vector<std::vector<PathStep>> cell_paths(const rt::AbstractionView& abs) {
  const rt::BspView& bsp = abs.bsp;
  const std::uint32_t d = abs.grid.dimension;
  std::vector<std::vector<PathStep>> paths(bsp.num_cells);
  std::vector<std::pair<std::uint32_t, std::vector<PathStep>>> stack{{0, {}}};
  while (!stack.empty()) {
    auto [node, path] = std::move(stack.back());
    stack.pop_back();
    if (bsp.cell[node] != rt::kInternalNode) {
      paths[bsp.cell[node]] = std::move(path);
      continue;
    }
    PathStep step{std::vector<double>(bsp.normal + std::size_t{node} * d,
                                      bsp.normal + std::size_t{node} * d + d),
                  bsp.bound[node], true};
    std::vector<PathStep> above = path;
    above.push_back(step);
    above.back().below = false;
    path.push_back(std::move(step));
    stack.emplace_back(bsp.below[node], std::move(path));
    stack.emplace_back(bsp.above[node], std::move(above));
  }
  return paths;
}

double dot(const std::vector<double>& a, const double* x) {
  double sum = 0;
  for (std::size_t i = 0; i < a.size(); ++i)
    sum += a[i] * x[i];
  return sum;
}

bool on_path(const std::vector<PathStep>& path, const double* x) {
  for (const PathStep& step : path)
    if ((dot(step.normal, x) <= step.bound) != step.below) return false;
  return true;
}

std::vector<Point2> clip(const std::vector<Point2>& polygon, double ax, double ay, double c) {
  std::vector<Point2> out;
  for (std::size_t k = 0; k < polygon.size(); ++k) {
    const Point2& p = polygon[k];
    const Point2& q = polygon[(k + 1) % polygon.size()];
    const double fp = ax * p.first + ay * p.second - c;
    const double fq = ax * q.first + ay * q.second - c;
    if (fp <= 0) out.push_back(p);
    if ((fp < 0 && fq > 0) || (fp > 0 && fq < 0)) {
      const double t = fp / (fp - fq);
      out.emplace_back(p.first + t * (q.first - p.first), p.second + t * (q.second - p.second));
    }
  }
  return out;
}

double area(const std::vector<Point2>& polygon) {
  double twice = 0;
  for (std::size_t k = 0; k < polygon.size(); ++k) {
    const Point2& p = polygon[k];
    const Point2& q = polygon[(k + 1) % polygon.size()];
    twice += p.first * q.second - q.first * p.second;
  }
  return std::fabs(twice) / 2;
}

std::vector<Point2> rectangle(double x0, double x1, double y0, double y1) {
  return {{x0, y0}, {x1, y0}, {x1, y1}, {x0, y1}};
}

std::vector<Point2> cell_polygon(const std::vector<Point2>& domain,
                                 const std::vector<PathStep>& path) {
  std::vector<Point2> polygon = domain;
  for (const PathStep& step : path) {
    const double sign = step.below ? 1 : -1;
    const double ay = step.normal.size() > 1 ? step.normal[1] : 0;
    polygon = clip(polygon, sign * step.normal[0], sign * ay, sign * step.bound);
    if (polygon.empty()) break;
  }
  return polygon;
}

}  // namespace oasis::verify
