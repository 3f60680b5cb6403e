// oasis/rt/reward_mass.hpp: how likely a noisy reading of a continuous state is to come from
// a true state where an abstraction's reward matches the observed reward.
//
// The noise-aware filter on a continuous catalog needs p(r_t | phi^i, s_obs): the probability
// that the true state lies in the cells of abstraction i whose reward matches r_t, when the
// true state is s_obs plus independent Gaussian errors of the catalog's sigma(d) per variable
// (PositionNoise). That is the Gaussian mass of a union of cells. RewardMass computes it by
// adaptive box subdivision over the abstraction's relevant axes:
//
//  * the window is the box of +-kWindowSigmas standard deviations around s_obs (the mass
//    outside it, at most 1 - erf(6/sqrt 2)^d < 2e-9 d, is counted as error);
//  * a box is classified against the partition: every cell it meets matches, none does, or
//    mixed. A box whose part inside the grid's domain is uniform and that also reaches out of
//    the domain takes the outside block into account too;
//  * a uniform box contributes its mass exactly (a product of normal CDF differences);
//  * a mixed box is split: at a grid breakpoint inside it when there is one (grid cells, or
//    the domain's edge), else at the face of a polytope cell it straddles when that face is
//    axis-aligned, else at the middle of its widest axis in sigma units. The first two cuts lie
//    on the partition's own boundaries, so on a grid every box ends inside one cell: the result
//    is exact up to rounding (box-shaped reward regions: products of normal CDFs);
//  * a mixed box that only a middle cut could refine and that is lighter than
//    MassLimits::tolerance, or any box at depth kMaxSplitDepth or past MassLimits::max_boxes
//    boxes, counts half its mass as matching and the other half as error, a rigorous bound.
// So the result is exact on grids and within the reported error bound on polytope cells (in
// practice only slanted faces leave any). A variable with sigma 0 contributes a point, so with
// every sigma 0 the answer is 1 or 0: Algorithm 1's deterministic detection model.
//
// No allocation: the stack of boxes and the per-variable sigmas live in a caller-provided
// workspace (workspace_size()). Cost per call: O(B (g log n + c)) for B boxes classified
// (at most max_boxes), g relevant axes of n breakpoints, and c the cells (grid) or BSP nodes
// (polytopes) a box meets. On the Go1 catalog (0.06 m cells) with sigma 3 cm, B is a few
// dozen; tests/bench/filter_benchmark.cpp measures it.
#pragma once

#include <cmath>
#include <cstddef>
#include <cstdint>

#include "oasis/rt/catalog_view.hpp"

namespace oasis::rt {

/// Half-width of the integration window, in standard deviations.
inline constexpr double kWindowSigmas = 6.0;
/// How many times one box may be split along a path from the window.
inline constexpr std::uint32_t kMaxSplitDepth = 40;

/// When RewardMass stops refining a mixed box.
struct MassLimits {
  /// A mixed box whose Gaussian mass is at most this is not split (its mass goes to the error
  /// bound). In (0, 1).
  double tolerance = 1e-4;
  /// Boxes classified per call, at most. At least 1.
  std::uint32_t max_boxes = 4096;
};

/// The answer of RewardMass::match_mass().
struct MassResult {
  /// P(true state where the reward matches | the reading), in [0, 1].
  double probability = 0.0;
  /// A bound on |probability - exact|: unresolved boxes and the window's tails.
  double error = 0.0;
  /// Boxes classified.
  std::uint32_t boxes = 0;
  /// True when a relevant coordinate of the reading was not finite (a missed detection):
  /// nothing was computed.
  bool missing = false;
};

class RewardMass {
 public:
  /// An unusable placeholder (for members built later); assign a constructed one before use.
  RewardMass() noexcept = default;

  /// Doubles of workspace needed for any abstraction of `catalog` (a continuous one): the
  /// sigmas, the stack of boxes, the pending nodes of a BSP walk and a grid walk's indices.
  static std::size_t workspace_size(const CatalogView& catalog) noexcept {
    const std::size_t d = catalog.state_dimension;
    return d + kStackEntries * entry_doubles(d) + max_bsp_nodes(catalog) + 3 * d;
  }

