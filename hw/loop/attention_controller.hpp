#pragma once
// One decision of the loop: perception's result in; the filter's belief, the chosen
// abstraction, the catalog action and the velocity that carries it out. The state the filter
// sees is the spec's (x1, y1, x2, y2): each person's robot-frame position.
//
// A person perception did not see keeps their last seen place (`hold_last_seen`, the default:
// people do not vanish, they leave the view), held in the odometry frame, so that as the robot
// turns and walks the held position moves in the robot's frame as a standing person's would.
// Otherwise they are put outside the catalog's domain (NaN coordinates: the outside block of
// every abstraction). Someone never seen is outside.
//
// A person seen outside the catalog's domain (the spec's x in [0, 5], y in [-3, 3]: beside or
// behind the robot, or far away) is put at the domain's nearest edge (`clamp_to_domain`, the
// default), so that the policy turns toward or walks to them; the outside block's action would
// otherwise be the same wherever they are.
#include <array>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "go1/motion_limits.hpp"
#include "go1/planar_pose.hpp"
#include "log/step_record.hpp"
#include "loop/loop_controller.hpp"
#include "oasis/rt/attention_filter.hpp"
#include "oasis/rt/catalog_view.hpp"
#include "perception/perception.hpp"

namespace oasis::hw::loop {

struct ControllerSettings {
  rt::FilterOptions filter;
  std::vector<go1::VelocityCommand> action_velocity;  // indexed by the catalog's action
  bool hold_last_seen = true;
  bool clamp_to_domain = true;
  // 0: the paper (the tag only decides the reward). In (0, 1): perception naming the treat's
  // holder is a second measurement of the step, right with this probability: the filter
  // weighs "human N holds the treat" by it and every other context by 1 - it
  // (rt::AttentionFilter::weigh_context). A hidden or unseen tag says nothing.
  double treat_sighting = 0.0;
  // 1: the paper (no tag seen says nothing of who holds it). In (0, 1): p(no tag seen | this
  // person holds the treat and their tag would show), hidden or turned away: with no tag seen,
  // "human N holds the treat" is weighed by it for each person whose tag would show
  // (HumanEstimate::tag_would_show), every other context by 1.
  double tag_unseen_likelihood = 1.0;
  // False: the paper (no tag seen is reward 0). True: when perception says the reward is not
  // known (PerceptionResult::reward_known: someone in reach whose tag would be out of the
  // image), the filter is given a NaN reward: robust mode then runs the prediction alone; paper
  // mode finds no abstraction matching (the guard keeps the prediction, else the prior).
  bool unknown_reward_when_tag_cut = false;
};

class AttentionController final : public LoopController {
 public:
  // Throws std::invalid_argument when the catalog is not a 4-variable continuous one, the
  // velocities do not cover its actions, or the filter refuses the options.
  AttentionController(const rt::CatalogView& catalog, ControllerSettings settings);
  AttentionController(const AttentionController&) = delete;
  AttentionController& operator=(const AttentionController&) = delete;

  // The first call starts the filter (Algorithm 1's initialisation: the prior, the state
  // located); later calls run one filter step with the previous decision's action.
  // `robot` is the robot's odometry pose when the frame was taken.
  log::StepRecord decide(const PerceptionResult& seen, double time_s,
                         const go1::Pose& robot) override;

  const rt::CatalogView& catalog() const { return catalog_; }

 private:
  void update_state(const PerceptionResult& seen, const go1::Pose& robot);
  void weigh_tag_evidence(const PerceptionResult& seen);

  const rt::CatalogView& catalog_;
  ControllerSettings settings_;
  std::vector<double> workspace_;
  rt::AttentionFilter filter_;
  std::vector<double> state_;
  std::vector<double> domain_low_;  // per state variable, over every abstraction's grid
  std::vector<double> domain_high_;
  std::vector<double> tag_likelihood_;  // per abstraction, for weigh_context
  std::array<std::optional<std::uint32_t>, 2> context_of_holder_;  // "human N holds the treat"
  std::array<std::optional<go1::PlanarPoint>, 2> last_seen_;       // odometry frame
  std::uint64_t steps_ = 0;
  std::uint32_t last_action_ = 0;
};

}  // namespace oasis::hw::loop
