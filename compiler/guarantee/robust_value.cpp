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

  // From now on, each entry's probability is added up in amounts[k] (count entries), and the
  // value of what goes outside the grid's cells in absorbed().
  void record(double* amounts) { amounts_ = amounts; }
  [[nodiscard]] double absorbed() const { return sums_.absorbed; }

  // Every outcome's lower bound first. `value_of(k)` is entry k's value.
  template <typename ValueOf>
  void start(const ValueOf& value_of) {
    double mass = slice_.outside_lower;
    double value = slice_.outside_lower * game_.outside_value;
    sums_.absorbed = value;
    for (std::uint32_t k = 0; k < slice_.count; ++k) {
      mass += lower_[k];
      value += lower_[k] * value_of(k);
    }
    if (amounts_ != nullptr) std::copy(lower_, lower_ + slice_.count, amounts_);
    sums_.value = value;
    sums_.rest = 1.0 - mass;
  }

  // The entries in order of preference, until the mass runs out: for i < n, `entry(i, k,
  // value)` sets entry k and its value, or returns false to pass over i. The running sums are
  // a local copy here, in the innermost loop of the synthesis: as a member they would be
  // stored at every step, in case a write to `amounts_` changed them.
  template <typename Entry>
  void offer_in_order(std::size_t n, const Entry& entry) {
    Sums sums = sums_;
    for (std::size_t i = 0; i < n && sums.rest > 0; ++i) {
      std::uint32_t k = 0;
      double value = 0;
      if (!entry(i, k, value)) continue;
      while (next_extra_ < extras_.size() && better(extras_[next_extra_].value, value)) {
        const Extra& extra = extras_[next_extra_];
        sums.absorbed += sums.give(extra.room, extra.value) * extra.value;
        ++next_extra_;
      }
      const double amount = sums.give(upper_[k] - lower_[k], value);
      if (amounts_ != nullptr) amounts_[k] += amount;
    }
    sums_ = sums;
  }

  double finish() {
    for (; next_extra_ < extras_.size(); ++next_extra_) {
      const Extra& extra = extras_[next_extra_];
      sums_.absorbed += sums_.give(extra.room, extra.value) * extra.value;
    }
    // Mass no outcome can take (bounds rounded outward make this empty): the value at the end
    // the result is rounded to.
    const bool up = game_.maximise != game_.round_against_chooser;
    if (sums_.rest > 0) {
      sums_.value += sums_.rest * (up ? 1.0 : 0.0);
      sums_.absorbed += sums_.rest * (up ? 1.0 : 0.0);
    }
    const double error = 2.0 * static_cast<double>(slice_.count + 4) * kUnitRoundoff;
    return up ? std::min(1.0, sums_.value + error) : std::max(0.0, sums_.value - error);
  }

 private:
  struct Extra {
    double value;
    double room;
  };
  struct Sums {
    double value;     // the expectation so far
    double rest;      // the mass not given yet
    double absorbed;  // the part of `value` from outside the grid's cells
    // Gives up to `room` of the mass left to an outcome of `outcome`; returns what it gave.
    double give(double room, double outcome) {
      const double amount = std::min(room, rest);
      if (amount <= 0) return 0;
      value += amount * outcome;
      rest -= amount;
      return amount;
    }
  };
  [[nodiscard]] bool better(double a, double b) const { return game_.maximise ? a > b : a < b; }

  const double* lower_;
  const double* upper_;
  const AxisSlice& slice_;
  const RobustGame& game_;
  std::array<Extra, 2> extras_{};
  std::size_t next_extra_ = 0;
  Sums sums_{0, 0, 0};
  double* amounts_ = nullptr;
};

class Expectation {
 public:
  Expectation(const IntervalMdp& mdp, const AxisSlice* row, const ValueTable& table,
              const RobustGame& game, RobustScratch& scratch)
      : mdp_(mdp), row_(row), table_(table), game_(game), scratch_(scratch) {
    if (scratch_.values.size() < mdp.grid.dimension()) {
      scratch_.values.resize(mdp.grid.dimension());
      scratch_.amounts.resize(mdp.grid.dimension());
    }
  }

