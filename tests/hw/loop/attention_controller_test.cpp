// The loop's decision step on the linked Go1 catalog: the state vector, the filter's belief,
// the action and its velocity.
#include "loop/attention_controller.hpp"

#include <cmath>
#include <string>

#include <gtest/gtest.h>

#include "go1_treat_catalog.hpp"
#include "spec_controller_settings.hpp"

namespace oasis::hw::loop {
namespace {

PerceptionResult seen_at(double x1, double y1, double x2, double y2, double reward) {
  PerceptionResult result;
  const double positions[2][2] = {{x1, y1}, {x2, y2}};
  for (std::size_t human = 0; human < 2; ++human) {
    result.humans[human].seen = true;
    result.humans[human].x_m = positions[human][0];
    result.humans[human].y_m = positions[human][1];
    result.humans[human].confidence = 1.0;
  }
  result.reward = reward;
  return result;
}

std::uint32_t abstraction_named(const rt::CatalogView& catalog, const std::string& context) {
  for (std::uint32_t i = 0; i < catalog.num_abstractions; ++i)
    if (context == catalog.abstractions[i].context) return i;
  ADD_FAILURE() << "no context " << context;
  return 0;
}

TEST(AttentionController, RewardNextToHumanOneSelectsItsContext) {
  const rt::CatalogView& catalog = go1_treat::catalog();
  AttentionController controller(catalog, spec_settings(catalog));
  const log::StepRecord first = controller.decide(seen_at(2.0, 0.5, 2.0, -0.5, 0.0), 0.0, {});
  EXPECT_EQ(first.step, 0u);
  EXPECT_EQ(first.filter_status, "ok");
  ASSERT_EQ(first.belief.size(), 2u);
  EXPECT_DOUBLE_EQ(first.belief[0] + first.belief[1], 1.0);
  EXPECT_EQ(first.state, (std::vector<double>{2.0, 0.5, 2.0, -0.5}));

  // Human 1 within reach, human 2 far: a reward of 1 is explained by context 1 only.
  const log::StepRecord second = controller.decide(seen_at(0.5, 0.0, 3.0, -1.5, 1.0), 0.2, {});
  const std::uint32_t human1 = abstraction_named(catalog, "human1_holds_treat");
  EXPECT_EQ(second.abstraction, human1);
  EXPECT_EQ(second.abstraction_name, "human1_holds_treat");
  EXPECT_DOUBLE_EQ(second.belief[human1], 1.0);
  EXPECT_EQ(second.action_name, catalog.action_names[second.action]);
}

TEST(AttentionController, FollowsTheHolderWithTheMappedVelocity) {
  const rt::CatalogView& catalog = go1_treat::catalog();
  AttentionController controller(catalog, spec_settings(catalog));
  controller.decide(seen_at(3.0, 0.0, 3.0, 0.0, 0.0), 0.0, {});
  // Human 2 in reach, human 1 far to the left: context 2; its policy keeps human 2 in reach,
  // and the command is the configured velocity of the chosen action.
  const log::StepRecord record = controller.decide(seen_at(3.0, 2.0, 0.6, 0.0, 1.0), 0.2, {});
  EXPECT_EQ(record.abstraction_name, "human2_holds_treat");
  const ControllerSettings settings = spec_settings(catalog);
  EXPECT_FLOAT_EQ(static_cast<float>(record.command.forward_m_s),
                  settings.action_velocity[record.action].forward);
  EXPECT_FLOAT_EQ(static_cast<float>(record.command.yaw_rate_rad_s),
                  settings.action_velocity[record.action].yaw_rate);
}

TEST(AttentionController, UnseenPersonKeepsTheLastPositionOrGoesOutside) {
  const rt::CatalogView& catalog = go1_treat::catalog();
  PerceptionResult gone = seen_at(1.0, 0.2, 2.0, -0.4, 0.0);
  gone.humans[1].seen = false;

  AttentionController holding(catalog, spec_settings(catalog));
  holding.decide(seen_at(1.0, 0.2, 2.5, -1.0, 0.0), 0.0, {});
  EXPECT_EQ(holding.decide(gone, 0.2, {}).state, (std::vector<double>{1.0, 0.2, 2.5, -1.0}));
  // The robot walks 1 m forward: the unseen person, standing still, is now 1 m closer.
  const log::StepRecord walked = holding.decide(gone, 0.4, {1.0, 0.0, 0.0});
  EXPECT_NEAR(walked.state[2], 1.5, 1e-12);
  EXPECT_NEAR(walked.state[3], -1.0, 1e-12);

  ControllerSettings outside = spec_settings(catalog);
  outside.hold_last_seen = false;
  AttentionController dropping(catalog, outside);
  const log::StepRecord record = dropping.decide(gone, 0.0, {});
  EXPECT_TRUE(std::isnan(record.state[2]) && std::isnan(record.state[3]));
  EXPECT_EQ(record.filter_status, "ok");
}

TEST(AttentionController, PeopleOutsideTheDomainArePutAtItsEdge) {
  const rt::CatalogView& catalog = go1_treat::catalog();
  const PerceptionResult beside = seen_at(-0.4, -1.2, 7.0, 3.5, 0.0);
  AttentionController clamping(catalog, spec_settings(catalog));
  EXPECT_EQ(clamping.decide(beside, 0.0, {}).state, (std::vector<double>{0.0, -1.2, 5.0, 3.0}));

  ControllerSettings outside = spec_settings(catalog);
  outside.clamp_to_domain = false;
  AttentionController passing(catalog, outside);
  EXPECT_EQ(passing.decide(beside, 0.0, {}).state, (std::vector<double>{-0.4, -1.2, 7.0, 3.5}));
}

TEST(AttentionController, RefusesVelocitiesThatDoNotCoverTheActions) {
  const rt::CatalogView& catalog = go1_treat::catalog();
  ControllerSettings settings = spec_settings(catalog);
  settings.action_velocity.pop_back();
  EXPECT_THROW(AttentionController(catalog, settings), std::invalid_argument);
}

TEST(AttentionController, RobustModeNeedsTheCatalogsObservationModel) {
  const rt::CatalogView& catalog = go1_treat::catalog();
  ControllerSettings settings = spec_settings(catalog);
  settings.filter.mode = rt::FilterMode::kNoiseAware;
  AttentionController noise_aware(catalog, settings);  // the spec declares its camera
  noise_aware.decide(seen_at(0.6, 0.0, 2.0, -0.5, 1.0), 0.0, {});
  const log::StepRecord second = noise_aware.decide(seen_at(0.6, 0.0, 2.0, -0.5, 1.0), 0.2, {});
  EXPECT_EQ(second.filter_status, "ok");
  EXPECT_EQ(second.abstraction, abstraction_named(catalog, "human1_holds_treat"));
  rt::CatalogView without = catalog;
  without.observation.position = {};
  EXPECT_THROW(AttentionController(without, settings), std::invalid_argument);
}

// Nobody in reach: both contexts predict reward 0, so only the tag seen on human 2 at 2 m says
// who holds the treat. Off (the paper), the belief stays at the prior; on, it is Bayes' rule
// with 0.9 against 0.1.
TEST(AttentionController, ASeenTreatTagWeighsItsHoldersContext) {
  const rt::CatalogView& catalog = go1_treat::catalog();
  const std::uint32_t human2 = abstraction_named(catalog, "human2_holds_treat");
  PerceptionResult tag_on_human2 = seen_at(2.0, 0.8, 2.0, -0.8, 0.0);
  tag_on_human2.holder = TreatHolder::kHuman2;

  AttentionController paper(catalog, spec_settings(catalog));
  paper.decide(tag_on_human2, 0.0, {});
  EXPECT_DOUBLE_EQ(paper.decide(tag_on_human2, 0.2, {}).belief[human2], 0.5);

  ControllerSettings settings = spec_settings(catalog);
  settings.treat_sighting = 0.9;
  AttentionController sighted(catalog, settings);
  EXPECT_NEAR(sighted.decide(tag_on_human2, 0.0, {}).belief[human2], 0.9, 1e-12);
  // Predicted 0.8 * 0.9 + 0.2 * 0.1 = 0.74, then 0.74 * 0.9 / (0.74 * 0.9 + 0.26 * 0.1).
  const log::StepRecord second = sighted.decide(tag_on_human2, 0.2, {});
  EXPECT_NEAR(second.belief[human2], 0.666 / 0.692, 1e-12);
  EXPECT_EQ(second.abstraction, human2);

  settings.treat_sighting = 1.0;
  EXPECT_THROW(AttentionController(catalog, settings), std::invalid_argument);
}

// No tag seen: on human 1 at 2 m, whose tag would show, that weighs "human 1 holds it" by 0.1;
// on human 2, too far for a tag to show, it says nothing.
TEST(AttentionController, NoTagWhereItWouldShowWeighsAgainstThatPerson) {
  const rt::CatalogView& catalog = go1_treat::catalog();
  const std::uint32_t human1 = abstraction_named(catalog, "human1_holds_treat");
  PerceptionResult no_tag = seen_at(2.0, 0.0, 4.5, -1.0, 0.0);
  no_tag.humans[0].tag_would_show = true;

  ControllerSettings settings = spec_settings(catalog);
  settings.tag_unseen_likelihood = 0.1;
  AttentionController controller(catalog, settings);
  EXPECT_NEAR(controller.decide(no_tag, 0.0, {}).belief[human1], 0.05 / 0.55, 1e-12);
  no_tag.humans[0].tag_would_show = false;
  const double before = controller.decide(no_tag, 0.2, {}).belief[human1];
  EXPECT_NEAR(before, 0.8 * (0.05 / 0.55) + 0.2 * (0.5 / 0.55), 1e-12);  // prediction only

  settings.tag_unseen_likelihood = 0.0;
  EXPECT_THROW(AttentionController(catalog, settings), std::invalid_argument);
}

// Human 1 at 0.4 m, in reach but too near for a tag to be in the image: perception says the
// reward is not known. The paper's controller reads 0 (human 1 does not hold the treat); with
// unknown_reward_when_tag_cut the filter is given NaN and predicts only.
TEST(AttentionController, AnUnknownRewardIsNotTakenForZero) {
  const rt::CatalogView& catalog = go1_treat::catalog();
  const std::uint32_t human1 = abstraction_named(catalog, "human1_holds_treat");
  PerceptionResult too_near = seen_at(0.4, 0.0, 3.0, -1.5, 0.0);
  too_near.reward_known = false;

  ControllerSettings settings = spec_settings(catalog);
  settings.filter.zero_likelihood_guard = true;
  AttentionController paper(catalog, settings);
  paper.decide(too_near, 0.0, {});
  const log::StepRecord ruled_out = paper.decide(too_near, 0.2, {});
  EXPECT_DOUBLE_EQ(ruled_out.belief[human1], 0.0);
  EXPECT_EQ(ruled_out.reward, 0.0);

  settings.filter.mode = rt::FilterMode::kNoiseAware;
  settings.unknown_reward_when_tag_cut = true;
  AttentionController careful(catalog, settings);
  careful.decide(too_near, 0.0, {});
  const log::StepRecord unknown = careful.decide(too_near, 0.2, {});
  EXPECT_EQ(unknown.filter_status, "missing_observation");
  EXPECT_DOUBLE_EQ(unknown.belief[human1], 0.5);
  EXPECT_TRUE(std::isnan(unknown.reward));
}

}  // namespace
}  // namespace oasis::hw::loop
