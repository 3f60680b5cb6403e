#pragma once
// The controller settings oasis-go1 runs with by default: the spec's action velocities as the
// shipped settings give them (hw/config/go1.yaml), for the linked Go1 catalog.
#include "loop/attention_controller.hpp"
#include "settings/settings.hpp"

namespace oasis::hw::loop {

inline ControllerSettings spec_settings(const rt::CatalogView& catalog) {
  ControllerSettings settings;
  settings.action_velocity = settings::velocity_table(settings::default_settings(), catalog);
  return settings;
}

}  // namespace oasis::hw::loop
