#include "guarantee/certificates.hpp"

#include <algorithm>
#include <cmath>

#include "guarantee/chain_solver.hpp"
#include "guarantee/end_components.hpp"

namespace oasis::guarantee {
namespace {

// A guess may be replaced by its images under the operator this many times before it is
// given up.
constexpr int kSmoothings = 3;

// A controller switches only to an action better by more than this: rounding noise must not
// make it move between actions of equal value.
constexpr double kSwitchGain = 1e-12;

// Policy iteration stops after this many solves, once the controller stays, or once no value
// moves by more than kPolicySettled in a solve: far below the certificates' lift. Noisy models
// settle in about five; a deterministic one can take a round per step of its longest path,
// each round costing a sweep over every action, and is better left to the sweeps.
constexpr std::uint64_t kPolicyRounds = 8;
constexpr double kPolicySettled = 1e-9;

// Such a model shows itself early: values jump by about 1 (0 to 1 where the target comes
// within reach) solve after solve. After kStepRounds solves in a row that each move some
// value by kStepMove or more, policy iteration gives up and leaves the rest to the sweeps.
constexpr std::uint64_t kStepRounds = 3;
constexpr double kStepMove = 0.5;

// Early rounds only point the controller the right way, and their solves may stop sooner:
// the first asks for a relative residual of kFirstResidual, each later one for
// kResidualPerMove times the largest change of the round before (at least 1e-13).
constexpr double kFirstResidual = 1e-8;
constexpr double kResidualPerMove = 1e-7;

}  // namespace

template <typename Image, typename Holds>
bool Certificates::settles(std::vector<double>& guess, const Image& image, const Holds& holds) {
  std::vector<double> next(guess.size());
  for (int application = 0; application <= kSmoothings; ++application) {
    const ValueTable& table = table_for(guess);
    bool all = true;
    for (std::size_t c = 0; c < guess.size(); ++c) {
      next[c] = undecided_[c] != 0 ? image(c, table) : guess[c];
      if (!holds(next[c], guess[c])) all = false;
    }
    if (all) return true;
    guess.swap(next);
  }
  return false;
}

Certificates::Certificates(const IntervalMdp& mdp, const ObjectiveCells& cells, SweepMode mode,
                           Bound bound)
    : mdp_(mdp),
      bound_(bound),
      sweeper_(mdp, cells, mode),
      undecided_(mdp.grid.cells),
      favourite_(mdp.grid.cells, 0) {
  for (std::size_t c = 0; c < undecided_.size(); ++c)
    undecided_[c] = sweeper_.fixed(c, bound) < 0 ? 1 : 0;
}

std::vector<double> Certificates::fixed_or_zero() const {
  return sweeper_.fixed_or_zero(bound_);
}

bool Certificates::post_fixed(std::vector<double>& candidate,
                              const std::vector<std::uint32_t>& policy) {
  return settles(
      candidate,
      [&](std::size_t c, const ValueTable& table) {
        return sweeper_.action_value(c, table, policy[c], bound_, Rounding::Down);
      },
      [](double image, double value) { return image >= value; });
}

const ValueTable& Certificates::table_for(const std::vector<double>& values) {
  if (table_) {
    table_->set_all(values);
  } else {
    table_.emplace(mdp_.grid, values);
  }
  return *table_;
}

bool Certificates::pre_fixed(std::vector<double>& guess) {
  return settles(
      guess,
      [&](std::size_t c, const ValueTable& table) {
        return sweeper_.update(c, table, bound_, favourite_[c], 0, Rounding::Up).best;
      },
      [](double image, double value) { return image <= value; });
}

bool Certificates::trap_free(const std::vector<std::uint32_t>& policy) const {
  const std::vector<std::uint8_t> trap = greatest_trap(mdp_, undecided_, policy);
  return std::none_of(trap.begin(), trap.end(), [](std::uint8_t t) { return t != 0; });
}

std::optional<std::vector<double>> Certificates::policy_iteration(
    std::vector<double> values, std::vector<std::uint32_t>& policy, std::uint64_t& rounds) {
  ChosenRow row;
  const RobustGame game = sweeper_.game(bound_);
  RobustScratch scratch;
  double residual = kFirstResidual;
  std::uint64_t steps = 0;  // solves in a row that moved a value by kStepMove or more
  for (std::uint64_t round = 1; round <= kPolicyRounds; ++round) {
    ++rounds;
    const ValueTable& table = table_for(values);
    ChainSolver chain(undecided_, values);
    bool switched = false;
    for (std::size_t c = 0; c < values.size(); ++c) {
      if (undecided_[c] == 0) continue;
      std::uint32_t action = policy[c];
      sweeper_.update(c, table, bound_, action, kSwitchGain);
      if (action != policy[c]) {
        policy[c] = action;
        switched = true;
      }
      robust_choice(mdp_, mdp_.row(c, policy[c]), table, game, scratch, row);
      chain.add_row(c, row);
    }
    std::optional<std::vector<double>> solved = chain.solve(residual);
    if (!solved) return std::nullopt;
    const double moved =
        std::max(largest_difference(*solved, values), largest_difference(values, *solved));
    residual = std::min(kFirstResidual, kResidualPerMove * moved);
    values = std::move(*solved);
    // Switches that move no value by more than this gain too little to pay another solve.
    if (!switched || moved <= kPolicySettled) break;
    steps = moved >= kStepMove ? steps + 1 : 0;
    if (steps == kStepRounds) return std::nullopt;
  }
  favourite_ = policy;
  return values;
}

std::vector<double> shifted(std::vector<double> values, double lift,
                            const std::vector<std::uint8_t>& undecided) {
  for (std::size_t c = 0; c < values.size(); ++c)
    if (undecided[c] != 0) values[c] = std::clamp(values[c] + lift, 0.0, 1.0);
  return values;
}

double largest_difference(const std::vector<double>& above, const std::vector<double>& below) {
  double largest = 0;
  for (std::size_t c = 0; c < above.size(); ++c)
    largest = std::max(largest, above[c] - below[c]);
  return largest;
}

}  // namespace oasis::guarantee
