#include "verify/stated_cells_check.hpp"

#include <algorithm>
#include <cmath>
#include <optional>
#include <random>
#include <string>

#include "support/text.hpp"
#include "verify/cell_geometry.hpp"
#include "verify/number_text.hpp"

namespace oasis::verify {
namespace {

using Problem = std::optional<std::string>;

// normal . x <= bound over the abstraction's axes.
struct Face {
  std::vector<double> normal;
  double bound = 0;
};

double largest_magnitude(const std::vector<double>& values) {
  double largest = 0;
  for (const double v : values)
    largest = std::max(largest, std::fabs(v));
  return largest;
}

bool close(double a, double b) {
  return std::fabs(a - b) <= 1e-9 * std::max({1.0, std::fabs(a), std::fabs(b)});
}

// True when row . x <= bound is the face times a positive factor (up to the doubles' rounding).
bool same_constraint(const std::vector<double>& row, double bound, const Face& face) {
  const double row_size = largest_magnitude(row);
  const double face_size = largest_magnitude(face.normal);
  if (row_size == 0 || face_size == 0) return false;
  const double factor = row_size / face_size;
  for (std::size_t i = 0; i < row.size(); ++i) {
    if (std::fabs(row[i] - factor * face.normal[i]) > 1e-9 * row_size) return false;
  }
  return close(bound, factor * face.bound);
}

std::string cell_name(std::size_t k) {
  return "cell " + std::to_string(k);
}

std::string constraint_text(const StatedCell& cell, std::size_t r) {
  std::string text = "[";
  for (std::size_t i = 0; i < cell.rows[r].size(); ++i)
    text += (i ? ", " : "") + number_text(cell.rows[r][i]);
  return text + "] . x <= " + number_text(cell.bounds[r]);
}

Problem check_shape(const StatedCell& cell, std::size_t d, std::size_t k) {
  if (cell.rows.empty()) return cell_name(k) + " states no constraint";
  if (cell.rows.size() != cell.bounds.size())
    return cell_name(k) + " states " + std::to_string(cell.rows.size()) + " rows of A and " +
           std::to_string(cell.bounds.size()) + " entries of b";
  for (std::size_t r = 0; r < cell.rows.size(); ++r) {
    if (cell.rows[r].size() != d)
      return cell_name(k) + ": row " + std::to_string(r) + " of A has " +
             std::to_string(cell.rows[r].size()) + " coefficients for " + std::to_string(d) +
             " variables";
    if (!std::isfinite(cell.bounds[r]) || !std::all_of(cell.rows[r].begin(), cell.rows[r].end(),
                                                       [](double a) { return std::isfinite(a); }))
      return cell_name(k) + ": row " + std::to_string(r) + " is not finite";
    if (largest_magnitude(cell.rows[r]) == 0)
      return cell_name(k) + ": row " + std::to_string(r) + " of A has every coefficient 0";
  }
  return std::nullopt;
}

// Every stated row is one of `faces`; with `all_faces`, every face is also stated.
Problem check_faces(const StatedCell& cell, const std::vector<Face>& faces, bool all_faces,
                    std::size_t k) {
  std::vector<bool> stated(faces.size(), false);
  for (std::size_t r = 0; r < cell.rows.size(); ++r) {
    bool found = false;
    for (std::size_t f = 0; f < faces.size(); ++f) {
      if (!same_constraint(cell.rows[r], cell.bounds[r], faces[f])) continue;
      stated[f] = true;
      found = true;
    }
    if (!found)
      return cell_name(k) + " states " + constraint_text(cell, r) +
             ", which is none of the cell's own faces";
  }
  if (all_faces) {
    for (std::size_t f = 0; f < faces.size(); ++f)
      if (!stated[f]) return cell_name(k) + " does not state a face of its box";
  }
  return std::nullopt;
}

std::vector<Face> domain_faces(const model::ModelIR& ir, const rt::GridView& grid) {
  std::vector<Face> faces;
  const std::uint32_t d = grid.dimension;
  for (std::uint32_t i = 0; i < d; ++i) {
    const auto& variable = ir.continuous[grid.axes[i]];
    std::vector<double> unit(d, 0.0);
    unit[i] = 1;
    faces.push_back({unit, to_double(variable.high)});
    unit[i] = -1;
    faces.push_back({unit, -to_double(variable.low)});
  }
  return faces;
}

// The faces of grid cell k (row-major, as rt::locate_cell numbers them).
std::vector<Face> box_faces(const rt::GridView& grid, std::uint64_t k) {
  const std::uint32_t d = grid.dimension;
  std::vector<Face> faces(2 * std::size_t{d});
  for (std::uint32_t i = d; i-- > 0;) {
    const double* breaks = grid.breaks + grid.break_begin[i];
    const std::uint32_t intervals = grid.break_begin[i + 1] - grid.break_begin[i] - 1;
    const auto index = static_cast<std::uint32_t>(k % intervals);
    k /= intervals;
    std::vector<double> unit(d, 0.0);
    unit[i] = 1;
    faces[2 * i] = {unit, breaks[index + 1]};
    unit[i] = -1;
    faces[2 * i + 1] = {unit, -breaks[index]};
  }
  return faces;
}

std::vector<Face> path_faces(const std::vector<Face>& domain, const std::vector<PathStep>& path) {
  std::vector<Face> faces = domain;
  for (const PathStep& step : path) {
    Face face{step.normal, step.bound};
    if (!step.below) {
      for (double& a : face.normal)
        a = -a;
      face.bound = -face.bound;
    }
    faces.push_back(std::move(face));
  }
  return faces;
}

Problem check_grid(const rt::AbstractionView& abs, const std::vector<StatedCell>& cells) {
  for (std::size_t k = 0; k < cells.size(); ++k) {
    if (auto problem = check_shape(cells[k], abs.grid.dimension, k)) return problem;
    if (auto problem = check_faces(cells[k], box_faces(abs.grid, k), true, k)) return problem;
  }
  return std::nullopt;
}

std::vector<Point2> domain_polygon(const model::ModelIR& ir, const rt::GridView& grid) {
  const auto& x = ir.continuous[grid.axes[0]];
  const bool two_d = grid.dimension == 2;
  return rectangle(to_double(x.low), to_double(x.high),
                   two_d ? to_double(ir.continuous[grid.axes[1]].low) : 0,
                   two_d ? to_double(ir.continuous[grid.axes[1]].high) : 1);
}

// One and two dimensions: the stated polygon, clipped to the domain, has the cell's area.
Problem compare_areas(const std::vector<Point2>& domain, const std::vector<PathStep>& path,
                      const StatedCell& cell, std::size_t k) {
  std::vector<Point2> stated = domain;
  for (std::size_t r = 0; r < cell.rows.size() && !stated.empty(); ++r)
    stated = clip(stated, cell.rows[r][0], cell.rows[r].size() > 1 ? cell.rows[r][1] : 0,
                  cell.bounds[r]);
  const double own = area(cell_polygon(domain, path));
  const double claimed = area(stated);
  if (std::fabs(own - claimed) > 1e-9 * area(domain))
    return cell_name(k) + "'s stated polytope covers " + number_text(claimed) +
           " of the domain, the cell " + number_text(own);
  return std::nullopt;
}

bool inside(const StatedCell& cell, const double* x, double slack) {
  for (std::size_t r = 0; r < cell.rows.size(); ++r) {
    const double scale = std::max(1.0, std::fabs(cell.bounds[r]));
    if (dot(cell.rows[r], x) > cell.bounds[r] + slack * scale) return false;
  }
  return true;
}

// More dimensions: at random points of the domain, the point's own stated cell holds it
// and no other stated cell holds it strictly inside.
Problem sample_overlaps(const model::ModelIR& ir, const rt::AbstractionView& abs,
                        const std::vector<std::vector<PathStep>>& paths,
                        const std::vector<StatedCell>& cells, std::size_t& points) {
  std::size_t work = 1;
  for (std::size_t k = 0; k < cells.size(); ++k)
    work += cells[k].rows.size() + paths[k].size();
  points = std::clamp<std::size_t>(20'000'000 / work, 200, 20'000);
  std::mt19937_64 random(11);
  const std::uint32_t d = abs.grid.dimension;
  std::vector<double> x(d);
  for (std::size_t p = 0; p < points; ++p) {
    for (std::uint32_t i = 0; i < d; ++i) {
      const auto& variable = ir.continuous[abs.grid.axes[i]];
      x[i] = std::uniform_real_distribution<double>(to_double(variable.low),
                                                    to_double(variable.high))(random);
    }
    std::size_t own = cells.size();
    for (std::size_t k = 0; k < cells.size() && own == cells.size(); ++k)
      if (on_path(paths[k], x.data())) own = k;
    if (own == cells.size()) continue;  // on no path: the BSP check reports it
    if (!inside(cells[own], x.data(), 1e-9))
      return "a point of " + cell_name(own) + " lies outside its stated polytope";
    for (std::size_t k = 0; k < cells.size(); ++k) {
      if (k != own && inside(cells[k], x.data(), -1e-9))
        return cell_name(k) + "'s stated polytope overlaps " + cell_name(own);
    }
  }
  return std::nullopt;
}

CatalogCheck check_abstraction(const model::ModelIR& ir, const rt::AbstractionView& abs,
                               const std::vector<StatedCell>& cells) {
  CatalogCheck check{"cells of context " + quoted(abs.context) + " as the JSON states them", "",
                     false};
  const std::uint64_t expected = rt::partition_cells(abs);
  Problem problem;
  std::string summary;
  if (cells.size() != expected) {
    problem = "the JSON states " + std::to_string(cells.size()) + " cells, the partition has " +
              std::to_string(expected);
  } else if (abs.bsp.num_nodes == 0) {
    problem = check_grid(abs, cells);
    summary = "each of the " + std::to_string(cells.size()) +
              " grid cells states exactly the faces of its box";
  } else {
    const auto paths = cell_paths(abs);
    const auto domain = domain_faces(ir, abs.grid);
    for (std::size_t k = 0; k < cells.size() && !problem; ++k) {
      problem = check_shape(cells[k], abs.grid.dimension, k);
      if (!problem) problem = check_faces(cells[k], path_faces(domain, paths[k]), false, k);
    }
    summary = "each of the " + std::to_string(cells.size()) +
              " cells states only its own faces (of its BSP path and the domain)";
    if (!problem && abs.grid.dimension <= 2) {
      const auto polygon = domain_polygon(ir, abs.grid);
      for (std::size_t k = 0; k < cells.size() && !problem; ++k)
        problem = compare_areas(polygon, paths[k], cells[k], k);
      summary += " and covers exactly the cell's area";
    } else if (!problem) {
      std::size_t points = 0;
      problem = sample_overlaps(ir, abs, paths, cells, points);
      summary += "; no overlap at " + std::to_string(points) + " random points";
    }
  }
  check.ok = !problem.has_value();
  check.verdict = problem ? "FAILED: " + *problem : summary;
  return check;
}

}  // namespace

std::vector<CatalogCheck> check_stated_cells(const model::ModelIR& ir,
                                             const rt::CatalogView& catalog,
                                             const std::vector<std::vector<StatedCell>>& stated) {
  std::vector<CatalogCheck> checks;
  if (stated.size() != catalog.num_abstractions) {
    checks.push_back({"cells as the JSON states them",
                      "FAILED: cells stated for " + std::to_string(stated.size()) +
                          " abstractions, the catalog has " +
                          std::to_string(catalog.num_abstractions),
                      false});
    return checks;
  }
  for (std::uint32_t a = 0; a < catalog.num_abstractions; ++a)
    checks.push_back(check_abstraction(ir, catalog.abstractions[a], stated[a]));
  return checks;
}

}  // namespace oasis::verify
