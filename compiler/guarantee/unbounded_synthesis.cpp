#include "guarantee/unbounded_synthesis.hpp"

#include <algorithm>
#include <atomic>
#include <cmath>
#include <cstdint>
#include <exception>
#include <optional>
#include <string>
#include <thread>
#include <vector>

#include "guarantee/certificates.hpp"
#include "guarantee/robust_value.hpp"

namespace oasis::guarantee {
namespace {

// A better lower-bound action must gain more than this before the controller switches to it:
// rounding noise must not make it move between actions of equal value (docs/guarantees.md).
constexpr double kSwitchGain = 1e-12;

// A certificate is tried every this many sweeps, once the iteration's rate is known.
constexpr std::uint64_t kCertifyEvery = 10;

// A certificate from an extrapolation is tried once the extrapolation reaches at most this
// many times the precision past the iterate: earlier, the check would fail and only cost.
constexpr double kExtrapolationReach = 100;

// The rate is the geometric mean of the ratios of the last this many largest changes.
constexpr std::size_t kRateWindow = 10;

// Sweeps line by line (block Gauss-Seidel: a line's new values are computed from the values
// before it, then stored) until `after_sweep(sweep, moved)` returns true or `budget` sweeps are
// done. `update(cell, table)` is the new value of a cell. Returns the sweeps done. The sweeps
// alternate between the lines' order and its reverse: a value reaches the lines after its own
// in the same sweep, and those before it only in the next, so one way alone carries news
// against it one line per sweep (the vehicle's deterministic rows: 54 sweeps one way).
template <typename Update, typename AfterSweep>
std::uint64_t iterate(ValueTable& table, std::uint64_t budget, const Update& update,
                      const AfterSweep& after_sweep) {
  const std::size_t length = table.line_length();
  std::vector<double> line_values(length);
  for (std::uint64_t sweep = 1; sweep <= budget; ++sweep) {
    table.begin_sweep();
    double moved = 0;
    const bool backward = sweep % 2 == 0;
    for (std::size_t step = 0; step < table.lines(); ++step) {
      const std::size_t line = backward ? table.lines() - 1 - step : step;
      for (std::size_t i = 0; i < length; ++i) {
        const std::size_t c = line * length + i;
        line_values[i] = update(c, table);
        moved = std::max(moved, std::abs(line_values[i] - table[c]));
      }
      table.set_line(line, line_values.data());
    }
    if (after_sweep(sweep, moved)) return sweep;
  }
  return budget;
}

// An iteration from below that converges geometrically, as the robust iterations do once the
// slowest mode dominates: its rate, and the values it is heading for. Only a guess: what it
// proposes is certified before it is used.
class Trend {
 public:
  // Records one sweep: the values before it, after it, and its largest change.
  void record(const std::vector<double>& before, const std::vector<double>& after, double moved) {
    before_ = &before;
    after_ = &after;
    moved_.push_back(moved);
  }

  // The rate of the last sweeps, or 0 when it is not known or the changes do not shrink.
  [[nodiscard]] double rate() const {
    if (moved_.size() <= kRateWindow) return 0;
    const double last = moved_.back();
    const double earlier = moved_[moved_.size() - 1 - kRateWindow];
    if (!(last > 0 && earlier > last)) return 0;
    return std::pow(last / earlier, 1.0 / static_cast<double>(kRateWindow));
  }

  // The sweeps still to come, summed: a geometric sequence of rate r has r / (1 - r) times
  // its last step ahead of it.
  [[nodiscard]] double steps_ahead() const {
    const double r = rate();
    return r / (1 - r);
  }

  [[nodiscard]] double last_change() const { return moved_.empty() ? 0 : moved_.back(); }

