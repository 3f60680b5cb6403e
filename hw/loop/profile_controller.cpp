#include "loop/profile_controller.hpp"

#include <stdexcept>

#include "loop/oracle_controller.hpp"

namespace oasis::hw::loop {

ControllerSettings with_profile(ControllerSettings base,
                                const settings::ControllerProfile& profile) {
  base.filter = profile.filter;
  base.treat_sighting = profile.evidence.treat_sighting;
  base.tag_unseen_likelihood = profile.evidence.tag_unseen_likelihood;
  base.unknown_reward_when_tag_cut = profile.evidence.unknown_reward_when_tag_cut;
  return base;
}

std::unique_ptr<LoopController> make_controller(const settings::ControllerProfile& profile,
                                                const ControllerInputs& inputs) {
  if (profile.kind == settings::ControllerKind::kOracle) {
    if (!inputs.truth)
      throw std::invalid_argument("controller " + profile.name +
                                  " is told the true context, which only oasis-go1 sim knows");
    return std::make_unique<OracleController>(inputs.catalog, inputs.settings, inputs.truth);
  }
  if (const std::string problem =
          settings::validate_profile_against_catalog(profile, inputs.catalog);
      !problem.empty())
    throw std::invalid_argument(problem);
  return std::make_unique<AttentionController>(inputs.catalog,
                                               with_profile(inputs.settings, profile));
}

}  // namespace oasis::hw::loop
