// The shipped controller profiles' YAML texts, compiled in from hw/config/controllers/ by CMake
// (the generated shipped_profiles.cpp in the build tree), in the order tables list them.
#pragma once

#include <span>

namespace oasis::hw::settings::detail {

struct ShippedProfileText {
  const char* name;  // "ours"
  const char* path;  // "hw/config/controllers/ours.yaml", for messages
  const char* text;  // the file's contents
};

std::span<const ShippedProfileText> shipped_profile_texts();

}  // namespace oasis::hw::settings::detail
