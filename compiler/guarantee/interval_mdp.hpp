#pragma once
// The interval MDP of a continuous model on a uniform grid (docs/guarantees.md): one state per
// cell, one action per (declared action, combination of input values), and for each (cell,
// action) one AxisRow per axis. The successor's axes are independent given the state, so a
// row is the product of its axes' distributions, each known to lie in its AxisRow's intervals;
// the row is kept in that factored form, never expanded.

#include <cstddef>
#include <cstdint>
#include <functional>
#include <string>
#include <vector>

#include "guarantee/axis_kernel.hpp"
#include "model/model_ir.hpp"

namespace oasis::guarantee {

// Breakpoints per axis, uniform over the declared range, rounded to the nearest double: the
// cells are the products of [t_k, t_{k+1}) (the last interval closed), in these doubles
// exactly. Cells are numbered with the last axis varying fastest.
struct UniformGrid {
  std::vector<std::vector<double>> breaks;
  std::vector<std::size_t> strides;  // cell index = sum of interval index * stride
  std::size_t cells = 0;

  [[nodiscard]] std::size_t dimension() const { return breaks.size(); }
  [[nodiscard]] std::size_t intervals(std::size_t axis) const { return breaks[axis].size() - 1; }
  // The interval index of `cell` along `axis`.
  [[nodiscard]] std::size_t coordinate(std::size_t cell, std::size_t axis) const {
    return cell / strides[axis] % intervals(axis);
  }
};

// Throws std::invalid_argument when the rounded breakpoints are not strictly increasing.
UniformGrid uniform_grid(const model::ModelIR& ir);

// One finite action: a declared action with one value per input.
struct ActionChoice {
  model::ActionIndex action = 0;
  std::vector<Rational> inputs;
};

// Every (action, input combination), actions in declaration order (those with dynamics), the
// last input varying fastest.
std::vector<ActionChoice> action_choices(const model::ModelIR& ir);

// One axis of one row, in the arena of IntervalMdp.
struct AxisSlice {
  std::uint32_t first = 0;   // the first interval with an entry
  std::uint32_t count = 0;   // entries
  std::uint64_t offset = 0;  // into IntervalMdp::lower / upper
  double outside_lower = 0;
  double outside_upper = 0;
  double truncated = 0;
};

struct IntervalMdp {
  UniformGrid grid;
  std::vector<ActionChoice> actions;
  std::vector<AxisSlice> slices;  // (cell * actions + action) * dimension + axis
  std::vector<double> lower;
  std::vector<double> upper;

  [[nodiscard]] const AxisSlice* row(std::size_t cell, std::size_t action) const {
    return &slices[(cell * actions.size() + action) * grid.dimension()];
  }
  [[nodiscard]] std::size_t entries() const { return lower.size(); }
  [[nodiscard]] std::size_t bytes() const {
    return slices.size() * sizeof(AxisSlice) + 2 * lower.size() * sizeof(double);
  }
};

struct BuildOptions {
  unsigned jobs = 1;
  // Called now and then with (rows done, rows in all); may throw to stop (an interrupt).
  std::function<void(std::size_t, std::size_t)> progress;
  // Refuses, before building, an abstraction whose rows would take more bytes than this
  // (estimated from a sample of cells spread over the grid). 0: no limit.
  std::uint64_t memory_budget = 0;
};

// Encloses f(cell, u) for every cell and action (model/enclosure.hpp) and bounds each axis's
// interval probabilities. Throws model::EnclosureError (with the expression's place) when a
// map cannot be enclosed on a cell, std::length_error when the memory budget is exceeded.
IntervalMdp build_interval_mdp(const model::ModelIR& ir, const BuildOptions& options);

}  // namespace oasis::guarantee
