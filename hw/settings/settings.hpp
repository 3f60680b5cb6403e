// The configuration of oasis-go1: everything the 5 Hz loop camera -> perception -> filter ->
// policy -> link needs, read from one YAML file (hw/config/go1.yaml holds the defaults).
//
// Every key is validated where it is read, and an error names the file, line, column and key:
//   go1.yaml:4:9: error: robot.port: expected an integer in 1..65535, got "80x2"
// An absent key keeps its default, so a file may hold only what differs from go1.yaml; an
// unknown key is an error (a typo must not silently keep a default). The YAML layout, key by
// key, is in schema.hpp; README.md says where each default comes from.
#pragma once

#include <chrono>
#include <filesystem>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "camera/live_camera_options.hpp"
#include "go1/motion_limits.hpp"
#include "go1/sender.hpp"
#include "oasis/rt/attention_filter.hpp"
#include "oasis/rt/catalog_view.hpp"
#include "perception/perception.hpp"
#include "settings/controller_profile.hpp"
#include "settings/settings_error.hpp"

namespace oasis::hw::settings {

// The velocity the robot walks at while the policy's action `action` is in force.
struct ActionVelocity {
  std::string action;  // a catalog action name
  go1::VelocityCommand velocity;

  bool operator==(const ActionVelocity&) const = default;
};

// The six actions of specs/go1_treat.oasis: one step is 0.2 s, walking moves 0.1 m per step
// (0.5 m/s) and turning 0.1 rad per step (0.5 rad/s); left is counter-clockwise, a positive
// yaw rate.
std::vector<ActionVelocity> spec_actions();

// What the filter is given for a person perception did not see this step.
enum class MissingHuman {
  kHoldLast,  // their last seen position (before they were first seen: as kOutside)
  kOutside,   // a position outside the spec's domain, so the filter locates them "outside"
};

// The sender's own defaults (go1/sender.hpp), go1::kDefaultWatchdogTimeout included: between
// its 5 Hz decisions the loop repeats the current command every loop.keepalive_ms (50 ms), so
// the watchdog fires only when the loop stalls, and the robot stops one timeout after it did.
go1::SenderOptions default_link_options();

// Where frames come from.
struct FrameSourceSetting {
  enum class Kind { kSynthetic, kCamera, kRecorded };
  Kind kind = Kind::kCamera;
  std::string directory;  // kRecorded only: the recorded sequence's folder

  bool operator==(const FrameSourceSetting&) const = default;
};

// The text of a source as the YAML `source:` key (or a command-line flag) spells it:
// "synthetic", "camera" or "recorded:DIR". Nothing if the text is none of these.
std::optional<FrameSourceSetting> parse_frame_source(std::string_view text);
std::string to_string(const FrameSourceSetting& source);

inline constexpr std::string_view kLinkedCatalog = "linked";
inline constexpr std::string_view kAnyCatalogSpec = "any";

struct LoopSettings {
  double rate_hz = 5.0;  // the spec's `period 0.2`
  // "linked": the catalog compiled into oasis-go1; otherwise a path to a .bin catalog file.
  std::string catalog = std::string(kLinkedCatalog);
  // The spec the catalog must have been compiled from, checked by its spec hash: "linked"
  // (the spec of the linked catalog, specs/go1_treat.oasis as this program was built), a path
  // to a .oasis spec, or "any" (no check). A catalog left behind by an edited spec is refused.
  std::string catalog_spec = std::string(kLinkedCatalog);
  std::vector<ActionVelocity> actions = spec_actions();  // one per catalog action name
  MissingHuman missing_human = MissingHuman::kHoldLast;
  // A person seen outside the catalog's domain is put at its nearest edge
  // (loop/attention_controller.hpp).
  bool clamp_to_domain = true;
  // Between decisions the loop repeats its command this often, so the watchdog only fires when
  // the loop itself stalls (loop/control_loop.hpp).
  std::chrono::milliseconds keepalive{50};
  // The controller: a profile of hw/config/controllers/ by name, or a path to a .yaml profile
  // (controller_profile.hpp): the filter's options and the tag evidence live there, so that
  // `sim`, `run` and `replay` read the same ones.
  std::string controller = std::string(kDefaultController);
};

struct Go1Settings {
  go1::SenderOptions link = default_link_options();  // YAML robot: and limits: (link.limits)
  camera::LiveCameraOptions camera;
  PerceptionConfig perception;  // YAML perception:, and camera.mount: (perception.mount)
  LoopSettings loop;            // YAML loop:, and actions: (loop.actions)
  FrameSourceSetting source;
};

// The defaults: the same as a value-initialised Go1Settings, and as hw/config/go1.yaml.
Go1Settings default_settings();

// Reads a settings file. Throws SettingsError (every problem found, each with its line,
// column and key) if the file cannot be read, is not YAML, is not a mapping, or holds a key
// that is unknown, of the wrong type or out of range.
Go1Settings load_settings(const std::filesystem::path& file);

// The same for YAML text; `file_name` is used in messages only.
Go1Settings parse_settings(std::string_view yaml_text, std::string_view file_name);

// Every key with its value and a comment (for `oasis-go1 config`). parse_settings()
// reads it back to equal settings; settings_to_yaml(default_settings()) is hw/config/go1.yaml.
std::string settings_to_yaml(const Go1Settings& settings);

// The problems parse_settings() would report for these values (ranges, and the checks across
// keys such as actions within limits), without file positions: for settings changed in code.
std::vector<Diagnostic> check_settings(const Go1Settings& settings);

// The keys whose values differ, as dotted paths ("robot.port", "actions.left.yaw_rate"); a key
// in only one of the two counts as differing. Actions are compared by name, not by order.
std::vector<std::string> differing_keys(const Go1Settings& a, const Go1Settings& b);

inline bool operator==(const Go1Settings& a, const Go1Settings& b) {
  return differing_keys(a, b).empty();
}

// Checks the settings against the catalog the loop will run: every catalog action must have a
// velocity and every velocity must name a catalog action. Returns one line per problem (naming
// both action lists), or "". (The controller's own check: validate_profile_against_catalog.)
std::string validate_against_catalog(const Go1Settings& settings, const rt::CatalogView& catalog);

// The velocity of each catalog action, indexed like catalog.action_names. Throws
// std::invalid_argument with validate_against_catalog()'s text if an action has no velocity
// or a velocity names no catalog action.
std::vector<go1::VelocityCommand> velocity_table(const Go1Settings& settings,
                                                 const rt::CatalogView& catalog);

}  // namespace oasis::hw::settings
