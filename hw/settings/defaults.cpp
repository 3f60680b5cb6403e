#include "settings/settings.hpp"

namespace oasis::hw::settings {

std::vector<ActionVelocity> spec_actions() {
  constexpr float kWalk = 0.5f;  // 0.1 m per 0.2 s step
  constexpr float kTurn = 0.5f;  // 0.1 rad per step; + is counter-clockwise, a left turn
  return {
      {"left", {0.0f, 0.0f, kTurn}},
      {"right", {0.0f, 0.0f, -kTurn}},
      {"straight", {kWalk, 0.0f, 0.0f}},
      {"left_straight", {kWalk, 0.0f, kTurn}},
      {"right_straight", {kWalk, 0.0f, -kTurn}},
      {"stop", {0.0f, 0.0f, 0.0f}},
  };
}

go1::SenderOptions default_link_options() {
  return go1::SenderOptions{};
}

Go1Settings default_settings() {
  return Go1Settings{};
}

}  // namespace oasis::hw::settings
