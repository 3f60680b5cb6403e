#include "geom/polytope_partition.hpp"

#include <algorithm>
#include <set>

#include "geom/polytope_error_bound.hpp"
#include "support/text.hpp"

namespace oasis::geom {
namespace {

// Splits cells until each lies inside `region` or meets it in a set of measure zero.
std::size_t insert_region(BspTree& tree, const Polytope& region) {
  std::size_t splits = 0;
  for (std::size_t cell = 0; cell < tree.num_cells(); ++cell) {
    for (const HalfSpace& h : region.constraints()) {
      const std::vector<Point>& vertices = tree.cells()[cell].vertices;
      const bool beyond = std::all_of(vertices.begin(), vertices.end(),
                                      [&](const Point& v) { return dot(h.normal, v) >= h.bound; });
      const bool within = std::all_of(vertices.begin(), vertices.end(),
                                      [&](const Point& v) { return dot(h.normal, v) <= h.bound; });
      if (beyond && !within) break;                  // outside the region (up to a shared face)
      if (!within && tree.split(cell, h)) ++splits;  // the part inside h keeps `cell`
    }
  }
  return splits;
}

struct CellBound {
  Rational bound;
  std::size_t cell = 0;
};

// The largest bound first, then the lowest cell.
struct WorseFirst {
  bool operator()(const CellBound& p, const CellBound& q) const {
    const int order = cmp(p.bound, q.bound);
    return order != 0 ? order > 0 : p.cell < q.cell;
  }
};
using CellsByBound = std::set<CellBound, WorseFirst>;

class Refiner {
 public:
  Refiner(const PolytopeGeometry& geometry, const PolytopePartitionOptions& options,
          PolytopePartition& result)
      : geometry_(geometry), options_(options), result_(result) {
    for (std::size_t a = 0; a < geometry.actions.size(); ++a)
      if (geometry.actions[a].has_undisturbed_axis()) deterministic_actions_.push_back(a);
  }

  // Step 2: passes over every cell until one pass splits nothing.
  void bisimulation() {
    bool changed = !deterministic_actions_.empty();
    while (changed) {
      changed = false;
      for (std::size_t cell = 0; cell < tree().num_cells(); ++cell) {
        for (const std::size_t a : deterministic_actions_) {
          while (!budget_spent()) {
            const CellErrorBound bound = cell_error_bound(geometry_, tree(), cell, a);
            if (!bound.preimage_split || !tree().split(cell, *bound.preimage_split)) break;
            ++result_.bisimulation_splits;
            changed = true;
            report();
          }
          if (budget_spent()) return;
        }
      }
    }
    result_.stable = true;
  }

  // Step 3: the worst cell first (of equal bounds, the lowest index), kept in order so that
  // finding it does not cost a pass over every cell.
  void error_driven() {
    CellsByBound worst;
    for (std::size_t cell = 0; cell < tree().num_cells(); ++cell)
      worst.insert({cell_bound(cell), cell});
    for (;;) {
      const auto top = worst.begin();
      result_.epsilon = top->bound;
      if (top->bound <= options_.epsilon || budget_spent()) return;
      const std::size_t cell = top->cell;
      if (!split_worst(cell)) return;  // cannot happen for a full-dimensional cell
      ++result_.error_splits;
      report(to_double(result_.epsilon));
      if (deterministic_actions_.empty()) {  // only the two halves changed
        worst.erase(top);
        worst.insert({cell_bound(cell), cell});
        worst.insert({cell_bound(tree().num_cells() - 1), tree().num_cells() - 1});
      } else {  // new hyperplanes may cut the images of other cells
        worst.clear();
        for (std::size_t c = 0; c < tree().num_cells(); ++c)
          worst.insert({cell_bound(c), c});
      }
    }
  }

 private:
  BspTree& tree() { return result_.tree; }
  [[nodiscard]] bool budget_spent() const { return result_.tree.num_cells() >= options_.max_cells; }
  void report(std::optional<double> worst_bound = std::nullopt) const {
    if (options_.progress) options_.progress(result_.tree.num_cells(), worst_bound);
  }

  Rational cell_bound(std::size_t cell) {
    Rational worst = 0;
    for (std::size_t a = 0; a < geometry_.actions.size(); ++a)
      worst = std::max(worst, cell_error_bound(geometry_, tree(), cell, a).epsilon);
    return worst;
  }

  bool split_worst(std::size_t cell) {
    for (std::size_t a = 0; a < geometry_.actions.size(); ++a) {
      const CellErrorBound bound = cell_error_bound(geometry_, tree(), cell, a);
      if (bound.preimage_split && tree().split(cell, *bound.preimage_split)) return true;
    }
    // Through the representative point, across the longest extent of the bounding box: an
    // interior point, so both halves are full-dimensional.
    const BspCell& c = tree().cells()[cell];
    const auto box = bounding_box_of(c.vertices);
    std::size_t axis = 0;
    for (std::size_t j = 1; j < geometry_.dimension(); ++j)
      if (box->high[j] - box->low[j] > box->high[axis] - box->low[axis]) axis = j;
    HalfSpace cut{std::vector<Rational>(geometry_.dimension(), 0), c.representative[axis]};
    cut.normal[axis] = 1;
    return tree().split(cell, cut);
  }

  const PolytopeGeometry& geometry_;
  const PolytopePartitionOptions& options_;
  PolytopePartition& result_;
  std::vector<std::size_t> deterministic_actions_;
};

std::vector<Rational> cell_rewards(const PolytopeGeometry& geometry, const BspTree& tree) {
  std::vector<Rational> rewards(tree.num_cells(), 0);
  for (std::size_t cell = 0; cell < tree.num_cells(); ++cell) {
    // The representative is interior and every cell is inside a region or meets it in
    // measure zero, so membership of the representative decides.
    for (const PolytopeReward& reward : geometry.rewards)
      if (reward.region.contains(tree.cells()[cell].representative)) rewards[cell] += reward.value;
  }
  return rewards;
}

}  // namespace

std::optional<PolytopePartition> partition_polytopes(const PolytopeGeometry& geometry,
                                                     const PolytopePartitionOptions& options,
                                                     std::string& error) {
  for (std::size_t i = 0; i < geometry.dimension(); ++i) {
    if (!(geometry.domain_low[i] < geometry.domain_high[i])) {
      error = "context " + quoted(geometry.context) + ": the domain of " +
              quoted(geometry.axis_names[i]) + " is empty or a single point";
      return std::nullopt;
    }
  }
  PolytopePartition result;
  result.tree = BspTree(geometry.domain_low, geometry.domain_high);
  for (const PolytopeReward& reward : geometry.rewards) {
    const Polytope region = reward.region.without_redundancy();
    if (region.is_full_dimensional()) result.reward_splits += insert_region(result.tree, region);
  }
  Refiner refiner(geometry, options, result);
  refiner.bisimulation();
  refiner.error_driven();
  result.met = result.epsilon <= options.epsilon;
  result.cell_reward = cell_rewards(geometry, result.tree);
  return result;
}

}  // namespace oasis::geom
