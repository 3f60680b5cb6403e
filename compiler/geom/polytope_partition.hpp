#pragma once
// The partition of a context's relevant box into convex cells for the polytope path, kept as
// a BSP tree (geom/bsp_tree.hpp, which states the boundary rule), in three steps:
//
// 1. Rewards: every reward region is inserted into the tree: a cell that straddles one of
//    the region's hyperplanes is split by it, so the reward is constant on every cell.
// 2. Bisimulation, for actions that leave some axis without a disturbance: a cell whose
//    image is cut by a splitting hyperplane reading only undisturbed axes (or by the edge of
//    the domain) is split by that hyperplane's pre-image, i.e. P by Pre_a(Q), until no image
//    is cut (`stable`) or the cell budget is spent.
// 3. Error: the cell with the largest bound ε_C,a (geom/polytope_error_bound.hpp) is split,
//    by a pre-image when the bound asks for one, else through its representative point
//    across its longest extent, until every bound is at most the target (`met`) or the cell
//    budget is spent.

#include <cstddef>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "geom/bsp_tree.hpp"
#include "geom/polytope_geometry.hpp"

namespace oasis::geom {

// No defaults for the target and budget: the caller gives both
// (pipeline/continuous_options.hpp holds the defaults).
struct PolytopePartitionOptions {
  Rational epsilon;       // the error bound to reach
  std::size_t max_cells;  // steps 2 and 3 stop at this many cells
  // Called after every split of steps 2 and 3 with the number of cells and, in step 3, the
  // worst cell's bound before that split (optional).
  std::function<void(std::size_t cells, std::optional<double> worst_bound)> progress = nullptr;
};

struct PolytopePartition {
  BspTree tree;
  std::vector<Rational> cell_reward;  // per cell: Σ of the rewards whose region holds it
  Rational epsilon;                   // the bound reached: max over cells and actions, exact
  bool met = false;                   // epsilon <= the target
  bool stable = false;                // step 2 ended with no image cut (not stopped by the budget)
  std::size_t reward_splits = 0;
  std::size_t bisimulation_splits = 0;
  std::size_t error_splits = 0;
};

// nullopt with `error` set when the domain box is empty or flat on some relevant axis.
std::optional<PolytopePartition> partition_polytopes(const PolytopeGeometry& geometry,
                                                     const PolytopePartitionOptions& options,
                                                     std::string& error);

}  // namespace oasis::geom
