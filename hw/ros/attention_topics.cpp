#include "ros/attention_topics.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <optional>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include <std_msgs/ColorRGBA.h>
#include <std_msgs/String.h>

#include "oasis/rt/bsp_locator.hpp"
#include "oasis/rt/grid_locator.hpp"

namespace oasis::hw::ros_node {
namespace {

using visualization_msgs::Marker;

// The state vector as the loop builds it: (x1, y1, x2, y2), person k's x and y at 2k and 2k+1.
constexpr std::size_t kStateSize = 4;
constexpr std::size_t kPeople = 2;

// Bounds per slice (one per person), so that a step never sends more than about 4000 points:
// line ends of the exact boundaries, corners of the highlight's triangles, sampled cubes.
constexpr std::size_t kMaxLinePoints = 1500;
constexpr std::size_t kMaxHighlightPoints = 600;
constexpr std::size_t kMaxSamples = 1200;
constexpr double kSampleStep = 0.1;  // metres; coarser when the domain is large

// Heights in the base frame that keep the flat layers apart, and the people's drawing.
constexpr double kReachZ = 0.0;
constexpr double kCellsZ = 0.01;
constexpr double kCurrentZ = 0.02;
constexpr double kFlat = 0.005;
constexpr double kLineWidth = 0.006;
constexpr double kPersonDiameter = 0.3;
constexpr double kPersonZ = 0.25;
constexpr double kLabelZ = 0.6;
constexpr double kLabelHeight = 0.15;
constexpr double kBeliefX = 5.3;  // the belief's text, beyond the far edge of the domain

std_msgs::ColorRGBA rgba(double r, double g, double b, double a) {
  std_msgs::ColorRGBA c;
  c.r = static_cast<float>(r);
  c.g = static_cast<float>(g);
  c.b = static_cast<float>(b);
  c.a = static_cast<float>(a);
  return c;
}

// Person k's colour: red for human 1, yellow for human 2 (their shirts).
std_msgs::ColorRGBA person_colour(std::size_t k, double alpha) {
  return k == 0 ? rgba(0.9, 0.1, 0.1, alpha) : rgba(1.0, 0.85, 0.0, alpha);
}

std_msgs::ColorRGBA grey(double alpha) {
  return rgba(0.55, 0.55, 0.55, alpha);
}
std_msgs::ColorRGBA highlight_colour() {
  return rgba(0.0, 0.8, 1.0, 0.55);
}

// A distinct, stable colour per block for the sampled drawing (golden-ratio hues).
std_msgs::ColorRGBA block_colour(std::uint32_t block) {
  const double hue = std::fmod(static_cast<double>(block) * 0.6180339887498949, 1.0) * 6.0;
  const double x = 1.0 - std::fabs(std::fmod(hue, 2.0) - 1.0);
  double r = 0.0, g = 0.0, b = 0.0;
  switch (static_cast<int>(hue)) {
    case 0:
      r = 1, g = x;
      break;
    case 1:
      r = x, g = 1;
      break;
    case 2:
      g = 1, b = x;
      break;
    case 3:
      g = x, b = 1;
      break;
    case 4:
      r = x, b = 1;
      break;
    default:
      r = 1, b = x;
      break;
  }
  // Pastel: halfway to white, so that the highlight stands out.
  return rgba(0.5 + 0.4 * r, 0.5 + 0.4 * g, 0.5 + 0.4 * b, 0.4);
}

geometry_msgs::Point point(double x, double y, double z) {
  geometry_msgs::Point p;
  p.x = x;
  p.y = y;
  p.z = z;
  return p;
}

Marker make_marker(const std::string& frame, const ros::Time& stamp, const char* ns,
                   std::int32_t id, std::int32_t type) {
  Marker m;
  m.header.frame_id = frame;
  m.header.stamp = stamp;
  m.ns = ns;
  m.id = id;
  m.type = type;
  m.action = Marker::ADD;
  m.pose.orientation.w = 1.0;  // rviz warns about an all-zero quaternion
  m.scale.x = m.scale.y = m.scale.z = 1.0;
  m.lifetime = ros::Duration(0);
  m.frame_locked = false;
  return m;
}

// The same slot, removed: every slot is sent every step, so rviz never keeps a stale one.
Marker deleted_marker(const std::string& frame, const ros::Time& stamp, const char* ns,
                      std::int32_t id) {
  Marker m = make_marker(frame, stamp, ns, id, Marker::CUBE);
  m.action = Marker::DELETE;
  return m;
}

struct Interval {
  double lo = 0.0;
  double hi = 0.0;
};

// The breakpoints of one grid axis.
struct GridAxis {
  const double* t = nullptr;
  std::uint32_t count = 0;
};

GridAxis grid_axis(const rt::GridView& grid, std::uint32_t i) {
  return {grid.breaks + grid.break_begin[i], grid.break_begin[i + 1] - grid.break_begin[i]};
}

bool grid_has_axis(const rt::GridView& grid, std::uint32_t variable) {
  for (std::uint32_t i = 0; i < grid.dimension; ++i)
    if (grid.axes[i] == variable) return true;
  return false;
}

// True when the abstraction's partition can be read for a state of `state_size` variables:
// a valid grid, a cell-to-block table, and a valid BSP if it has one.
bool usable_partition(const rt::AbstractionView& abs, std::size_t state_size) {
  if (abs.cell_block == nullptr || !rt::validate_grid(abs.grid, state_size)) return false;
  if (abs.bsp.num_nodes == 0) return true;
  std::vector<unsigned char> scratch(abs.bsp.num_cells);
  return rt::validate_bsp(abs.bsp, abs.grid.dimension, scratch.data());
}

// The range of a state variable: the attended abstraction's grid's, else the first other
// abstraction's that grids it (an abstraction need not grid every variable).
std::optional<Interval> variable_domain(const rt::CatalogView& catalog, std::uint32_t attended,
                                        std::uint32_t variable, std::size_t state_size) {
  for (std::uint32_t n = 0; n < catalog.num_abstractions; ++n) {
    const std::uint32_t a = n == 0 ? attended : (n <= attended ? n - 1 : n);
    const rt::GridView& grid = catalog.abstractions[a].grid;
    if (!rt::validate_grid(grid, state_size)) continue;
    for (std::uint32_t i = 0; i < grid.dimension; ++i) {
      if (grid.axes[i] != variable) continue;
      const GridAxis axis = grid_axis(grid, i);
      return Interval{axis.t[0], axis.t[axis.count - 1]};
    }
  }
  return std::nullopt;
}

// The drawing of one person's slice: `cells` (boundaries or samples) and `current` (the
// current block's part of the slice); either may be absent.
struct SliceDrawing {
  std::optional<Marker> cells;
  std::optional<Marker> current;
};

// What every slice drawing needs to know.
struct SliceInput {
  const rt::CatalogView& catalog;
  std::uint32_t attended;
  const rt::AbstractionView& abs;
  const std::vector<double>& state;
  std::size_t person;  // 0 or 1
  const std::string& frame;
  const ros::Time& stamp;

