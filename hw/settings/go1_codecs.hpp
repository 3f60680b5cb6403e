// The codecs of the Go1 settings' own kinds of scalar (the catalog, the spec it comes from,
// the controller profile, the frame source), beside the engine's general ones
// (yaml_schema/codecs.hpp), which schema.hpp and profile_schema.hpp use by their plain names.
#pragma once

#include <string>
#include <string_view>
#include <vector>

#include "settings/settings.hpp"
#include "yaml_schema/codecs.hpp"

namespace oasis::hw::settings::detail {

// The settings' schemas are written in the engine's vocabulary (codecs, visitors, CrossProblem).
using namespace yaml_schema;

// "linked", or a path to a .bin catalog file.
struct CatalogCodec {
  std::string expected() const { return "linked, or a path to a .bin catalog file"; }
  bool parse(std::string_view text, std::string& out) const;
  std::string format(const std::string& value) const { return yaml_string(value); }
};

// "linked", "any", or a path to a .oasis spec: what a catalog must have been compiled from.
struct CatalogSpecCodec {
  std::string expected() const { return "linked, any, or a path to a .oasis spec"; }
  bool parse(std::string_view text, std::string& out) const;
  std::string format(const std::string& value) const { return yaml_string(value); }
};

// A controller profile: the name of a shipped one (hw/config/controllers/), or a path to a
// .yaml profile (controller_profile.hpp).
struct ControllerCodec {
  std::string expected() const;
  bool parse(std::string_view text, std::string& out) const;
  std::string format(const std::string& value) const { return yaml_string(value); }
  std::vector<std::string> spellings() const;
};

// "synthetic", "camera", or "recorded:DIR".
struct SourceCodec {
  std::string expected() const { return "synthetic, camera, or recorded:DIR"; }
  bool parse(std::string_view text, FrameSourceSetting& out) const;
  std::string format(const FrameSourceSetting& value) const;
  std::vector<std::string> spellings() const { return {"synthetic", "camera"}; }
};

}  // namespace oasis::hw::settings::detail
