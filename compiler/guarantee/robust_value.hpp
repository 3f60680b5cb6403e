#pragma once
// The worst (or best) expected value of a cell's successor over every distribution an interval
// MDP row allows (docs/guarantees.md, "Robust values"). The row is factored by axis, and the
// successor's axes are independent: the expectation is taken axis by axis, the last axis
// innermost, each axis's distribution chosen within its intervals once the earlier axes'
// outcomes are known. That choice is freer than the true one (a single product distribution),
// so the minimum is at most the true minimum and the maximum at least the true maximum: both
// stay sound.
//
// On one axis the optimum over {lower <= p <= upper, sum p = 1} is the greedy one: every
// outcome gets its lower bound, and the rest of the mass goes to the outcomes in order of value
// (lowest first to minimise), each up to its upper bound. On the last axis the order comes
// from ValueTable, which keeps every grid line sorted, so no row sorts its own entries there.

#include <cstddef>
#include <cstdint>
#include <vector>

#include "guarantee/interval_mdp.hpp"

namespace oasis::guarantee {

struct RobustGame {
  bool maximise = false;       // the disturbance's side: false for lower bounds
  double outside_value = 0;    // the value of leaving the grid's box
  double truncated_value = 0;  // the value of a Gaussian's truncated tail
  // Values are rounded in the chooser's favour (down when minimising, up when maximising), so
  // that a lower bound stays below and an upper bound above. Set, they are rounded the other
  // way: a minimum rounded up, to check that values are above a minimum.
  bool round_against_chooser = false;
};

// Values per cell, and per line of the last axis (the cells that differ only in their last
// coordinate, consecutive in the numbering) the line's intervals in increasing order of value.
class ValueTable {
 public:
  ValueTable(const UniformGrid& grid, std::vector<double> values);

  [[nodiscard]] const std::vector<double>& values() const { return values_; }
  [[nodiscard]] double operator[](std::size_t cell) const { return values_[cell]; }
  [[nodiscard]] std::size_t line_length() const { return line_length_; }
  [[nodiscard]] std::size_t lines() const { return values_.size() / line_length_; }
  // The order of the line whose first cell is `line * line_length()`.
  [[nodiscard]] const std::uint32_t* order(std::size_t line) const {
    return order_.data() + line * line_length_;
  }

  // Replaces the values of one line and sorts it again. Between two begin_sweep() calls each
  // line is set at most once.
  void set_line(std::size_t line, const double* values);
  // Starts a sweep: every line may be set once more.
  void begin_sweep();
  // A bound on how far values have moved: no value has moved by more than drift() - b since
  // drift_base() was b. It is the sum, over the sweeps since, of each sweep's largest change
  // (a value changes at most once per sweep), so it grows with the largest change per sweep,
  // not with the number of lines.
  [[nodiscard]] double drift() const { return committed_drift_ + sweep_drift_; }
  [[nodiscard]] double drift_base() const { return committed_drift_; }
  // Replaces every value (a sweep of its own).
  void set_all(std::vector<double> values);
  std::vector<double> release() { return std::move(values_); }

 private:
  void sort_line(std::size_t line);

  std::vector<double> values_;
  std::vector<std::uint32_t> order_;
  std::size_t line_length_;
  double committed_drift_ = 0;  // the sweeps before this one
  double sweep_drift_ = 0;      // the largest change in this sweep so far
};

// Scratch space reused across calls (no allocation per row).
struct RobustScratch {
  std::vector<std::vector<double>> values;   // per axis level
  std::vector<std::vector<double>> amounts;  // per axis level, for robust_choice
  std::vector<std::uint32_t> order;
};

// The robust expectation of `table`'s values under `row` (the slices of one cell and action),
// rounded outward (RobustGame::round_against_chooser says which way) by a bound on the rounding
// of the sums, then clamped to [0, 1].
double robust_value(const IntervalMdp& mdp, const AxisSlice* row, const ValueTable& table,
                    const RobustGame& game, RobustScratch& scratch);

// The distribution robust_value chooses, expanded over the cells: probabilities (a cell may
// appear more than once), and the value of what leaves the cells (outside the box, the
// truncated tails, mass no outcome takes) as `constant`. Unrounded: a guess for solvers whose
// results are checked with robust_value, never a bound itself.
struct ChosenRow {
  std::vector<std::uint32_t> cells;
  std::vector<double> probabilities;
  double constant = 0;
};

void robust_choice(const IntervalMdp& mdp, const AxisSlice* row, const ValueTable& table,
                   const RobustGame& game, RobustScratch& scratch, ChosenRow& out);

}  // namespace oasis::guarantee
