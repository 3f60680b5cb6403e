#include "bisim/discrete_proof.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>
#include <utility>

namespace oasis::bisim {
namespace {

// The unit roundoff of doubles: a rounding moves a result by at most this much of itself.
constexpr double kUnit = std::numeric_limits<double>::epsilon() / 2;
// Slack on the bounds' own arithmetic: each is a handful of roundings of non-negative numbers.
constexpr double kSlack = 1 + 16 * kUnit;
// A positive value below this could make a term underflow, where relative bounds end.
constexpr double kSmallestSafe = 1e-280;

// (1 + u)^n - 1 <= n u / (1 - n u) (Higham, Lemma 3.1), rounded up.
double growth(double n) {
  return n * kUnit / (1 - n * kUnit) * kSlack;
}

// Fixed positive weights, one per action, summing to at most 1: a combination that equal
// rows always agree on and different rows rarely do.
std::vector<double> action_weights(std::uint32_t num_actions) {
  std::vector<double> weight(num_actions);
  for (std::uint32_t a = 0; a < num_actions; ++a) {
    const double spread = std::fmod(0.6180339887498949 * (a + 1), 1.0);  // golden-ratio steps
    weight[a] = (1 + spread) / (2.0 * num_actions);
  }
  return weight;
}

// States in groups that no invariant has told apart yet, each group contiguous in `order`.
class Groups {
 public:
  explicit Groups(std::uint32_t num_states) : order_(num_states) {
    std::iota(order_.begin(), order_.end(), 0U);
    if (num_states > 1) open_.emplace_back(0, num_states);
    count_ = num_states > 0 ? 1 : 0;
  }

  [[nodiscard]] std::uint32_t count() const { return count_; }
  [[nodiscard]] bool all_single() const { return open_.empty(); }

  // Sorts every group of two or more by h and cuts it between neighbours a <= b whose exact
  // values, each within a relative `error` of the computed one, cannot meet. True if any cut.
  bool split(const std::vector<double>& h, double error) {
    std::vector<std::pair<std::uint32_t, std::uint32_t>> still_open;
    const std::uint32_t before = count_;
    for (const auto& [begin, end] : open_) {
      const auto first = order_.begin() + begin;
      const auto last = order_.begin() + end;
      std::sort(first, last, [&h](std::uint32_t s, std::uint32_t t) {
        return h[s] < h[t] || (h[s] == h[t] && s < t);
      });
      std::uint32_t group_begin = begin;
      for (std::uint32_t i = begin + 1; i <= end; ++i) {
        if (i < end && !apart(h[order_[i - 1]], h[order_[i]], error)) continue;
        if (i - group_begin > 1) still_open.emplace_back(group_begin, i);
        if (i < end) ++count_;
        group_begin = i;
      }
    }
    open_ = std::move(still_open);
    return count_ > before;
  }

 private:
  static bool apart(double a, double b, double error) {
    return a * (1 + error) * kSlack < b * (1 - error) / kSlack;
  }

  std::vector<std::uint32_t> order_;
  std::vector<std::pair<std::uint32_t, std::uint32_t>> open_;  // groups of two or more
  std::uint32_t count_ = 0;
};

// The smallest positive value of h, or +infinity when there is none.
double smallest_positive(const std::vector<double>& h) {
  double smallest = std::numeric_limits<double>::infinity();
  for (const double v : h)
    if (v > 0) smallest = std::min(smallest, v);
  return smallest;
}

}  // namespace

DiscreteProof prove_discrete(const InvariantModel& model, const DiscreteProofOptions& options) {
  const std::uint32_t n = model.num_states;
  DiscreteProof proof;
  if (n == 0) return proof;
  const double lowest = *std::min_element(model.reward.begin(), model.reward.end());
  std::vector<double> r(n);
  for (std::uint32_t s = 0; s < n; ++s)
    r[s] = model.reward[s] - lowest;  // the same for equal rewards, and never negative
  const std::vector<double> weight = action_weights(model.num_actions);
  const double least_weight = *std::min_element(weight.begin(), weight.end());
  // One round: the expectation's roundings, the weight's product, the sum over actions and r.
  const double round_growth = growth(model.rounding_depth + model.num_actions + 2.0);

  Groups groups(n);
  std::vector<double> h = r;  // exact: h_0 is defined as the rounded r
  double error = 0;
  groups.split(h, error);
  std::vector<double> next(n);
  std::uint32_t stalled = 0;
  while (!groups.all_single() && proof.rounds < options.max_rounds &&
         stalled < options.max_stalled_rounds) {
    if (smallest_positive(h) * model.smallest_term * least_weight < kSmallestSafe) break;
    if (model.prepare) model.prepare(h.data());
    for (std::uint32_t s = 0; s < n; ++s) {
      double mixed = 0;
      for (std::uint32_t a = 0; a < model.num_actions; ++a)
        mixed += weight[a] * model.expectation(s, a, h.data());
      next[s] = r[s] + mixed;
    }
    std::swap(h, next);
    error = (error + round_growth + error * round_growth) * kSlack;
    ++proof.rounds;
    stalled = groups.split(h, error) ? 0 : stalled + 1;
  }
  proof.discrete = groups.all_single();
  proof.groups = groups.count();
  return proof;
}

}  // namespace oasis::bisim