  // after + factor * (after - before) + lift on the undecided cells, within [0, 1].
  [[nodiscard]] std::vector<double> ahead(double factor, double lift,
                                          const std::vector<std::uint8_t>& undecided) const {
    std::vector<double> values = *after_;
    for (std::size_t c = 0; c < values.size(); ++c) {
      if (undecided[c] == 0) continue;
      const double step = (*after_)[c] - (*before_)[c];
      values[c] = std::clamp(values[c] + factor * step + lift, 0.0, 1.0);
    }
    return values;
  }

 private:
  const std::vector<double>* before_ = nullptr;
  const std::vector<double>* after_ = nullptr;
  std::vector<double> moved_;
};

// The upper bound, once it is known, for the lower bound's iteration to stop on a closed gap.
struct PublishedBound {
  std::atomic<bool> ready{false};
  std::vector<double> values;  // read only after `ready`
};

// The lower bound and its controller. The optimum is iterated from below with a controller
// kept beside it; values never fall, and each is the robust value, under the cell's action,
// of a table no higher than the final one, so the final table v is a post-fixed point of the
// controller's operator (v <= B v). After a few sweeps, policy iteration guesses the fixed
// point; guesses (it, and extrapolations of the iteration) are kept only once proven
// post-fixed (certificates.hpp). When the controller has no trap, every post-fixed point is
// below what it attains: the certificate. With a trap, the controller's value is computed
// from 0 instead, where every iterate is a bound.
class LowerBound {
 public:
  LowerBound(const IntervalMdp& mdp, const ObjectiveCells& cells, SweepMode mode,
             const SynthesisOptions& options, const PublishedBound& upper)
      : mdp_(mdp),
        options_(options),
        upper_(upper),
        sweeper_(mdp, cells, mode),
        checks_(mdp, cells, mode, Bound::Lower),
        policy_(mdp.grid.cells, 0) {}

  void solve(Synthesis& result) {
    ValueTable table(mdp_.grid, checks_.fixed_or_zero());
    Trend trend;
    result.stop_reason = "sweep limit";
    const auto update = [&](std::size_t c, const ValueTable& values) {
      std::uint32_t action = policy_[c];
      const double chosen = sweeper_.update(c, values, Bound::Lower, action, kSwitchGain).chosen;
      if (chosen < values[c]) return values[c];  // keep the action that earned the value
      policy_[c] = action;
      return chosen;
    };
    // Policy iteration first, from the fixed values (a post-fixed point of every controller's
    // operator): a sweep before it would evaluate every action at every cell as its first
    // round does.
    if (options_.policy_iteration && jump(table, 0, result)) {
      result.sweeps = 0;
      finish(table.release(), result);
      return;
    }
    std::vector<double> previous = table.values();
    bool back_to_certificate = false;
    result.sweeps =
        iterate(table, options_.max_sweeps, update, [&](std::uint64_t sweep, double moved) {
          if (options_.progress) options_.progress(sweep, moved);
          trend.record(previous, table.values(), moved);
          bool stop = false;
          if (moved <= options_.stall) {
            result.stop_reason = "values stopped moving";
            stop = true;
          } else if (certificate_meets_upper()) {
            result.stop_reason = "gap closed";
            stop = true;
            back_to_certificate = true;
          } else if (sweep % kCertifyEvery == 0) {
            stop = try_extrapolation(trend, sweep, result.stop_reason);
          }
          previous = table.values();
          return stop;
        });
    std::vector<double> values = table.release();
    if (back_to_certificate) {
      // The sweeps' controller may have moved between actions of equal value since: the
      // certificate is for the controller it was made with.
      policy_ = certified_policy_;
      values = certified_;
    } else if (certificate_for_current()) {
      for (std::size_t c = 0; c < values.size(); ++c)
        values[c] = std::max(values[c], certified_[c]);
    }
    finish(std::move(values), result);
  }