  /// `workspace` holds workspace_size(catalog) doubles, outlives this object and is used by
  /// nothing else. The catalog must be continuous and valid.
  RewardMass(const CatalogView& catalog, const MassLimits& limits, double* workspace) noexcept
      : catalog_(&catalog), limits_(limits) {
    const std::size_t d = catalog.state_dimension;
    sigma_ = workspace;
    stack_ = sigma_ + d;
    nodes_ = stack_ + kStackEntries * entry_doubles(d);
    scratch_ = nodes_ + max_bsp_nodes(catalog);
    for (std::size_t v = 0; v < d; ++v)
      sigma_[v] = 0.0;
  }

  /// Sets every variable's standard deviation from a reading (`state`, state_dimension
  /// doubles): sigma(d) of its object at the object's measured distance, 0 for exact variables.
  /// A missed object (non-finite coordinates) gets sigma 0; match_mass() reports it missing.
  void measure(const double* state) noexcept {
    const PositionNoise& noise = catalog_->observation.position;
    const std::uint32_t d = catalog_->state_dimension;
    for (std::uint32_t v = 0; v < d; ++v) {
      const std::uint32_t object = noise.num_objects == 0 ? kExactVariable : noise.object_of[v];
      if (object == kExactVariable) {
        sigma_[v] = 0.0;
        continue;
      }
      double squared = 0.0;
      for (std::uint32_t u = 0; u < d; ++u)
        if (noise.object_of[u] == object) squared += state[u] * state[u];
      const double sigma = object_sigma(noise, object, std::sqrt(squared));
      sigma_[v] = std::isfinite(sigma) ? sigma : 0.0;
    }
  }

  /// The standard deviation measure() set for variable v.
  double sigma(std::uint32_t v) const noexcept { return sigma_[v]; }

  /// P(true state in a cell of `abs` whose block b has matches(b) true | reading `state`),
  /// with the sigmas of the last measure(). `matches` is called with block indices.
  template <typename Matches>
  MassResult match_mass(const AbstractionView& abs, const double* state,
                        Matches&& matches) noexcept {
    MassResult result;
    const std::uint32_t g = abs.grid.dimension;
    std::uint32_t noisy_axes = 0;
    double* box = stack_;
    for (std::uint32_t a = 0; a < g; ++a) {
      const double x = state[abs.grid.axes[a]];
      if (!std::isfinite(x)) {
        result.missing = true;
        return result;
      }
      const double s = sigma_[abs.grid.axes[a]];
      if (s > 0.0) ++noisy_axes;
      box[a] = x - kWindowSigmas * s;
      box[g + a] = x + kWindowSigmas * s;
    }
    box[2 * std::size_t{g}] = 0.0;  // depth
    std::uint32_t size = 1;
    double matched = 0.0;
    double unresolved = 0.0;
    while (size > 0) {
      --size;
      const double* top = stack_ + static_cast<std::size_t>(size) * entry_doubles(g);
      const auto depth = static_cast<std::uint32_t>(top[2 * std::size_t{g}]);
      ++result.boxes;
      const double mass = box_mass(abs, state, top);
      const unsigned status = classify(abs, top, top + g, matches);
      if (status != kMixed) {
        if (status == kMatch) matched += mass;
        continue;
      }
      const Cut cut = plan_cut(abs, top);
      if ((!cut.exact && mass <= limits_.tolerance) || depth >= kMaxSplitDepth ||
          result.boxes >= limits_.max_boxes) {
        // Somewhere in [0, mass]: count half, and half as the error.
        matched += 0.5 * mass;
        unresolved += 0.5 * mass;
        continue;
      }
      split(abs, size, cut, depth + 1);
      size += 2;
    }
    const double window = std::pow(std::erf(kWindowSigmas / std::sqrt(2.0)), noisy_axes);
    const double probability = matched / window;
    result.probability = probability < 0.0 ? 0.0 : probability > 1.0 ? 1.0 : probability;
    result.error = unresolved / window + (1.0 - window);
    return result;
  }