  std::uint32_t x_var() const { return static_cast<std::uint32_t>(2 * person); }
  std::uint32_t y_var() const { return static_cast<std::uint32_t>(2 * person + 1); }
};

// The block of the current state in the attended abstraction, or nothing outside its domain.
std::optional<std::uint32_t> current_block(const SliceInput& in) {
  const std::uint32_t cell =
      rt::locate_partition_cell(in.abs.grid, in.abs.bsp, in.state.data(), in.state.size());
  if (cell == rt::kOutsideCell) return std::nullopt;
  return in.abs.cell_block[cell];
}

// ---- exact: a gridded abstraction's block boundaries ----

// One axis of the slice: the grid's breakpoints along the person's coordinate, or, when the
// grid does not have that coordinate, the variable's domain as a single interval (stride 0).
struct SliceAxis {
  std::vector<double> breaks;
  std::uint64_t stride = 0;
  std::size_t intervals() const { return breaks.size() - 1; }
};

// A 2-D slice of a grid: the person's x and y vary, every other gridded variable is fixed at
// its current value, so the slice's cell (i, j) is grid cell base + i * x.stride + j * y.stride.
struct GridSlice {
  SliceAxis x;
  SliceAxis y;
  std::uint64_t base = 0;
};

std::optional<GridSlice> grid_slice(const SliceInput& in) {
  const rt::GridView& grid = in.abs.grid;
  const std::uint32_t d = grid.dimension;
  std::vector<std::uint64_t> stride(d, 1);
  for (std::uint32_t i = d - 1; i > 0; --i)
    stride[i - 1] = stride[i] * (grid_axis(grid, i).count - 1);
  GridSlice slice;
  for (std::uint32_t i = 0; i < d; ++i) {
    const GridAxis axis = grid_axis(grid, i);
    const std::uint32_t variable = grid.axes[i];
    if (variable == in.x_var() || variable == in.y_var()) {
      SliceAxis& s = variable == in.x_var() ? slice.x : slice.y;
      s.breaks.assign(axis.t, axis.t + axis.count);
      s.stride = stride[i];
      continue;
    }
    // The grid's own boundary rule (grid_locator.hpp), so that the fixed coordinates fall in
    // the same cell as the filter puts them.
    const std::uint32_t k = rt::detail::locate_interval(axis.t, axis.count, in.state[variable]);
    if (k == rt::kOutsideCell) return std::nullopt;  // the whole slice is outside the domain
    slice.base += k * stride[i];
  }
  for (SliceAxis* s : {&slice.x, &slice.y}) {
    if (!s->breaks.empty()) continue;
    const auto domain = variable_domain(in.catalog, in.attended,
                                        s == &slice.x ? in.x_var() : in.y_var(), in.state.size());
    if (!domain) return std::nullopt;
    s->breaks = {domain->lo, domain->hi};
  }
  return slice;
}

std::uint32_t slice_block(const rt::AbstractionView& abs, const GridSlice& slice, std::size_t i,
                          std::size_t j) {
  return abs.cell_block[slice.base + i * slice.x.stride + j * slice.y.stride];
}

// The edges between cells of different blocks, and the slice's outline, each grid line's runs
// merged into one segment; nothing if that takes more than kMaxLinePoints points.
std::optional<Marker> boundary_lines(const SliceInput& in, const GridSlice& slice) {
  Marker m = make_marker(in.frame, in.stamp, "cells", static_cast<std::int32_t>(in.person),
                         Marker::LINE_LIST);
  m.scale.x = kLineWidth;
  m.color = person_colour(in.person, 0.7);
  const std::vector<double>& tx = slice.x.breaks;
  const std::vector<double>& ty = slice.y.breaks;
  const std::size_t nx = slice.x.intervals();
  const std::size_t ny = slice.y.intervals();
  // Lines x = tx[i] (across y) when `across_y`, else y = ty[i] (across x).
  for (const bool across_y : {true, false}) {
    const std::size_t lines = (across_y ? nx : ny) + 1;
    const std::size_t steps = across_y ? ny : nx;
    const std::vector<double>& along = across_y ? ty : tx;
    for (std::size_t i = 0; i < lines; ++i) {
      std::optional<std::size_t> run;
      for (std::size_t j = 0; j <= steps; ++j) {
        bool edge = false;
        if (j < steps) {
          edge =
              i == 0 || i == lines - 1 ||
              (across_y ? slice_block(in.abs, slice, i - 1, j) != slice_block(in.abs, slice, i, j)
                        : slice_block(in.abs, slice, j, i - 1) != slice_block(in.abs, slice, j, i));
        }
        if (edge && !run) run = j;
        if (!edge && run) {
          const double at = across_y ? tx[i] : ty[i];
          const double from = along[*run];
          const double to = along[j];
          m.points.push_back(across_y ? point(at, from, kCellsZ) : point(from, at, kCellsZ));
          m.points.push_back(across_y ? point(at, to, kCellsZ) : point(to, at, kCellsZ));
          if (m.points.size() > kMaxLinePoints) return std::nullopt;
          run.reset();
        }
      }
    }
  }
  return m;
}

void add_rectangle(Marker& m, double x0, double y0, double x1, double y1) {
  for (const auto& [x, y] : {std::pair{x0, y0}, std::pair{x1, y0}, std::pair{x1, y1},  //
                             std::pair{x0, y0}, std::pair{x1, y1}, std::pair{x0, y1}})
    m.points.push_back(point(x, y, kCurrentZ));
}

// The slice's cells of the current block, filled (each row's runs as one rectangle); only the
// cell holding the state if that takes more than kMaxHighlightPoints points.
std::optional<Marker> current_cells(const SliceInput& in, const GridSlice& slice) {
  const auto block = current_block(in);
  if (!block) return std::nullopt;
  Marker m = make_marker(in.frame, in.stamp, "current_cell", static_cast<std::int32_t>(in.person),
                         Marker::TRIANGLE_LIST);
  m.color = highlight_colour();
  const std::vector<double>& tx = slice.x.breaks;
  const std::vector<double>& ty = slice.y.breaks;
  const std::size_t nx = slice.x.intervals();
  for (std::size_t j = 0; j < slice.y.intervals(); ++j) {
    for (std::size_t i = 0; i < nx; ++i) {
      if (slice_block(in.abs, slice, i, j) != *block) continue;
      std::size_t end = i + 1;
      while (end < nx && slice_block(in.abs, slice, end, j) == *block)
        ++end;
      add_rectangle(m, tx[i], ty[j], tx[end], ty[j + 1]);
      i = end - 1;
    }
  }
  if (m.points.size() > kMaxHighlightPoints) {
    // The cell holding the state: an axis the grid does not have is a single interval.
    const auto interval = [&](const SliceAxis& s, double v) -> std::uint32_t {
      if (s.stride == 0) return 0;
      return rt::detail::locate_interval(s.breaks.data(),
                                         static_cast<std::uint32_t>(s.breaks.size()), v);
    };
    const std::uint32_t i = interval(slice.x, in.state[in.x_var()]);
    const std::uint32_t j = interval(slice.y, in.state[in.y_var()]);
    m.points.clear();
    if (i == rt::kOutsideCell || j == rt::kOutsideCell) return std::nullopt;
    add_rectangle(m, tx[i], ty[j], tx[i + 1], ty[j + 1]);
  }
  if (m.points.empty()) return std::nullopt;
  return m;
}

// ---- sampled: any partition (a BSP's polytopes, or a grid too fine to draw exactly) ----

// The slice sampled on a regular lattice (kSampleStep, coarser when there would be more than
// kMaxSamples samples): a flat cube per sample coloured by its block, those in the current
// block repeated in `current`. Samples outside the partition are left out.
SliceDrawing sampled_slice(const SliceInput& in) {
  const std::size_t n = in.state.size();
  const auto dx = variable_domain(in.catalog, in.attended, in.x_var(), n);
  const auto dy = variable_domain(in.catalog, in.attended, in.y_var(), n);
  if (!dx || !dy) return {};
  const double w = dx->hi - dx->lo;
  const double h = dy->hi - dy->lo;
  double step = std::max(kSampleStep, std::sqrt(w * h / static_cast<double>(kMaxSamples)));
  std::size_t nx = 0, ny = 0;
  for (;; step *= 1.1) {
    nx = std::max<std::size_t>(1, static_cast<std::size_t>(std::ceil(w / step)));
    ny = std::max<std::size_t>(1, static_cast<std::size_t>(std::ceil(h / step)));
    if (nx * ny <= kMaxSamples) break;
  }
  const double sx = w / static_cast<double>(nx);
  const double sy = h / static_cast<double>(ny);

  Marker cells = make_marker(in.frame, in.stamp, "cells", static_cast<std::int32_t>(in.person),
                             Marker::CUBE_LIST);
  cells.scale.x = sx;
  cells.scale.y = sy;
  cells.scale.z = kFlat;
  cells.color = rgba(1.0, 1.0, 1.0, 0.4);
  Marker current = make_marker(in.frame, in.stamp, "current_cell",
                               static_cast<std::int32_t>(in.person), Marker::CUBE_LIST);
  current.scale = cells.scale;
  current.color = highlight_colour();
  const auto block = current_block(in);

  std::vector<double> s = in.state;
  for (std::size_t i = 0; i < nx; ++i) {
    for (std::size_t j = 0; j < ny; ++j) {
      s[in.x_var()] = dx->lo + (static_cast<double>(i) + 0.5) * sx;
      s[in.y_var()] = dy->lo + (static_cast<double>(j) + 0.5) * sy;
      const std::uint32_t cell = rt::locate_partition_cell(in.abs.grid, in.abs.bsp, s.data(), n);
      if (cell == rt::kOutsideCell) continue;
      const std::uint32_t b = in.abs.cell_block[cell];
      cells.points.push_back(point(s[in.x_var()], s[in.y_var()], kCellsZ));
      cells.colors.push_back(block_colour(b));
      if (block && b == *block)
        current.points.push_back(point(s[in.x_var()], s[in.y_var()], kCurrentZ));
    }
  }
  SliceDrawing drawing;
  if (!cells.points.empty()) drawing.cells = std::move(cells);
  if (!current.points.empty()) drawing.current = std::move(current);
  return drawing;
}

// Person k's slice of the attended abstraction; nothing when the abstraction does not attend
// to that person (its partition does not change along the slice).
SliceDrawing slice_drawing(const SliceInput& in) {
  if (!grid_has_axis(in.abs.grid, in.x_var()) && !grid_has_axis(in.abs.grid, in.y_var())) return {};
  if (in.abs.bsp.num_nodes == 0) {
    const auto slice = grid_slice(in);
    if (!slice) return {};
    if (auto lines = boundary_lines(in, *slice))
      return {std::move(lines), current_cells(in, *slice)};
  }
  return sampled_slice(in);
}

// True when the cells can be drawn: a continuous catalog over at least (x1, y1, x2, y2), a
// state that has all its variables, and an attended abstraction with a readable partition.
bool cells_drawable(const rt::CatalogView& catalog, const log::StepRecord& record) {
  return record.state.size() >= kStateSize && catalog.is_continuous() &&
         catalog.state_dimension >= kStateSize && record.state.size() >= catalog.state_dimension &&
         catalog.abstractions != nullptr && record.abstraction < catalog.num_abstractions &&
         usable_partition(catalog.abstractions[record.abstraction], record.state.size());
}

void add_people(visualization_msgs::MarkerArray& array, const log::StepRecord& record,
                const std::string& frame, const ros::Time& stamp) {
  for (std::size_t k = 0; k < kPeople; ++k) {
    const log::ObservedHuman& human = record.humans[k];
    // Seen: where perception put them. Not seen: greyed, where the filter holds them (the
    // state), if the record has it.
    std::optional<std::pair<double, double>> at;
    if (human.seen) {
      at.emplace(human.x_m, human.y_m);
    } else if (record.state.size() >= kStateSize) {
      at.emplace(record.state[2 * k], record.state[2 * k + 1]);
    }
    if (at && !(std::isfinite(at->first) && std::isfinite(at->second))) at.reset();
    const auto id = static_cast<std::int32_t>(k);
    if (!at) {
      array.markers.push_back(deleted_marker(frame, stamp, "people", id));
      array.markers.push_back(deleted_marker(frame, stamp, "people", id + 2));
      continue;
    }
    Marker sphere = make_marker(frame, stamp, "people", id, Marker::SPHERE);
    sphere.pose.position = point(at->first, at->second, kPersonZ);
    sphere.scale.x = sphere.scale.y = sphere.scale.z = kPersonDiameter;
    sphere.color = human.seen ? person_colour(k, 0.9) : grey(0.5);
    array.markers.push_back(std::move(sphere));

    Marker label = make_marker(frame, stamp, "people", id + 2, Marker::TEXT_VIEW_FACING);
    label.pose.position = point(at->first, at->second, kLabelZ);
    label.scale.z = kLabelHeight;
    label.color = rgba(1.0, 1.0, 1.0, 1.0);
    label.text = "human " + std::to_string(k + 1) + (human.seen ? "" : " (not seen)");
    array.markers.push_back(std::move(label));
  }
}

Marker reach_marker(const ReachRegion& reach, const std::string& frame, const ros::Time& stamp) {
  const bool valid = std::isfinite(reach.x_min_m) && std::isfinite(reach.x_max_m) &&
                     std::isfinite(reach.y_min_m) && std::isfinite(reach.y_max_m) &&
                     reach.x_min_m <= reach.x_max_m && reach.y_min_m <= reach.y_max_m;
  if (!valid) return deleted_marker(frame, stamp, "reach", 0);
  Marker m = make_marker(frame, stamp, "reach", 0, Marker::CUBE);
  m.pose.position =
      point((reach.x_min_m + reach.x_max_m) / 2, (reach.y_min_m + reach.y_max_m) / 2, kReachZ);
  m.scale.x = reach.x_max_m - reach.x_min_m;
  m.scale.y = reach.y_max_m - reach.y_min_m;
  m.scale.z = kFlat;
  m.color = rgba(0.1, 0.8, 0.2, 0.35);
  return m;
}

// The belief as text beyond the domain's far edge, one line per context, the attended one marked,
// so that rviz (which has no display for ~belief's numbers) shows it beside the cells.
Marker belief_marker(const std::vector<std::string>& names, const log::StepRecord& record,
                     const std::string& frame, const ros::Time& stamp) {
  Marker m = make_marker(frame, stamp, "belief", 0, Marker::TEXT_VIEW_FACING);
  m.pose.position = point(kBeliefX, 0.0, kLabelZ);
  m.scale.z = kLabelHeight;
  m.color = rgba(1.0, 1.0, 1.0, 1.0);
  for (std::size_t k = 0; k < record.belief.size(); ++k) {
    char probability[16];
    std::snprintf(probability, sizeof probability, "%.2f", record.belief[k]);
    m.text += (k == 0 ? "" : "\n") + (k < names.size() ? names[k] : std::to_string(k)) + "  " +
              probability + (k == record.abstraction ? "  <- attended" : "");
  }
  return m;
}

}  // namespace

std::vector<std::string> context_names(const rt::CatalogView& catalog) {
  std::vector<std::string> names;
  if (catalog.abstractions == nullptr) return names;
  names.reserve(catalog.num_abstractions);
  for (std::uint32_t i = 0; i < catalog.num_abstractions; ++i) {
    const char* name = catalog.abstractions[i].context;
    names.emplace_back(name != nullptr ? name : "");
  }
  return names;
}

std_msgs::Float64MultiArray belief_message(const log::StepRecord& record,
                                           const std::vector<std::string>& names) {
  std_msgs::Float64MultiArray message;
  const auto n = static_cast<std::uint32_t>(record.belief.size());
  std_msgs::MultiArrayDimension contexts;
  contexts.label = "contexts";
  contexts.size = n;
  contexts.stride = n;
  message.layout.dim.push_back(contexts);
  for (std::uint32_t i = 0; i < n; ++i) {
    std_msgs::MultiArrayDimension name;
    // A belief longer than the names (it should not be) still gets a label: its index.
    name.label = i < names.size() ? names[i] : std::to_string(i);
    name.size = 1;
    name.stride = 1;
    message.layout.dim.push_back(name);
  }
  message.layout.data_offset = 0;
  message.data = record.belief;
  return message;
}

visualization_msgs::MarkerArray attention_markers(const rt::CatalogView& catalog,
                                                  const log::StepRecord& record,
                                                  const ReachRegion& reach,
                                                  const std::string& base_frame,
                                                  const ros::Time& stamp) {
  visualization_msgs::MarkerArray array;
  array.markers.push_back(reach_marker(reach, base_frame, stamp));

  std::array<SliceDrawing, kPeople> slices;
  if (cells_drawable(catalog, record)) {
    for (std::size_t k = 0; k < kPeople; ++k) {
      const SliceInput in{catalog,
                          record.abstraction,
                          catalog.abstractions[record.abstraction],
                          record.state,
                          k,
                          base_frame,
                          stamp};
      slices[k] = slice_drawing(in);
    }
  }
  for (const char* ns : {"cells", "current_cell"}) {
    for (std::size_t k = 0; k < kPeople; ++k) {
      const std::optional<Marker>& m =
          std::string_view(ns) == "cells" ? slices[k].cells : slices[k].current;
      array.markers.push_back(
          m ? *m : deleted_marker(base_frame, stamp, ns, static_cast<std::int32_t>(k)));
    }
  }
  add_people(array, record, base_frame, stamp);
  array.markers.push_back(belief_marker(context_names(catalog), record, base_frame, stamp));
  return array;
}

AttentionTopics::AttentionTopics(ros::NodeHandle& private_node, const rt::CatalogView& catalog,
                                 ReachRegion reach, std::string base_frame)
    : catalog_(catalog),
      names_(context_names(catalog)),
      reach_(reach),
      base_frame_(std::move(base_frame)),
      belief_(private_node.advertise<std_msgs::Float64MultiArray>("belief", 10)),
      context_(private_node.advertise<std_msgs::String>("context", 10)),
      markers_(private_node.advertise<visualization_msgs::MarkerArray>("markers", 2)) {}

void AttentionTopics::publish(const log::StepRecord& record, const ros::Time& stamp) {
  belief_.publish(belief_message(record, names_));
  std_msgs::String context;
  context.data = record.abstraction_name;
  context_.publish(context);
  // The markers cost a walk over the attended abstraction's slice: only for someone watching.
  if (markers_.getNumSubscribers() > 0)
    markers_.publish(attention_markers(catalog_, record, reach_, base_frame_, stamp));
}

}  // namespace oasis::hw::ros_node
