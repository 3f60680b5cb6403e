#include "loop/session.hpp"

#include <cstdint>
#include <filesystem>
#include <optional>
#include <stdexcept>

#include "camera/camera_error.hpp"
#include "camera/live_camera.hpp"
#include "camera/recorded_source.hpp"
#include "files/input_file.hpp"
#include "go1/link_error.hpp"
#include "go1_treat_catalog.hpp"
#include "loop/go1_link.hpp"
#include "loop/synthetic_world.hpp"
#include "loop/treat_contexts.hpp"
#include "oasis/rt/spec_hash.hpp"

namespace oasis::hw::loop {
namespace {

SessionSource synthetic_source(const settings::Go1Settings& settings,
                               const rt::CatalogView& catalog, RobotLink& link) {
  SyntheticWorldSettings world;
  world.period_s = 1.0 / settings.loop.rate_hz;
  world.render.intrinsics = settings.camera.intrinsics;
  world.render.depth_scale_m_per_unit = settings.camera.depth_scale_m_per_unit;
  world.render.mount = settings.perception.mount;
  world.reach = settings.perception.reach;
  auto source = std::make_unique<SyntheticWorld>(world, [&link] { return link.pose(); });
  SessionSource session;
  session.description = "synthetic world (two people, the treat handed over at 12 s and 24 s)";
  const std::optional<std::uint32_t> human1 = context_index(catalog, TreatHolder::kHuman1);
  const std::optional<std::uint32_t> human2 = context_index(catalog, TreatHolder::kHuman2);
  if (human1 && human2) {
    session.truth = [world = source.get(), one = *human1,
                     two = *human2]() -> std::optional<log::GroundTruth> {
      const std::optional<WorldTruth>& truth = world->truth_of_last_frame();
      if (!truth || truth->holder == TreatHolder::kNone) return std::nullopt;
      return log::GroundTruth{truth->holder == TreatHolder::kHuman1 ? one : two,
                              truth->holder_in_reach ? 1.0 : 0.0};
    };
  }
  session.true_holder = [world = source.get()]() -> std::optional<TreatHolder> {
    const std::optional<WorldTruth>& truth = world->truth_of_last_frame();
    if (!truth) return std::nullopt;
    return truth->holder;
  };
  session.source = std::move(source);
  return session;
}

}  // namespace

settings::Go1Settings settings_or_defaults(const std::string& file) {
  return file.empty() ? settings::default_settings() : settings::load_settings(file);
}

settings::FrameSourceSetting source_option(const std::string& text) {
  const std::optional<settings::FrameSourceSetting> source = settings::parse_frame_source(text);
  if (!source)
    throw SetupError("--source: expected synthetic, camera or recorded:DIR, got \"" + text + "\"");
  return *source;
}

ControllerSettings controller_settings(const settings::Go1Settings& settings,
                                       const rt::CatalogView& catalog) {
  const std::string mismatch = settings::validate_against_catalog(settings, catalog);
  if (!mismatch.empty()) throw SetupError(mismatch);
  ControllerSettings result;
  result.action_velocity = settings::velocity_table(settings, catalog);
  result.hold_last_seen = settings.loop.missing_human == settings::MissingHuman::kHoldLast;
  result.clamp_to_domain = settings.loop.clamp_to_domain;
  return result;
}

namespace {

// The shipped profiles a robot can run: "paper, guard, ours".
std::string robot_profile_names() {
  std::string names;
  for (const settings::ControllerProfile& profile : settings::shipped_controller_profiles())
    if (profile.kind == settings::ControllerKind::kAttention &&
        profile.catalog == settings::ProfileCatalog::kSession)
      names += (names.empty() ? "" : ", ") + profile.name;
  return names;
}

}  // namespace

settings::ControllerProfile robot_profile(const std::string& name_or_path) {
  settings::ControllerProfile profile;
  try {
    profile = settings::find_controller_profile(name_or_path, "--controller");
  } catch (const std::invalid_argument& e) {
    throw SetupError(e.what());
  }
  if (profile.kind == settings::ControllerKind::kOracle)
    throw SetupError("controller " + profile.name +
                     " is told who holds the treat, which only oasis-go1 sim knows; a robot "
                     "runs " +
                     robot_profile_names());
  if (profile.catalog == settings::ProfileCatalog::kFullState)
    throw SetupError("controller " + profile.name +
                     " is a simulation baseline on the no-attention catalog: run it with "
                     "oasis-go1 sim; a robot runs " +
                     robot_profile_names());
  return profile;
}

namespace {

// The compiler's own limit on a spec (support/limits.hpp): a larger file is not a spec.
constexpr std::size_t kMaxSpecBytes = std::size_t{16} << 20;

// The spec hash a catalog must carry, or nothing for "any".
std::optional<std::uint64_t> expected_spec_hash(const std::string& spec_setting) {
  if (spec_setting == settings::kAnyCatalogSpec) return std::nullopt;
  if (spec_setting == settings::kLinkedCatalog) return go1_treat::catalog().spec_hash;
  // The readers' one rule (common/files/input_file.hpp), with the compiler's limit on specs.
  std::string reason;
  const std::optional<std::string> text = files::read_input(spec_setting, kMaxSpecBytes, reason);
  if (!text) throw SetupError("loop.catalog_spec: cannot read " + spec_setting + ": " + reason);
  return rt::spec_hash(*text);
}

}  // namespace

SessionCatalog::SessionCatalog(const std::string& setting, const std::string& spec_setting) {
  const std::optional<std::uint64_t> spec_hash = expected_spec_hash(spec_setting);
  if (setting == settings::kLinkedCatalog) {
    view_ = &go1_treat::catalog();
    description_ = "linked catalog go1_treat (generated/go1_treat)";
  } else {
    loaded_ = rt::LoadedCatalog::from_file(setting);
    if (!loaded_.ok()) throw SetupError("catalog " + setting + ": " + loaded_.error());
    view_ = &loaded_.view();
    description_ = "catalog " + setting;
  }
  if (spec_hash && view_->spec_hash != *spec_hash) {
    const std::string spec =
        spec_setting == settings::kLinkedCatalog ? "the linked catalog's spec" : spec_setting;
    throw SetupError(
        description_ + " was compiled from another spec than " + spec + " (spec hash " +
        rt::spec_hash_text(view_->spec_hash) + ", expected " + rt::spec_hash_text(*spec_hash) +
        "): recompile it with oasisc compile, or set loop.catalog_spec (--catalog-spec) "
        "to the spec it came from, or to any");
  }
}

std::unique_ptr<RobotLink> open_link(const settings::Go1Settings& settings, bool dry_run,
                                     std::chrono::milliseconds robot_timeout) {
  if (dry_run) return std::make_unique<DryRunLink>();
  std::unique_ptr<Go1Link> link;
  try {
    link = std::make_unique<Go1Link>(settings.link);
  } catch (const go1::LinkError& e) {
    throw SetupError(std::string("robot link: ") + e.what());
  }
  if (!link->wait_for_robot(robot_timeout)) {
    const std::string report = link->silence_report();
    link->shut_down();
    throw SetupError("the robot did not answer within " + std::to_string(robot_timeout.count()) +
                     " ms: " + report +
                     ". Check that the robot is on and standing, that this machine is on its "
                     "network (192.168.123.x), and robot.level_flag (hw/README.md, \"First "
                     "checks\"); or run with --dry-run.");
  }
  return link;
}

SessionSource open_source(const settings::Go1Settings& settings, const rt::CatalogView& catalog,
                          RobotLink& link) {
  using Kind = settings::FrameSourceSetting::Kind;
  try {
    switch (settings.source.kind) {
      case Kind::kSynthetic:
        return synthetic_source(settings, catalog, link);
      case Kind::kCamera: {
        SessionSource session;
        session.source = std::make_unique<camera::LiveCamera>(settings.camera);
        session.realtime_only = true;
        session.description = "camera " + settings.camera.colour_device + " (colour) + " +
                              settings.camera.depth_device + " (depth)";
        return session;
      }
      case Kind::kRecorded: {
        SessionSource session;
        auto recording = std::make_unique<camera::RecordedSource>(settings.source.directory);
        session.true_holder = [recording = recording.get()] {
          return recording->truth_of_last_frame();
        };
        session.source = std::move(recording);
        session.description = "recording " + settings.source.directory;
        return session;
      }
    }
  } catch (const camera::CameraError& e) {
    throw SetupError(e.what());
  }
  throw SetupError("unknown frame source");
}

}  // namespace oasis::hw::loop