 private:
  static constexpr unsigned kMatch = 1;
  static constexpr unsigned kMiss = 2;
  static constexpr unsigned kMixed = kMatch | kMiss;

  // A box of the stack: lo[g], hi[g], its depth. Splitting a box at depth k leaves at most
  // one pending sibling per depth above it, so kMaxSplitDepth + 1 entries always suffice.
  static constexpr std::size_t kStackEntries = kMaxSplitDepth + 2;
  static std::size_t entry_doubles(std::size_t g) noexcept { return 2 * g + 1; }

  static std::size_t max_bsp_nodes(const CatalogView& catalog) noexcept {
    std::size_t nodes = 0;
    for (std::uint32_t i = 0; i < catalog.num_abstractions; ++i)
      if (catalog.abstractions[i].bsp.num_nodes > nodes)
        nodes = catalog.abstractions[i].bsp.num_nodes;
    return nodes;
  }

  static double normal_cdf_difference(double low, double high) noexcept {
    constexpr double kInvSqrt2 = 0.70710678118654752440;
    return 0.5 * (std::erf(high * kInvSqrt2) - std::erf(low * kInvSqrt2));
  }

  double box_mass(const AbstractionView& abs, const double* state,
                  const double* box) const noexcept {
    const std::uint32_t g = abs.grid.dimension;
    double mass = 1.0;
    for (std::uint32_t a = 0; a < g; ++a) {
      const std::uint32_t v = abs.grid.axes[a];
      const double s = sigma_[v];
      if (s > 0.0)
        mass *= normal_cdf_difference((box[a] - state[v]) / s, (box[g + a] - state[v]) / s);
    }
    return mass;
  }

  template <typename Matches>
  unsigned status_of_block(std::uint32_t block, Matches& matches) const noexcept {
    return matches(block) ? kMatch : kMiss;
  }

  // The statuses of the cells the box [lo, hi] meets (and of the outside block if it reaches
  // beyond the domain), OR-ed: kMatch, kMiss or kMixed.
  template <typename Matches>
  unsigned classify(const AbstractionView& abs, const double* lo, const double* hi,
                    Matches& matches) noexcept {
    straddled_ = kInternalNode;
    const GridView& grid = abs.grid;
    bool beyond = false;
    for (std::uint32_t a = 0; a < grid.dimension; ++a) {
      const double* t = grid.breaks + grid.break_begin[a];
      const std::uint32_t count = grid.break_begin[a + 1] - grid.break_begin[a];
      // Entirely outside on this axis; a box that only touches the domain's face (a set of
      // measure zero) is outside too, while a point on the face is inside.
      const bool point = !(hi[a] > lo[a]);
      if (point ? (hi[a] < t[0] || lo[a] > t[count - 1]) : (hi[a] <= t[0] || lo[a] >= t[count - 1]))
        return status_of_block(abs.outside_block, matches);
      beyond = beyond || lo[a] < t[0] || hi[a] > t[count - 1];
    }
    unsigned status = beyond ? status_of_block(abs.outside_block, matches) : 0u;
    return status | (abs.bsp.num_nodes != 0 ? classify_bsp(abs, lo, hi, status, matches)
                                            : classify_grid(abs, lo, hi, status, matches));
  }

  // The cells' index range on one axis for the part of [lo, hi] inside the axis's domain:
  // the interval holding lo (boundary rule) to the last interval reaching above hi's left.
  static void interval_range(const double* t, std::uint32_t count, double lo, double hi,
                             std::uint32_t& first, std::uint32_t& last) noexcept {
    const double low = lo < t[0] ? t[0] : lo;
    const double high = hi > t[count - 1] ? t[count - 1] : hi;
    first = detail::locate_interval(t, count, low);
    if (!(high > low)) {
      last = first;
      return;
    }
    // The smallest j >= 1 with t[j] >= high; the box's interior reaches interval j - 1.
    std::uint32_t begin = 1;
    std::uint32_t end = count - 1;
    while (begin < end) {
      const std::uint32_t middle = begin + (end - begin) / 2;
      if (t[middle] >= high) {
        end = middle;
      } else {
        begin = middle + 1;
      }
    }
    last = begin - 1;
  }