 private:
  // The bound of a post-fixed point `values` of the controller's operator: itself when the
  // controller has no trap, else the controller's own iteration from 0.
  void finish(std::vector<double> values, Synthesis& result) {
    if (checks_.trap_free(policy_)) {
      result.lower = std::move(values);
      result.lower_method = "certified: the controller has no trap";
    } else {
      result.lower = evaluate_from_zero(result.evaluation_sweeps);
      result.lower_method = "the controller evaluated from 0 (it has a trap)";
    }
    result.controller.push_back(policy_);
  }

  // Policy iteration from the iteration's values and controller. Whether it ends the
  // iteration: when its guess is certified and tight. When it is only certified, the iteration
  // goes on from it (a post-fixed point of the new controller's operator: the iteration's
  // invariant holds again from there); else as it was.
  bool jump(ValueTable& table, std::uint64_t sweep, Synthesis& result) {
    const std::vector<std::uint32_t> kept = policy_;
    const std::optional<std::vector<double>> guess =
        checks_.policy_iteration(table.values(), policy_, result.policy_rounds);
    if (guess && certify_around(*guess, sweep, result.stop_reason)) {
      table.set_all(certified_);
      return true;
    }
    if (guess && certificate_for_current()) {
      table.set_all(certified_);
      return false;
    }
    policy_ = kept;
    return false;
  }

  // Whether the last certificate was made for the controller as it is now.
  [[nodiscard]] bool certificate_for_current() const {
    return !certified_.empty() && certified_policy_ == policy_;
  }

  // Whether the last certificate (for the controller it was made with) is within the gap of
  // the upper bound, once that is published: the other thread's often comes a little after
  // policy iteration's guess is certified.
  [[nodiscard]] bool certificate_meets_upper() const {
    return !certified_.empty() && upper_.ready.load(std::memory_order_acquire) &&
           largest_difference(upper_.values, certified_) <= options_.gap;
  }

  // Extrapolates the iteration to its limit and tries it with certify_around().
  bool try_extrapolation(const Trend& trend, std::uint64_t sweep, std::string& stop_reason) {
    if (trend.rate() <= 0) return false;
    const double steps = trend.steps_ahead();
    if (steps * trend.last_change() > kExtrapolationReach * options_.precision) return false;
    return certify_around(trend.ahead(steps, 0, checks_.undecided()), sweep, stop_reason);
  }

  // Certifies a value a little below `estimate` as the controller's. Whether the iteration can
  // stop: when the certified bound is within the gap of the upper bound (if known yet), or
  // within the precision of a ceiling, a value a little above the estimate proven above the
  // lower game's least fixed point (the best lower bound the abstraction admits), so that the
  // iteration has nothing more to give.
  bool certify_around(const std::vector<double>& estimate, std::uint64_t sweep,
                      std::string& stop_reason) {
    const double lift = 0.1 * options_.precision;
    std::vector<double> candidate = shifted(estimate, -lift, checks_.undecided());
    if (!checks_.post_fixed(candidate, policy_)) return false;
    certified_ = std::move(candidate);
    certified_policy_ = policy_;
    if (certificate_meets_upper()) {
      stop_reason = "gap closed";
      return true;
    }
    if (sweep < next_ceiling_) return false;
    std::vector<double> ceiling = shifted(estimate, lift, checks_.undecided());
    if (checks_.pre_fixed(ceiling) &&
        largest_difference(ceiling, certified_) <= options_.precision) {
      stop_reason = "within the precision of the lower game's fixed point";
      return true;
    }
    next_ceiling_ = sweep + ceiling_wait_;
    ceiling_wait_ *= 2;
    return false;
  }

  std::vector<double> evaluate_from_zero(std::uint64_t& sweeps) {
    ValueTable table(mdp_.grid, checks_.fixed_or_zero());
    // evaluate() reads no action cache: the sweeper's, tied to the optimum's table, is unused.
    sweeps = iterate(
        table, options_.max_sweeps,
        [&](std::size_t c, const ValueTable& values) {
          return sweeper_.evaluate(c, values, policy_[c]);
        },
        [&](std::uint64_t, double moved) { return moved <= options_.stall; });
    return table.release();
  }

