#include "fit/forward_algorithm.hpp"

#include <cmath>
#include <limits>

namespace oasis::fit {
namespace {

constexpr double kMinusInfinity = -std::numeric_limits<double>::infinity();

class Forward {
 public:
  Forward(const FilterModel& model, const std::vector<double>& switching)
      : m_(model), switching_(switching), n_(model.num_contexts), s_(model.num_states) {}

  double run(const std::vector<LoggedRun>& runs) {
    double total = 0.0;
    for (const LoggedRun& run : runs) {
      total += m_.joint() ? joint(run) : paper(run);
      if (!std::isfinite(total)) return kMinusInfinity;
    }
    return total;
  }

 private:
  double detection(std::uint32_t i, std::uint32_t x, double reward) const {
    const double expected = m_.state_reward[static_cast<std::size_t>(i) * s_ + x];
    const bool match = std::fabs(reward - expected) <= m_.reward_tolerance;
    return match ? 1.0 - m_.detection_epsilon : m_.detection_epsilon;
  }

  double observation(std::uint32_t observed, std::uint32_t s) const {
    if (m_.noise.kind == StateNoise::Kind::kMatrix)
      return m_.noise.confusion[static_cast<std::size_t>(s) * s_ + observed];
    if (observed == s) return m_.noise.p_correct;
    return (1.0 - m_.noise.p_correct) / static_cast<double>(s_ - 1);
  }

  // out[i * stride] = sum_j p(i | j) in[j * stride]
  void switch_predict(const double* in, double* out, std::size_t stride) const {
    for (std::uint32_t i = 0; i < n_; ++i)
      out[i * stride] = 0.0;
    for (std::uint32_t j = 0; j < n_; ++j) {
      const double mass = in[j * stride];
      if (mass == 0.0) continue;
      const double* row = switching_.data() + static_cast<std::size_t>(j) * n_;
      for (std::uint32_t i = 0; i < n_; ++i)
        out[i * stride] += row[i] * mass;
    }
  }

  double paper(const LoggedRun& run) {
    std::vector<double> alpha(m_.prior), predicted(n_);
    double log_l = 0.0;
    for (const LoggedStep& step : run.steps) {
      for (std::uint32_t k = 0; k < step.missing_before; ++k) {
        switch_predict(alpha.data(), predicted.data(), 1);
        alpha.swap(predicted);
      }
      switch_predict(alpha.data(), predicted.data(), 1);
      double evidence = 0.0;
      for (std::uint32_t i = 0; i < n_; ++i) {
        alpha[i] = predicted[i] * detection(i, step.observed_state, step.reward);
        evidence += alpha[i];
      }
      if (!(evidence > 0.0)) return kMinusInfinity;
      for (double& a : alpha)
        a /= evidence;
      log_l += std::log(evidence);
    }
    return log_l;
  }

  // Moves every row of `from` (i, s) under P^i(. | s, action) into `to`.
  void move(const std::vector<double>& from, std::vector<double>& to, std::uint32_t action) const {
    std::fill(to.begin(), to.end(), 0.0);
    const std::uint32_t actions = m_.num_actions;
    for (std::uint32_t i = 0; i < n_; ++i) {
      const model::CsrData& csr = m_.transitions[i];
      const double* in = from.data() + static_cast<std::size_t>(i) * s_;
      double* out = to.data() + static_cast<std::size_t>(i) * s_;
      for (std::uint32_t s = 0; s < s_; ++s) {
        const double mass = in[s];
        if (mass == 0.0) continue;
        const std::size_t base = static_cast<std::size_t>(s) * actions;
        if (action != kUnknownAction) {
          for (std::uint32_t e = csr.choice_begin[base + action];
               e < csr.choice_begin[base + action + 1]; ++e)
            out[csr.target[e]] += csr.probability[e] * mass;
          continue;
        }
        std::uint32_t enabled = 0;
        for (std::uint32_t a = 0; a < actions; ++a)
          if (csr.choice_begin[base + a + 1] > csr.choice_begin[base + a]) ++enabled;
        if (enabled == 0) continue;
        const double share = mass / static_cast<double>(enabled);
        for (std::uint32_t e = csr.choice_begin[base]; e < csr.choice_begin[base + actions]; ++e)
          out[csr.target[e]] += csr.probability[e] * share;
      }
    }
  }

