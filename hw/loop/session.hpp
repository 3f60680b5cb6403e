#pragma once
// What `oasis-go1 run` and `replay` assemble from the settings before the loop starts: the
// catalog (linked or loaded), the robot link (the Go1 or a dry run), the frame source
// (synthetic world, live camera, recording), and the ground truth when the source knows it.
// Each part fails here, before anything moves, with an error that says what to check.
#include <chrono>
#include <functional>
#include <memory>
#include <optional>
#include <stdexcept>
#include <string>

#include "log/step_record.hpp"
#include "loop/attention_controller.hpp"
#include "loop/robot_link.hpp"
#include "oasis/rt/catalog_file.hpp"
#include "perception/frame.hpp"
#include "perception/treat_holder.hpp"
#include "settings/controller_profile.hpp"
#include "settings/settings.hpp"

namespace oasis::hw::loop {

// An error that ends oasis-go1 with status 1 before (or instead of) running the loop.
class SetupError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// The settings in `file`, or the built-in defaults (equal to hw/config/go1.yaml) when it is
// empty. Throws settings::SettingsError.
settings::Go1Settings settings_or_defaults(const std::string& file);

// The value of a --source option: synthetic, camera or recorded:DIR. Throws SetupError.
settings::FrameSourceSetting source_option(const std::string& text);

// The catalog the loop runs: the one linked into oasis-go1, or a .bin file, compiled from the
// spec `spec_setting` names (LoopSettings::catalog_spec: "linked", a .oasis path, or "any").
// Throws SetupError when the file cannot be loaded or was compiled from another spec.
class SessionCatalog {
 public:
  SessionCatalog(const std::string& setting, const std::string& spec_setting);
  const rt::CatalogView& view() const { return *view_; }
  std::string describe() const { return description_; }

 private:
  rt::LoadedCatalog loaded_;
  const rt::CatalogView* view_ = nullptr;
  std::string description_;
};

// The robot-side part of the controller's settings (action velocities, missing people, the
// domain clamp) from the settings; the profile's options go on top (with_profile()). Throws
// SetupError when the actions do not match the catalog's.
ControllerSettings controller_settings(const settings::Go1Settings& settings,
                                       const rt::CatalogView& catalog);

// The controller profile `run` and `replay` drive with: a shipped profile by name or a .yaml
// path (loop.controller, or --controller). Throws SetupError when there is no such profile,
// or it cannot drive a robot (the oracle, a no-attention baseline). Whether it fits the
// catalog, make_controller() checks (profile_controller.hpp).
settings::ControllerProfile robot_profile(const std::string& name_or_path);

// The Go1 link after the robot answered, or a dry run. Throws SetupError when the robot does
// not answer within `robot_timeout` (the sender meanwhile only ever commanded stand).
std::unique_ptr<RobotLink> open_link(const settings::Go1Settings& settings, bool dry_run,
                                     std::chrono::milliseconds robot_timeout);

struct SessionSource {
  std::unique_ptr<FrameSource> source;
  // The ground truth of the frame just taken, for the log: the synthetic world knows it. A
  // recording knows only the holder, not the true reward, so its log has no truth column.
  std::function<std::optional<log::GroundTruth>()> truth;
  // Who truly held the treat in the frame just taken (recordings written from the synthetic
  // world keep it); empty when unknown.
  std::function<std::optional<TreatHolder>()> true_holder;
  bool realtime_only = false;  // a live camera: frames come at the camera's pace anyway
  std::string description;
};

// Opens settings.source. The synthetic world sees the robot where `link` says it is. Throws
// SetupError (a missing camera, a bad recording).
SessionSource open_source(const settings::Go1Settings& settings, const rt::CatalogView& catalog,
                          RobotLink& link);

}  // namespace oasis::hw::loop
