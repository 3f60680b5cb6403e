#pragma once
// The loop controller a controller profile (settings/controller_profile.hpp) describes, for
// `sim`, `run` and `replay` alike: the attention filter with the profile's options and tag
// evidence, or (sim only) the oracle told the true context. The robot-side settings (action
// velocities, missing people, the domain clamp) come from the session's ControllerSettings.
#include <cstdint>
#include <functional>
#include <memory>
#include <optional>

#include "loop/attention_controller.hpp"
#include "loop/loop_controller.hpp"
#include "settings/controller_profile.hpp"

namespace oasis::hw::loop {

// `base` with the profile's filter options and tag evidence.
ControllerSettings with_profile(ControllerSettings base,
                                const settings::ControllerProfile& profile);

struct ControllerInputs {
  const rt::CatalogView& catalog;
  ControllerSettings settings;  // from oasis-go1's settings; the profile's options go on top
  // The index of the true context of the frame just taken: only a simulator knows it, and only
  // the oracle may call it. Empty on a robot.
  std::function<std::optional<std::uint32_t>()> truth;
};

// The controller. Throws std::invalid_argument when the profile cannot run here: the oracle
// without a truth, or a filter mode the catalog has no noise model for.
std::unique_ptr<LoopController> make_controller(const settings::ControllerProfile& profile,
                                                const ControllerInputs& inputs);

}  // namespace oasis::hw::loop