  const IntervalMdp& mdp_;
  const SynthesisOptions& options_;
  const PublishedBound& upper_;
  Sweeper sweeper_;
  Certificates checks_;
  std::vector<std::uint32_t> policy_;
  std::vector<double> certified_;
  std::vector<std::uint32_t> certified_policy_;  // the controller certified_ is for
  // A failed ceiling costs sweeps over every action: after one, the next waits twice as long.
  std::uint64_t next_ceiling_ = 0;
  std::uint64_t ceiling_wait_ = kCertifyEvery;
};

// The upper bound: a pre-fixed point of the upper game's operator (certificates.hpp), above
// its least fixed point, which is at least the optimum of the true system. Policy iteration
// guesses it first, and a post-fixed point of a controller without a trap a little below the
// guess proves it tight. Otherwise the least fixed point is approached from below, and guesses
// a little above the iterate (extrapolated, then lifted) are tried as the values settle; the
// least of the verified ones is kept (a minimum of pre-fixed points is one), and the iterate,
// below the least fixed point, tells how tight it is. If none holds, the bound is iterated
// down from 1, where every iterate is a bound.
class UpperBound {
 public:
  UpperBound(const IntervalMdp& mdp, const ObjectiveCells& cells, SweepMode mode,
             const SynthesisOptions& options)
      : mdp_(mdp),
        cells_(cells),
        mode_(mode),
        options_(options),
        sweeper_(mdp, cells, mode),
        checks_(mdp, cells, mode, Bound::Upper) {}

  std::vector<double> solve() {
    if (options_.policy_iteration && from_policy_iteration()) {
      method = "policy iteration, verified and proven tight";
      return best_;
    }
    ValueTable table(mdp_.grid, checks_.fixed_or_zero());
    std::vector<double> previous = table.values();
    std::vector<std::uint32_t> choice(mdp_.grid.cells, 0);  // tried first: the last best
    Trend trend;
    const auto rise = [&](std::size_t c, const ValueTable& values) {
      return std::max(values[c], sweeper_.update(c, values, Bound::Upper, choice[c], 0).best);
    };
    sweeps = iterate(table, options_.max_sweeps, rise, [&](std::uint64_t sweep, double moved) {
      if (abandon.load()) throw Abandoned{};
      trend.record(previous, table.values(), moved);
      bool stop = false;
      if (moved <= options_.stall) {
        stop = true;
        for (const double lift :
             {10 * options_.stall, options_.precision, 1e3 * options_.precision})
          if (try_guess(trend, 0, lift)) break;
      } else if (sweep % kCertifyEvery == 0 && trend.rate() > 0) {
        stop = try_guesses(trend);
      }
      previous = table.values();
      return stop;
    });
    if (!best_.empty()) {
      method = "a guess from below, verified";
      return best_;
    }
    return from_above();
  }

  std::uint64_t sweeps = 0;
  std::uint64_t policy_rounds = 0;
  std::string method;
  // Set from another thread to stop solve() (it then throws Abandoned).
  std::atomic<bool> abandon{false};
  struct Abandoned {};

 private:
  // Whether policy iteration gave a verified upper bound (kept) proven within the precision
  // of the least fixed point.
  bool from_policy_iteration() {
    std::vector<std::uint32_t> policy(mdp_.grid.cells, 0);
    const std::optional<std::vector<double>> guess =
        checks_.policy_iteration(checks_.fixed_or_zero(), policy, policy_rounds);
    if (!guess || abandon.load()) return false;
    const double lift = 0.1 * options_.precision;
    std::vector<double> above = shifted(*guess, lift, checks_.undecided());
    if (!checks_.pre_fixed(above)) return false;
    keep(std::move(above));
    std::vector<double> below = shifted(*guess, -lift, checks_.undecided());
    return checks_.post_fixed(below, policy) && checks_.trap_free(policy) &&
           largest_difference(best_, below) <= options_.precision;
  }

