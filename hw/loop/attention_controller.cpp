#include "loop/attention_controller.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <utility>

#include "loop/treat_contexts.hpp"

namespace oasis::hw::loop {
namespace {

constexpr std::size_t kStateDimension = 4;  // x1 y1 x2 y2, specs/go1_treat.oasis

const rt::CatalogView& checked(const rt::CatalogView& catalog, const ControllerSettings& settings) {
  if (catalog.state_dimension != kStateDimension)
    throw std::invalid_argument(
        "the catalog must have the Go1 spec's 4 continuous variables (x1 y1 x2 y2), it has " +
        std::to_string(catalog.state_dimension));
  if (settings.action_velocity.size() != catalog.num_actions)
    throw std::invalid_argument("the loop has velocities for " +
                                std::to_string(settings.action_velocity.size()) +
                                " actions, the catalog has " + std::to_string(catalog.num_actions));
  return catalog;
}

std::string filter_error_text(rt::FilterError error) {
  switch (error) {
    case rt::FilterError::kNone:
      return "no error";
    case rt::FilterError::kWorkspaceTooSmall:
      return "workspace too small";
    case rt::FilterError::kNoRobustSection:
      return "filter.mode needs the catalog's noise model, which it lacks; use paper";
    case rt::FilterError::kWrongCatalogKind:
      return "filter.mode joint is for discrete catalogs and noise_aware for continuous ones";
    case rt::FilterError::kBadOptions:
      return "a filter option is out of range";
    case rt::FilterError::kEmptyCatalog:
      return "the catalog is empty";
  }
  return "unknown filter error";
}

// The box every abstraction's grid covers, per state variable (unbounded where no grid
// reaches).
void domain_of(const rt::CatalogView& catalog, std::vector<double>& low,
               std::vector<double>& high) {
  low.assign(catalog.state_dimension, -std::numeric_limits<double>::infinity());
  high.assign(catalog.state_dimension, std::numeric_limits<double>::infinity());
  for (std::uint32_t i = 0; i < catalog.num_abstractions; ++i) {
    const rt::GridView& grid = catalog.abstractions[i].grid;
    for (std::uint32_t k = 0; k < grid.dimension; ++k) {
      const std::uint32_t axis = grid.axes[k];
      low[axis] = std::max(low[axis], grid.breaks[grid.break_begin[k]]);
      high[axis] = std::min(high[axis], grid.breaks[grid.break_begin[k + 1] - 1]);
    }
  }
}

}  // namespace

AttentionController::AttentionController(const rt::CatalogView& catalog,
                                         ControllerSettings settings)
    : catalog_(checked(catalog, settings)),
      settings_(std::move(settings)),
      workspace_(rt::AttentionFilter::workspace_size(catalog_, settings_.filter)),
      filter_(catalog_, settings_.filter, workspace_.data(), workspace_.size()),
      state_(kStateDimension, std::numeric_limits<double>::quiet_NaN()) {
  if (!filter_.ok()) throw std::invalid_argument(filter_error_text(filter_.error()));
  if (!(settings_.treat_sighting >= 0.0 && settings_.treat_sighting < 1.0))
    throw std::invalid_argument("treat_sighting must be in [0, 1)");
  if (!(settings_.tag_unseen_likelihood > 0.0 && settings_.tag_unseen_likelihood <= 1.0))
    throw std::invalid_argument("tag_unseen_likelihood must be in (0, 1]");
  domain_of(catalog_, domain_low_, domain_high_);
  tag_likelihood_.assign(catalog_.num_abstractions, 1.0);
  context_of_holder_ = {context_index(catalog_, TreatHolder::kHuman1),
                        context_index(catalog_, TreatHolder::kHuman2)};
}

// What the treat tag says beyond the reward (ControllerSettings::treat_sighting and
// tag_unseen_likelihood); nothing to weigh on a catalog without the Go1 spec's contexts.
void AttentionController::weigh_tag_evidence(const PerceptionResult& seen) {
  if (seen.holder != TreatHolder::kNone) {
    const std::optional<std::uint32_t> named = context_of_holder_[person_of_holder(seen.holder)];
    if (settings_.treat_sighting == 0.0 || !named) return;
    std::fill(tag_likelihood_.begin(), tag_likelihood_.end(), 1.0 - settings_.treat_sighting);
    tag_likelihood_[*named] = settings_.treat_sighting;
    filter_.weigh_context(tag_likelihood_.data(), tag_likelihood_.size());
    return;
  }
  if (settings_.tag_unseen_likelihood >= 1.0) return;  // 1: absence says nothing
  std::fill(tag_likelihood_.begin(), tag_likelihood_.end(), 1.0);
  bool informative = false;
  for (std::size_t person = 0; person < 2; ++person) {
    if (!context_of_holder_[person] || !seen.humans[person].tag_would_show) continue;
    tag_likelihood_[*context_of_holder_[person]] = settings_.tag_unseen_likelihood;
    informative = true;
  }
  if (informative) filter_.weigh_context(tag_likelihood_.data(), tag_likelihood_.size());
}

void AttentionController::update_state(const PerceptionResult& seen, const go1::Pose& robot) {
  for (std::size_t human = 0; human < 2; ++human) {
    const HumanEstimate& estimate = seen.humans[human];
    if (estimate.seen)
      last_seen_[human] = go1::to_odometry_frame(robot, {estimate.x_m, estimate.y_m});
    std::optional<go1::PlanarPoint> place;
    if (estimate.seen)
      place = go1::PlanarPoint{estimate.x_m, estimate.y_m};
    else if (settings_.hold_last_seen && last_seen_[human])
      place = go1::to_body_frame(robot, *last_seen_[human]);
    state_[2 * human] = place ? place->x : std::numeric_limits<double>::quiet_NaN();
    state_[2 * human + 1] = place ? place->y : std::numeric_limits<double>::quiet_NaN();
  }
  if (!settings_.clamp_to_domain) return;
  for (std::size_t k = 0; k < state_.size(); ++k)  // std::clamp keeps NaN: unseen stays outside
    if (!std::isnan(state_[k])) state_[k] = std::clamp(state_[k], domain_low_[k], domain_high_[k]);
}

log::StepRecord AttentionController::decide(const PerceptionResult& seen, double time_s,
                                            const go1::Pose& robot) {
  update_state(seen, robot);
  const double reward = seen.reward_known || !settings_.unknown_reward_when_tag_cut
                            ? seen.reward
                            : std::numeric_limits<double>::quiet_NaN();
  const rt::StepStatus status =
      steps_ == 0 ? filter_.start(state_.data(), state_.size())
                  : filter_.step(state_.data(), state_.size(), reward, last_action_);
  weigh_tag_evidence(seen);

  log::StepRecord record;
  record.step = steps_++;
  record.time_s = time_s;
  for (std::size_t human = 0; human < 2; ++human) {
    const HumanEstimate& estimate = seen.humans[human];
    record.humans[human] = {estimate.seen, estimate.x_m, estimate.y_m, estimate.confidence};
  }
  record.state = state_;
  record.holder = static_cast<int>(seen.holder);
  record.reward = reward;  // as the filter was given it
  record.belief.assign(filter_.beliefs(), filter_.beliefs() + catalog_.num_abstractions);
  record.abstraction = filter_.ml_abstraction();
  record.abstraction_name = catalog_.abstractions[record.abstraction].context;
  record.filter_status = rt::step_status_name(status);

  // No enabled action in the block (never for the shipped spec, whose every action is enabled
  // everywhere): stand still and say so, rather than guess.
  const std::uint32_t action = filter_.action();
  record.action = action;
  if (action == rt::kNoAction) {
    record.action_name = "none";
  } else {
    record.action_name = catalog_.action_names[action];
    const go1::VelocityCommand& velocity = settings_.action_velocity[action];
    record.command = {velocity.forward, velocity.lateral, velocity.yaw_rate};
    last_action_ = action;
  }
  return record;
}

}  // namespace oasis::hw::loop
