#include "codegen/abstraction_svg.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <sstream>

#include "pipeline/continuous_catalog_data.hpp"
#include "support/text.hpp"

namespace oasis::codegen {
namespace {

constexpr double kPlot = 560;  // pixels along the longer axis
constexpr double kMargin = 60;

// Eight hues that stay apart on screen and in greyscale print.
constexpr const char* kActionHues[] = {"#1f77b4", "#d62728", "#2ca02c", "#9467bd",
                                       "#ff7f0e", "#8c564b", "#e377c2", "#17becf"};

std::string hue_of(std::uint32_t action) {
  return kActionHues[action % (sizeof kActionHues / sizeof *kActionHues)];
}

std::string number(double value) {
  char text[32];
  std::snprintf(text, sizeof text, "%.4g", value);
  return text;
}

// Which cells the picture shows: axes 0 and 1 (or 0 alone); other axes at the interval that
// holds the centre of their domain.
struct Slice {
  std::vector<std::uint32_t> fixed;  // per axis: the interval shown (axes >= 2)
  std::size_t shown_axes = 0;
};

Slice slice_of(const pipeline::CellPartition& grid) {
  Slice slice;
  slice.shown_axes = std::min<std::size_t>(grid.dimension(), 2);
  slice.fixed.assign(grid.dimension(), 0);
  for (std::size_t i = slice.shown_axes; i < grid.dimension(); ++i) {
    const auto& t = grid.breaks[i];
    slice.fixed[i] = *grid.locate(i, (t.front() + t.back()) / 2);
  }
  return slice;
}

struct Frame {
  double x0, x1, y0, y1;  // data bounds of the shown axes
  double scale;           // pixels per unit
  double px(double x) const { return kMargin + (x - x0) * scale; }
  // y grows upwards in the picture, as on a plot.
  double py(double y) const { return kMargin + (y1 - y) * scale; }
};

// The corners of a 2-D convex cell in drawing order: sorted by angle about their mean.
std::vector<std::pair<double, double>> polygon_of(const pipeline::PolytopeCell& cell) {
  std::vector<std::pair<double, double>> corners;
  double cx = 0;
  double cy = 0;
  for (const std::vector<double>& v : cell.corners) {
    corners.emplace_back(v[0], v[1]);
    cx += corners.back().first;
    cy += corners.back().second;
  }
  cx /= static_cast<double>(corners.size());
  cy /= static_cast<double>(corners.size());
  std::sort(corners.begin(), corners.end(), [&](const auto& p, const auto& q) {
    return std::atan2(p.second - cy, p.first - cx) < std::atan2(q.second - cy, q.first - cx);
  });
  return corners;
}

// Polytope cells (the BSP path) in one or two dimensions: each cell filled like a grid cell,
// outlined thin, and thick where it earns a reward (its block's reward is not 0).
void draw_polytope_cells(std::ostringstream& out,
                         const pipeline::ContinuousAbstraction& abstraction, const Frame& frame,
                         bool two_d, double low, double high) {
  for (std::size_t c = 0; c < abstraction.cells.polytopes.size(); ++c) {
    const pipeline::PolytopeCell& cell = abstraction.cells.polytopes[c];
    const std::uint32_t z = abstraction.cell_block[c];
    const double shade = high > low ? (abstraction.value[z] - low) / (high - low) : 1;
    const bool rewarded = abstraction.block_reward[z] != 0;
    out << "<polygon points=\"";
    if (two_d) {
      for (const auto& [x, y] : polygon_of(cell))
        out << number(frame.px(x)) << ',' << number(frame.py(y)) << ' ';
    } else {
      const double a = frame.px(cell.corners.front()[0]);
      const double b = frame.px(cell.corners.back()[0]);
      const double top = frame.py(frame.y1);
      out << number(a) << ',' << number(top) << ' ' << number(b) << ',' << number(top) << ' '
          << number(b) << ',' << number(top + 40) << ' ' << number(a) << ',' << number(top + 40);
    }
    out << "\" fill=\"" << hue_of(abstraction.policy[z]) << "\" fill-opacity=\""
        << number(0.15 + 0.85 * shade) << "\" stroke=\"" << (rewarded ? "black" : "white")
        << "\" stroke-width=\"" << (rewarded ? 1.5 : 0.3) << "\"/>\n";
  }
}

}  // namespace

std::string abstraction_svg(const pipeline::ContinuousCatalog& catalog, std::size_t which) {
  const pipeline::ContinuousAbstraction& abstraction = catalog.abstractions[which];
  const pipeline::CellPartition& grid = abstraction.cells;
  const Slice slice = slice_of(grid);
  const auto& xs = grid.breaks[0];
  const bool two_d = slice.shown_axes == 2;
  const std::vector<double> strip{0, 1};
  const auto& ys = two_d ? grid.breaks[1] : strip;
  Frame frame{xs.front(), xs.back(), ys.front(), ys.back(), 0};
  const double extent = std::max(frame.x1 - frame.x0, two_d ? frame.y1 - frame.y0 : 0.0);
  frame.scale = kPlot / extent;
  if (!two_d) frame.y1 = frame.y0 + 40 / frame.scale;  // a strip 40 pixels high
  const double width = 2 * kMargin + (frame.x1 - frame.x0) * frame.scale;
  const double height = 2 * kMargin + (frame.y1 - frame.y0) * frame.scale + 30;

  double low = HUGE_VAL;
  double high = -HUGE_VAL;
  for (std::uint32_t z = 0; z < abstraction.num_blocks; ++z) {
    if (z == abstraction.outside_block) continue;
    low = std::min(low, abstraction.value[z]);
    high = std::max(high, abstraction.value[z]);
  }
  std::ostringstream out;
  out << "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"" << number(width) << "\" height=\""
      << number(height) << "\" font-family=\"sans-serif\" font-size=\"12\">\n";
  if (abstraction.cells.bsp && grid.dimension() <= 2) {
    draw_polytope_cells(out, abstraction, frame, two_d, low, high);
  } else if (abstraction.cells.bsp) {
    out << "<text x=\"" << number(kMargin) << "\" y=\"" << number(kMargin + 20)
        << "\">polytope cells in more than two dimensions are not drawn</text>\n";
  }
  std::vector<std::uint32_t> index = slice.fixed;
  // A polytope abstraction's grid is its domain box, drawn above as cells: no grid loops.
  const std::size_t nx = abstraction.cells.bsp ? 0 : grid.intervals(0);
  const std::size_t ny = two_d ? grid.intervals(1) : 1;
  auto block_at = [&](std::size_t i, std::size_t j) {
    index[0] = static_cast<std::uint32_t>(i);
    if (two_d) index[1] = static_cast<std::uint32_t>(j);
    return abstraction.cell_block[grid.cell_of(index)];
  };
  for (std::size_t i = 0; i < nx; ++i) {
    for (std::size_t j = 0; j < ny; ++j) {
      const std::uint32_t z = block_at(i, j);
      const double shade = high > low ? (abstraction.value[z] - low) / (high - low) : 1;
      out << "<rect x=\"" << number(frame.px(xs[i])) << "\" y=\""
          << number(frame.py(two_d ? ys[j + 1] : frame.y1)) << "\" width=\""
          << number((xs[i + 1] - xs[i]) * frame.scale) << "\" height=\""
          << number(two_d ? (ys[j + 1] - ys[j]) * frame.scale : 40) << "\" fill=\""
          << hue_of(abstraction.policy[z]) << "\" fill-opacity=\"" << number(0.15 + 0.85 * shade)
          << "\"/>\n";
    }
  }
  // Lines between neighbours: thin between blocks, thick where the reward changes.
  auto edge = [&](double ax, double ay, double bx, double by, std::uint32_t p, std::uint32_t q) {
    if (p == q) return;
    const bool reward = abstraction.block_reward[p] != abstraction.block_reward[q];
    out << "<line x1=\"" << number(ax) << "\" y1=\"" << number(ay) << "\" x2=\"" << number(bx)
        << "\" y2=\"" << number(by) << "\" stroke=\"" << (reward ? "black" : "white")
        << "\" stroke-width=\"" << (reward ? 2.5 : 0.3) << "\"/>\n";
  };
  for (std::size_t i = 0; i < nx; ++i) {
    for (std::size_t j = 0; j < ny; ++j) {
      const double top = frame.py(two_d ? ys[j + 1] : frame.y1);
      const double bottom = two_d ? frame.py(ys[j]) : top + 40;
      if (i + 1 < nx)
        edge(frame.px(xs[i + 1]), top, frame.px(xs[i + 1]), bottom, block_at(i, j),
             block_at(i + 1, j));
      if (two_d && j + 1 < ny)
        edge(frame.px(xs[i]), top, frame.px(xs[i + 1]), top, block_at(i, j), block_at(i, j + 1));
    }
  }
  const std::string x_name = abstraction.axis_names[0];
  out << "<text x=\"" << number(width / 2) << "\" y=\"" << number(height - 40)
      << "\" text-anchor=\"middle\">" << x_name << " [" << number(xs.front()) << " .. "
      << number(xs.back()) << "]</text>\n";
  if (two_d) {
    out << "<text x=\"14\" y=\"" << number(height / 2) << "\" transform=\"rotate(-90 14 "
        << number(height / 2) << ")\" text-anchor=\"middle\">" << abstraction.axis_names[1] << " ["
        << number(ys.front()) << " .. " << number(ys.back()) << "]</text>\n";
  }
  std::string attends;
  for (const std::string& name : abstraction.axis_names)
    attends += (attends.empty() ? "" : ", ") + name;
  out << "<text x=\"" << number(kMargin) << "\" y=\"20\">" << catalog.name << " / "
      << abstraction.context << ": attends to " << attends << "</text>\n";
  out << "<text x=\"" << number(kMargin) << "\" y=\"38\">epsilon "
      << number(pipeline::bound_as_double(abstraction.epsilon))
      << (abstraction.exact() ? " (exact bisimulation)" : " (approximation)") << "; "
      << abstraction.num_cells() << (abstraction.cells.bsp ? " polytope" : "") << " cells, "
      << abstraction.num_blocks << " blocks"
      << (grid.dimension() > 2 ? "; slice through the centre of the other variables" : "")
      << "</text>\n";
  double legend = kMargin;
  for (std::uint32_t a = 0; a < catalog.action_names.size(); ++a) {
    out << "<rect x=\"" << number(legend) << "\" y=\"" << number(height - 22)
        << "\" width=\"10\" height=\"10\" fill=\"" << hue_of(a) << "\"/><text x=\""
        << number(legend + 14) << "\" y=\"" << number(height - 13) << "\">"
        << catalog.action_names[a] << "</text>\n";
    legend += 20 + 7.5 * static_cast<double>(catalog.action_names[a].size());
  }
  out << "</svg>\n";
  return out.str();
}

}  // namespace oasis::codegen
