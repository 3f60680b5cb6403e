#include "guarantee/robust_value.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <numeric>

namespace oasis::guarantee {
namespace {

constexpr double kUnitRoundoff = 0x1p-52;  // twice the unit roundoff of a double

// The greedy optimum on one axis, given its outcomes in order of preference (best first for
// the side that chooses: lowest values when minimising).
class AxisChoice {
 public:
  AxisChoice(const IntervalMdp& mdp, const AxisSlice& slice, const RobustGame& game)
      : lower_(mdp.lower.data() + slice.offset),
        upper_(mdp.upper.data() + slice.offset),
        slice_(slice),
        game_(game) {
    extras_ = {Extra{game.outside_value, slice.outside_upper - slice.outside_lower},
               Extra{game.truncated_value, slice.truncated}};
    if (better(extras_[1].value, extras_[0].value)) std::swap(extras_[0], extras_[1]);
  }

  // Every outcome's lower bound first. `value_of(k)` is entry k's value.
  template <typename ValueOf>
  void start(const ValueOf& value_of) {
    double mass = slice_.outside_lower;
    value_ = slice_.outside_lower * game_.outside_value;
    for (std::uint32_t k = 0; k < slice_.count; ++k) {
      mass += lower_[k];
      value_ += lower_[k] * value_of(k);
    }
    rest_ = 1.0 - mass;
  }

  // The next entry in order of preference.
  void offer(std::uint32_t k, double value) {
    while (next_extra_ < extras_.size() && better(extras_[next_extra_].value, value)) {
      give(extras_[next_extra_].room, extras_[next_extra_].value);
      ++next_extra_;
    }
    give(upper_[k] - lower_[k], value);
  }
  [[nodiscard]] bool done() const { return rest_ <= 0; }

  double finish() {
    for (; next_extra_ < extras_.size(); ++next_extra_)
      give(extras_[next_extra_].room, extras_[next_extra_].value);
    // Mass no outcome can take (bounds rounded outward make this empty): the value at the end
    // the result is rounded to.
    const bool up = game_.maximise != game_.round_against_chooser;
    if (rest_ > 0) value_ += rest_ * (up ? 1.0 : 0.0);
    const double error = 2.0 * static_cast<double>(slice_.count + 4) * kUnitRoundoff;
    return up ? std::min(1.0, value_ + error) : std::max(0.0, value_ - error);
  }

 private:
  struct Extra {
    double value;
    double room;
  };
  [[nodiscard]] bool better(double a, double b) const { return game_.maximise ? a > b : a < b; }
  void give(double room, double value) {
    const double amount = std::min(room, rest_);
    if (amount <= 0) return;
    value_ += amount * value;
    rest_ -= amount;
  }

  const double* lower_;
  const double* upper_;
  const AxisSlice& slice_;
  const RobustGame& game_;
  std::array<Extra, 2> extras_{};
  std::size_t next_extra_ = 0;
  double value_ = 0;
  double rest_ = 0;
};

class Expectation {
 public:
  Expectation(const IntervalMdp& mdp, const AxisSlice* row, const ValueTable& table,
              const RobustGame& game, RobustScratch& scratch)
      : mdp_(mdp), row_(row), table_(table), game_(game), scratch_(scratch) {
    if (scratch_.values.size() < mdp.grid.dimension()) scratch_.values.resize(mdp.grid.dimension());
  }

  // The expectation over axes axis.. given the cell offset of the earlier axes' outcomes.
  double at(std::size_t axis, std::size_t base) {
    if (axis + 1 == mdp_.grid.dimension()) return last_axis(base);
    const AxisSlice& slice = row_[axis];
    const std::size_t stride = mdp_.grid.strides[axis];
    std::vector<double>& level = scratch_.values[axis];
    level.resize(slice.count);
    for (std::uint32_t k = 0; k < slice.count; ++k)
      level[k] = at(axis + 1, base + (slice.first + k) * stride);
    // Deeper levels used only scratch_.values of deeper axes, so `level` is intact here.
    AxisChoice choice(mdp_, slice, game_);
    choice.start([&](std::uint32_t k) { return level[k]; });
    std::vector<std::uint32_t>& order = scratch_.order;
    order.resize(slice.count);
    std::iota(order.begin(), order.end(), 0u);
    std::sort(order.begin(), order.end(), [&](std::uint32_t a, std::uint32_t b) {
      return game_.maximise ? level[a] > level[b] : level[a] < level[b];
    });
    for (std::size_t i = 0; i < order.size() && !choice.done(); ++i)
      choice.offer(order[i], level[order[i]]);
    return choice.finish();
  }

 private:
  // The last axis: the entries are cells of one grid line, already sorted by ValueTable.
  double last_axis(std::size_t base) {
    const AxisSlice& slice = row_[mdp_.grid.dimension() - 1];
    const double* values = table_.values().data() + base;
    AxisChoice choice(mdp_, slice, game_);
    choice.start([&](std::uint32_t k) { return values[slice.first + k]; });
    const std::uint32_t* order = table_.order(base / table_.line_length());
    const std::size_t n = table_.line_length();
    for (std::size_t i = 0; i < n && !choice.done(); ++i) {
      const std::uint32_t interval = order[game_.maximise ? n - 1 - i : i];
      if (interval < slice.first || interval >= slice.first + slice.count) continue;
      choice.offer(interval - slice.first, values[interval]);
    }
    return choice.finish();
  }

  const IntervalMdp& mdp_;
  const AxisSlice* row_;
  const ValueTable& table_;
  const RobustGame& game_;
  RobustScratch& scratch_;
};

}  // namespace

ValueTable::ValueTable(const UniformGrid& grid, std::vector<double> values)
    : values_(std::move(values)),
      order_(values_.size()),
      line_length_(grid.intervals(grid.dimension() - 1)) {
  for (std::size_t line = 0; line < lines(); ++line)
    sort_line(line);
}

void ValueTable::set_line(std::size_t line, const double* values) {
  const double* old = values_.data() + line * line_length_;
  for (std::size_t i = 0; i < line_length_; ++i)
    sweep_drift_ = std::max(sweep_drift_, std::abs(values[i] - old[i]));
  std::copy(values, values + line_length_,
            values_.begin() + static_cast<std::ptrdiff_t>(line * line_length_));
  sort_line(line);
}

void ValueTable::begin_sweep() {
  // Rounded up, so that the sum stays an upper bound on the movement.
  committed_drift_ =
      std::nextafter(committed_drift_ + sweep_drift_, std::numeric_limits<double>::infinity());
  sweep_drift_ = 0;
}

void ValueTable::set_all(std::vector<double> values) {
  begin_sweep();
  for (std::size_t c = 0; c < values_.size(); ++c)
    sweep_drift_ = std::max(sweep_drift_, std::abs(values[c] - values_[c]));
  values_ = std::move(values);
  for (std::size_t line = 0; line < lines(); ++line)
    sort_line(line);
  begin_sweep();
}

void ValueTable::sort_line(std::size_t line) {
  std::uint32_t* order = order_.data() + line * line_length_;
  const double* values = values_.data() + line * line_length_;
  std::iota(order, order + line_length_, 0u);
  std::stable_sort(order, order + line_length_,
                   [values](std::uint32_t a, std::uint32_t b) { return values[a] < values[b]; });
}

double robust_value(const IntervalMdp& mdp, const AxisSlice* row, const ValueTable& table,
                    const RobustGame& game, RobustScratch& scratch) {
  return Expectation(mdp, row, table, game, scratch).at(0, 0);
}

}  // namespace oasis::guarantee
