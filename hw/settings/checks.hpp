// The checks that span keys (an action's speed against limits:, the principal point against
// the image size, ...) and the per-item checks shared by the reader and check_settings().
#pragma once

#include <string>
#include <string_view>
#include <vector>

#include "settings/settings.hpp"
#include "yaml_schema/cross_problem.hpp"

namespace oasis::hw::settings::detail {

using yaml_schema::CrossProblem;

// Every cross-key problem of settings whose keys are each valid on their own.
std::vector<CrossProblem> cross_check(const Go1Settings& settings);

// "" if the band is usable: whole numbers, hue 0..179, saturation and value 0..255, and
// low <= high in every channel; else what is wrong.
std::string band_problem(const HsvBand& band);

// An action name as the spec language spells identifiers: [A-Za-z_][A-Za-z0-9_]*.
bool is_action_name(std::string_view name);

// The components of one action entry, in order.
inline constexpr std::string_view kActionComponents[] = {"forward", "lateral", "yaw_rate"};

}  // namespace oasis::hw::settings::detail