  // Once a verified guess would be within the precision of the iterate (so above the least
  // fixed point, which the iterate approaches from below, by at most that), tries guesses past
  // the iteration's limit, tightest first. Whether one held: the upper bound is then that
  // tight, proven.
  bool try_guesses(const Trend& trend) {
    const double factor = trend.steps_ahead();
    const double ahead = factor * trend.last_change();
    for (const double share : {0.1, 0.5}) {
      const double lift = share * options_.precision;
      if (ahead + lift > options_.precision) return false;
      if (try_guess(trend, factor, lift)) return true;
    }
    return false;
  }

  bool try_guess(const Trend& trend, double factor, double lift) {
    std::vector<double> guess = trend.ahead(factor, lift, checks_.undecided());
    if (!checks_.pre_fixed(guess)) return false;
    keep(std::move(guess));
    return true;
  }

  // Keeps the least of the verified guesses.
  void keep(std::vector<double> guess) {
    if (best_.empty()) {
      best_ = std::move(guess);
      return;
    }
    for (std::size_t c = 0; c < guess.size(); ++c)
      best_[c] = std::min(best_[c], guess[c]);
  }

  std::vector<double> from_above() {
    std::vector<double> start = shifted(checks_.fixed_or_zero(), 1, checks_.undecided());
    Sweeper sweeper(mdp_, cells_, mode_);  // a fresh action cache for a fresh table
    ValueTable table(mdp_.grid, start);
    std::vector<std::uint32_t> choice(start.size(), 0);
    sweeps += iterate(
        table, options_.max_sweeps,
        [&](std::size_t c, const ValueTable& values) {
          return std::min(values[c], sweeper.update(c, values, Bound::Upper, choice[c], 0).best);
        },
        [&](std::uint64_t, double moved) {
          if (abandon.load()) throw Abandoned{};
          return moved <= options_.stall;
        });
    method = "iterated down from 1";
    return table.release();
  }

  const IntervalMdp& mdp_;
  const ObjectiveCells& cells_;
  SweepMode mode_;
  const SynthesisOptions& options_;
  Sweeper sweeper_;
  Certificates checks_;
  std::vector<double> best_;
};

}  // namespace

Synthesis synthesise_unbounded(const IntervalMdp& mdp, const ObjectiveCells& cells, SweepMode mode,
                               const SynthesisOptions& options) {
  Synthesis result;
  UpperBound upper(mdp, cells, mode, options);
  PublishedBound published;
  const auto solve_upper = [&] {
    published.values = upper.solve();
    published.ready.store(true, std::memory_order_release);
  };
  if (options.jobs > 1) {
    // The lower bound may stop by an exception (an interrupt from the progress callback): the
    // upper bound's thread is then told to stop, and joined, before it propagates. A failure
    // of the upper bound's own (a refused allocation) is carried over and thrown here.
    std::exception_ptr upper_failure;
    std::thread upper_thread([&] {
      try {
        solve_upper();
      } catch (const UpperBound::Abandoned&) {
      } catch (...) {
        upper_failure = std::current_exception();
      }
    });
    try {
      LowerBound(mdp, cells, mode, options, published).solve(result);
    } catch (...) {
      upper.abandon = true;
      upper_thread.join();
      throw;
    }
    upper_thread.join();
    if (upper_failure) std::rethrow_exception(upper_failure);
  } else {
    solve_upper();  // first: it usually converges sooner, and lets the lower bound stop on it
    LowerBound(mdp, cells, mode, options, published).solve(result);
  }
  result.upper_sweeps = upper.sweeps;
  result.policy_rounds += upper.policy_rounds;
  result.upper_method = upper.method;
  result.upper = std::move(published.values);
  result.largest_gap = largest_gap(result.lower, result.upper);
  result.gap_closed = result.largest_gap <= options.gap;
  if (result.gap_closed) result.stop_reason = "gap closed";
  return result;
}

}  // namespace oasis::guarantee