  template <typename Matches>
  unsigned classify_grid(const AbstractionView& abs, const double* lo, const double* hi,
                         unsigned status, Matches& matches) noexcept {
    const GridView& grid = abs.grid;
    const std::uint32_t g = grid.dimension;
    double* first = scratch_;  // the odometer over the cells the box meets
    double* last = first + g;
    double* current = last + g;
    for (std::uint32_t a = 0; a < g; ++a) {
      std::uint32_t f = 0;
      std::uint32_t l = 0;
      interval_range(grid.breaks + grid.break_begin[a],
                     grid.break_begin[a + 1] - grid.break_begin[a], lo[a], hi[a], f, l);
      first[a] = f;
      last[a] = l;
      current[a] = f;
    }
    for (;;) {
      std::uint64_t cell = 0;
      for (std::uint32_t a = 0; a < g; ++a) {
        const std::uint32_t intervals = grid.break_begin[a + 1] - grid.break_begin[a] - 1;
        cell = cell * intervals + static_cast<std::uint32_t>(current[a]);
      }
      status |= status_of_block(abs.cell_block[cell], matches);
      if (status == kMixed) return status;
      std::uint32_t a = g;
      while (a > 0 && current[a - 1] >= last[a - 1]) {
        current[a - 1] = first[a - 1];
        --a;
      }
      if (a == 0) return status;
      current[a - 1] += 1;
    }
  }

  template <typename Matches>
  unsigned classify_bsp(const AbstractionView& abs, const double* lo, const double* hi,
                        unsigned status, Matches& matches) noexcept {
    const BspView& bsp = abs.bsp;
    const std::uint32_t g = abs.grid.dimension;
    std::uint32_t pending = 0;
    nodes_[pending++] = 0;
    straddled_ = kInternalNode;
    while (pending > 0) {
      const auto node = static_cast<std::uint32_t>(nodes_[--pending]);
      if (bsp.cell[node] != kInternalNode) {
        status |= status_of_block(abs.cell_block[bsp.cell[node]], matches);
        if (status == kMixed) return status;
        continue;
      }
      // min and max of a.x over the box, clipped to the domain (the grid's single cell).
      double low = 0.0;
      double high = 0.0;
      for (std::uint32_t a = 0; a < g; ++a) {
        const double* t = abs.grid.breaks + abs.grid.break_begin[a];
        const std::uint32_t count = abs.grid.break_begin[a + 1] - abs.grid.break_begin[a];
        const double l = lo[a] < t[0] ? t[0] : lo[a];
        const double h = hi[a] > t[count - 1] ? t[count - 1] : hi[a];
        const double c = bsp.normal[std::size_t{node} * g + a];
        low += c * (c > 0.0 ? l : h);
        high += c * (c > 0.0 ? h : l);
      }
      // A box that only touches the plane (measure zero) is on one side; a box flat along the
      // normal follows the point rule (a.x <= c goes below).
      const bool flat = !(high > low);
      const bool below = flat ? low <= bsp.bound[node] : low < bsp.bound[node];
      const bool above = high > bsp.bound[node];
      if (below) nodes_[pending++] = bsp.below[node];
      if (above) nodes_[pending++] = bsp.above[node];
      if (below && above && straddled_ == kInternalNode) straddled_ = node;
    }
    return status;
  }

  // Where to split a mixed box: the axis and the coordinate, and whether the cut lies on a
  // boundary of the partition (then the halves are closer to uniform, and refining is never
  // an approximation).
  struct Cut {
    std::uint32_t axis = 0;
    double at = 0.0;
    bool exact = false;
  };