  void joint_predict(std::vector<double>& belief, std::vector<double>& scratch,
                     std::uint32_t action) const {
    for (std::uint32_t s = 0; s < s_; ++s)
      switch_predict(belief.data() + s, scratch.data() + s, s_);
    move(scratch, belief, action);
  }

  double joint(const LoggedRun& run) {
    const std::size_t cells = static_cast<std::size_t>(n_) * s_;
    std::vector<double> belief(cells), scratch(cells);
    for (std::uint32_t i = 0; i < n_; ++i)
      for (std::uint32_t s = 0; s < s_; ++s)
        belief[static_cast<std::size_t>(i) * s_ + s] = m_.prior[i] / s_;
    const bool reward_at_true = m_.noise.reward == RewardFollows::kTrueState;
    double log_l = 0.0;
    for (const LoggedStep& step : run.steps) {
      for (std::uint32_t k = 0; k < step.missing_before; ++k) {
        joint_predict(belief, scratch, kUnknownAction);
        double kept = 0.0;  // mass lost where no action is enabled
        for (double b : belief)
          kept += b;
        if (!(kept > 0.0)) return kMinusInfinity;
        for (double& b : belief)
          b /= kept;
        log_l += std::log(kept);
      }
      joint_predict(belief, scratch, step.action);
      const std::uint32_t o = step.observed_state;
      double evidence = 0.0;
      for (std::uint32_t i = 0; i < n_; ++i) {
        double* row = belief.data() + static_cast<std::size_t>(i) * s_;
        const double at_observed = reward_at_true ? 0.0 : detection(i, o, step.reward);
        for (std::uint32_t s = 0; s < s_; ++s) {
          if (row[s] == 0.0) continue;
          row[s] *=
              observation(o, s) * (reward_at_true ? detection(i, s, step.reward) : at_observed);
          evidence += row[s];
        }
      }
      if (!(evidence > 0.0)) return kMinusInfinity;
      for (double& b : belief)
        b /= evidence;
      log_l += std::log(evidence);
    }
    return log_l;
  }

  const FilterModel& m_;
  const std::vector<double>& switching_;
  std::uint32_t n_;
  std::uint32_t s_;
};

}  // namespace

FilterModel filter_model(const model::CatalogData& catalog, const model::ExplicitModel& model) {
  FilterModel out;
  out.num_contexts = static_cast<std::uint32_t>(catalog.abstractions.size());
  out.num_states = catalog.num_states;
  out.num_actions = catalog.num_actions;
  out.prior = catalog.prior;
  out.state_reward.resize(static_cast<std::size_t>(out.num_contexts) * out.num_states);
  for (std::uint32_t i = 0; i < out.num_contexts; ++i) {
    const model::AbstractionData& abstraction = catalog.abstractions[i];
    for (std::uint32_t s = 0; s < out.num_states; ++s)
      out.state_reward[static_cast<std::size_t>(i) * out.num_states + s] =
          abstraction.block_reward[abstraction.block_of[s]];
  }
  for (const model::Context& context : model.contexts)
    out.transitions.push_back(model::csr_of(model, *context.transitions));
  return out;
}

double log_likelihood(const FilterModel& model, const std::vector<double>& switching,
                      const std::vector<LoggedRun>& runs) {
  return Forward(model, switching).run(runs);
}

std::vector<double> symmetric_switching(std::uint32_t num_contexts, double p_stay) {
  const std::size_t n = num_contexts;
  std::vector<double> matrix(n * n, n > 1 ? (1.0 - p_stay) / static_cast<double>(n - 1) : 0.0);
  for (std::size_t i = 0; i < n; ++i)
    matrix[i * n + i] = n > 1 ? p_stay : 1.0;
  return matrix;
}

}  // namespace oasis::fit