  // What at() chose on one axis: each entry's probability, and the value of the rest.
  struct Recording {
    double* amounts = nullptr;
    double absorbed = 0;
  };

  // The expectation over axes axis.. given the cell offset of the earlier axes' outcomes; with
  // `recording`, what this axis chose.
  double at(std::size_t axis, std::size_t base, Recording* recording = nullptr) {
    if (axis + 1 == mdp_.grid.dimension()) return last_axis(base, recording);
    const AxisSlice& slice = row_[axis];
    const std::size_t stride = mdp_.grid.strides[axis];
    std::vector<double>& level = scratch_.values[axis];
    level.resize(slice.count);
    for (std::uint32_t k = 0; k < slice.count; ++k)
      level[k] = at(axis + 1, base + (slice.first + k) * stride);
    // Deeper levels used only scratch_.values of deeper axes, so `level` is intact here.
    AxisChoice choice(mdp_, slice, game_);
    if (recording != nullptr) choice.record(recording->amounts);
    choice.start([&](std::uint32_t k) { return level[k]; });
    std::vector<std::uint32_t>& order = scratch_.order;
    order.resize(slice.count);
    std::iota(order.begin(), order.end(), 0u);
    std::sort(order.begin(), order.end(), [&](std::uint32_t a, std::uint32_t b) {
      return game_.maximise ? level[a] > level[b] : level[a] < level[b];
    });
    choice.offer_in_order(order.size(), [&](std::size_t i, std::uint32_t& k, double& value) {
      k = order[i];
      value = level[k];
      return true;
    });
    const double value = choice.finish();
    if (recording != nullptr) recording->absorbed = choice.absorbed();
    return value;
  }

  // The distribution at() chooses over axes axis.., each probability times `weight`, into
  // `out`: cells as they come (a cell may repeat), the rest's value into out.constant.
  void choose(std::size_t axis, std::size_t base, double weight, ChosenRow& out) {
    const AxisSlice& slice = row_[axis];
    // Per axis level: the deeper calls below use deeper levels only.
    std::vector<double>& amounts = scratch_.amounts[axis];
    amounts.assign(slice.count, 0);
    Recording recording{amounts.data()};
    at(axis, base, &recording);
    out.constant += weight * recording.absorbed;
    const bool last = axis + 1 == mdp_.grid.dimension();
    const std::size_t stride = mdp_.grid.strides[axis];
    for (std::uint32_t k = 0; k < slice.count; ++k) {
      const double p = weight * amounts[k];
      if (!(p > 0)) continue;
      const std::size_t at_k = base + (slice.first + k) * stride;
      if (last) {
        out.cells.push_back(static_cast<std::uint32_t>(at_k));
        out.probabilities.push_back(p);
      } else {
        choose(axis + 1, at_k, p, out);
      }
    }
  }

 private:
  // The last axis: the entries are cells of one grid line, already sorted by ValueTable.
  double last_axis(std::size_t base, Recording* recording) {
    const AxisSlice& slice = row_[mdp_.grid.dimension() - 1];
    const double* values = table_.values().data() + base;
    AxisChoice choice(mdp_, slice, game_);
    if (recording != nullptr) choice.record(recording->amounts);
    choice.start([&](std::uint32_t k) { return values[slice.first + k]; });
    const std::uint32_t* order = table_.order(base / table_.line_length());
    const std::size_t n = table_.line_length();
    const bool maximise = game_.maximise;
    choice.offer_in_order(n, [&](std::size_t i, std::uint32_t& k, double& value) {
      const std::uint32_t interval = order[maximise ? n - 1 - i : i];
      // Unsigned: an interval before the slice's first wraps past its count.
      k = interval - slice.first;
      value = values[interval];
      return k < slice.count;
    });
    const double value = choice.finish();
    if (recording != nullptr) recording->absorbed = choice.absorbed();
    return value;
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

void robust_choice(const IntervalMdp& mdp, const AxisSlice* row, const ValueTable& table,
                   const RobustGame& game, RobustScratch& scratch, ChosenRow& out) {
  out.cells.clear();
  out.probabilities.clear();
  out.constant = 0;
  Expectation(mdp, row, table, game, scratch).choose(0, 0, 1.0, out);
}

}  // namespace oasis::guarantee