  // A grid breakpoint inside the box (grid cells, or the domain's edge) on its widest axis in
  // sigma units; else the axis-aligned face of the first BSP node the box straddles; else the
  // middle of the widest axis.
  Cut plan_cut(const AbstractionView& abs, const double* box) const noexcept {
    const std::uint32_t g = abs.grid.dimension;
    Cut cut;
    double widest = -1.0;
    for (std::uint32_t a = 0; a < g; ++a) {
      double inner = 0.0;
      const double width = sigma_width(abs, box, a);
      if (width > widest && inner_break(abs.grid, a, box[a], box[g + a], inner)) {
        widest = width;
        cut = {a, inner, true};
      }
    }
    if (cut.exact) return cut;
    if (abs.bsp.num_nodes != 0 && straddled_ != kInternalNode) {
      const double* normal = abs.bsp.normal + std::size_t{straddled_} * g;
      std::uint32_t nonzero = 0;
      std::uint32_t axis = 0;
      for (std::uint32_t a = 0; a < g; ++a)
        if (normal[a] != 0.0) {
          ++nonzero;
          axis = a;
        }
      const double at = nonzero == 1 ? abs.bsp.bound[straddled_] / normal[axis] : 0.0;
      if (nonzero == 1 && at > box[axis] && at < box[g + axis]) return {axis, at, true};
    }
    for (std::uint32_t a = 0; a < g; ++a) {
      const double width = sigma_width(abs, box, a);
      if (width > widest) {
        widest = width;
        cut = {a, 0.5 * (box[a] + box[g + a]), false};
      }
    }
    return cut;
  }

  double sigma_width(const AbstractionView& abs, const double* box,
                     std::uint32_t a) const noexcept {
    const double s = sigma_[abs.grid.axes[a]];
    return s > 0.0 ? (box[abs.grid.dimension + a] - box[a]) / s : 0.0;
  }

  // Replaces the box at stack entry k with its two halves at entries k and k + 1.
  void split(const AbstractionView& abs, std::uint32_t k, const Cut& cut,
             std::uint32_t depth) noexcept {
    const std::uint32_t g = abs.grid.dimension;
    double* low_half = stack_ + static_cast<std::size_t>(k) * entry_doubles(g);
    double* high_half = low_half + entry_doubles(g);
    for (std::size_t j = 0; j < 2 * std::size_t{g}; ++j)
      high_half[j] = low_half[j];
    low_half[g + cut.axis] = cut.at;
    high_half[cut.axis] = cut.at;
    low_half[2 * std::size_t{g}] = depth;
    high_half[2 * std::size_t{g}] = depth;
  }

  // The breakpoint of axis a strictly inside (lo, hi) nearest its middle, if any.
  static bool inner_break(const GridView& grid, std::uint32_t a, double lo, double hi,
                          double& cut) noexcept {
    const double* t = grid.breaks + grid.break_begin[a];
    const std::uint32_t count = grid.break_begin[a + 1] - grid.break_begin[a];
    const double middle = 0.5 * (lo + hi);
    // The first breakpoint >= middle.
    std::uint32_t begin = 0;
    std::uint32_t end = count;
    while (begin < end) {
      const std::uint32_t m = begin + (end - begin) / 2;
      if (t[m] < middle) {
        begin = m + 1;
      } else {
        end = m;
      }
    }
    bool found = false;
    double best = 0.0;
    for (std::uint32_t j = begin > 0 ? begin - 1 : 0; j < count && j <= begin; ++j) {
      if (!(t[j] > lo && t[j] < hi)) continue;
      if (!found || std::fabs(t[j] - middle) < std::fabs(best - middle)) best = t[j];
      found = true;
    }
    cut = best;
    return found;
  }

  const CatalogView* catalog_ = nullptr;
  MassLimits limits_;
  double* sigma_ = nullptr;    // [state_dimension]
  double* stack_ = nullptr;    // [kStackEntries entries of 2 d + 1]: boxes to classify
  double* nodes_ = nullptr;    // [max BSP nodes] pending nodes of a BSP walk
  double* scratch_ = nullptr;  // [3 d] a grid walk's first, last and current cell indices
  std::uint32_t straddled_ = kInternalNode;  // the last BSP walk's first straddled node
};

}  // namespace oasis::rt
