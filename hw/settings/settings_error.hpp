// The settings' errors are the schema engine's (yaml_schema/settings_error.hpp): every problem
// of a settings file, in the compiler format. Named here so that users of the settings need
// not know the engine.
#pragma once

#include "yaml_schema/settings_error.hpp"

namespace oasis::hw::settings {

using yaml_schema::Diagnostic;
using yaml_schema::format_diagnostic;
using yaml_schema::SettingsError;

}  // namespace oasis::hw::settings
