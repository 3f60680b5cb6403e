// The Go1 settings' own codecs (go1_codecs.hpp) and the frame source's text.

#include "settings/go1_codecs.hpp"

#include "settings/controller_profile.hpp"
#include "settings/shipped_profiles.hpp"

namespace oasis::hw::settings::detail {

bool CatalogCodec::parse(std::string_view text, std::string& out) const {
  const bool bin = text.size() > 4 && text.substr(text.size() - 4) == ".bin";
  if (text != kLinkedCatalog && !bin) return false;
  out = std::string(text);
  return true;
}

bool CatalogSpecCodec::parse(std::string_view text, std::string& out) const {
  const bool spec = text.size() > 6 && text.substr(text.size() - 6) == ".oasis";
  if (text != kLinkedCatalog && text != kAnyCatalogSpec && !spec) return false;
  out = std::string(text);
  return true;
}

std::string ControllerCodec::expected() const {
  return "a controller profile (" + shipped_profile_names() + ") or a path to a .yaml profile";
}

bool ControllerCodec::parse(std::string_view text, std::string& out) const {
  bool known = is_profile_path(text);
  for (const std::string& name : spellings())
    known = known || name == text;
  if (!known) return false;
  out = std::string(text);
  return true;
}

std::vector<std::string> ControllerCodec::spellings() const {
  std::vector<std::string> names;
  for (const detail::ShippedProfileText& shipped : shipped_profile_texts())
    names.push_back(shipped.name);
  return names;
}

bool SourceCodec::parse(std::string_view text, FrameSourceSetting& out) const {
  constexpr std::string_view kRecorded = "recorded:";
  if (text == "synthetic") {
    out = {FrameSourceSetting::Kind::kSynthetic, {}};
  } else if (text == "camera") {
    out = {FrameSourceSetting::Kind::kCamera, {}};
  } else if (text.size() > kRecorded.size() && text.substr(0, kRecorded.size()) == kRecorded) {
    out = {FrameSourceSetting::Kind::kRecorded, std::string(text.substr(kRecorded.size()))};
  } else {
    return false;
  }
  return true;
}

std::string SourceCodec::format(const FrameSourceSetting& value) const {
  return yaml_string(to_string(value));
}

}  // namespace oasis::hw::settings::detail

namespace oasis::hw::settings {

std::optional<FrameSourceSetting> parse_frame_source(std::string_view text) {
  FrameSourceSetting source;
  if (!detail::SourceCodec{}.parse(text, source)) return std::nullopt;
  return source;
}

std::string to_string(const FrameSourceSetting& source) {
  switch (source.kind) {
    case FrameSourceSetting::Kind::kSynthetic:
      return "synthetic";
    case FrameSourceSetting::Kind::kCamera:
      return "camera";
    case FrameSourceSetting::Kind::kRecorded:
      return "recorded:" + source.directory;
  }
  return "?";
}

}  // namespace oasis::hw::settings
