// The shipped hw/config/go1.yaml against the code's defaults, and settings_to_yaml() round trips.
#include <cmath>
#include <fstream>
#include <limits>
#include <sstream>

#include <gtest/gtest.h>

#include "settings/settings.hpp"
#include "yaml_schema/schema_reader.hpp"

namespace oasis::hw::settings {
namespace {

using Keys = std::vector<std::string>;

TEST(SettingsShipped, Go1YamlLoadsToTheDefaults) {
  const Go1Settings loaded = load_settings(OASIS_SHIPPED_GO1_YAML);
  EXPECT_EQ(differing_keys(loaded, default_settings()), Keys{});
}

TEST(SettingsShipped, Go1YamlIsTheDefaultsPrintedWithEveryKey) {
  const std::string expected = settings_to_yaml(default_settings());
  if (yaml_schema::read_yaml_file(OASIS_SHIPPED_GO1_YAML) == expected) return;
  const std::string fresh = std::filesystem::absolute("go1.yaml.expected").string();
  std::ofstream(fresh, std::ios::binary) << expected;
  ADD_FAILURE() << OASIS_SHIPPED_GO1_YAML << " is not settings_to_yaml(default_settings()).\n"
                << "If the code's defaults and comments are right, refresh the file with\n"
                << "  cp " << fresh << " " << OASIS_SHIPPED_GO1_YAML;
}

TEST(SettingsShipped, DefaultsPassTheirOwnChecks) {
  EXPECT_EQ(check_settings(default_settings()), std::vector<Diagnostic>{});
  EXPECT_EQ(differing_keys(Go1Settings{}, default_settings()), Keys{});
}

TEST(SettingsShipped, DefaultActionsAreTheSpecsSixAtItsSpeeds) {
  const std::vector<ActionVelocity> actions = default_settings().loop.actions;
  ASSERT_EQ(actions.size(), 6u);
  EXPECT_EQ(actions[0], (ActionVelocity{"left", {0.0f, 0.0f, 0.5f}}));  // counter-clockwise
  EXPECT_EQ(actions[1], (ActionVelocity{"right", {0.0f, 0.0f, -0.5f}}));
  EXPECT_EQ(actions[2], (ActionVelocity{"straight", {0.5f, 0.0f, 0.0f}}));
  EXPECT_EQ(actions[3], (ActionVelocity{"left_straight", {0.5f, 0.0f, 0.5f}}));
  EXPECT_EQ(actions[4], (ActionVelocity{"right_straight", {0.5f, 0.0f, -0.5f}}));
  EXPECT_EQ(actions[5], (ActionVelocity{"stop", {0.0f, 0.0f, 0.0f}}));
}

// Every section touched, with values that need care: quoting, "any", extreme integers,
// floats and doubles without a short decimal form.
Go1Settings unusual_settings() {
  Go1Settings s;
  s.link.robot = {"192.168.12.1", 8082};
  s.link.local = {"192.168.123.162", 0};
  s.link.level_flag = go1::kLevelFlagZero;
  s.link.state_level_flag.reset();
  s.link.check_state_crc = false;
  s.link.rate_hz = 1000.0 / 3.0;
  s.link.watchdog_timeout = std::chrono::milliseconds(1000);
  s.link.stop_hold = std::chrono::milliseconds(0);
  s.link.gait = go1::GaitType::kTrotRunning;
  s.link.limits.max_forward = 0.1f;
  s.link.limits.max_yaw_rate = 1.0f / 3.0f;
  s.loop.actions = {{"creep", {0.1f, -0.05f, 0.0f}}, {"spin", {0.0f, 0.0f, -1.0f / 3.0f}}};
  s.camera.colour_device = "/dev/v4l/by-id/usb-Intel(R)_RealSense(TM) #1";
  s.camera.depth_device = "yes";  // a YAML 1.1 boolean, must be quoted
  s.camera.intrinsics = {615.123456789, 614.5, 320.25, 240.75, 1280, 720};
  s.perception.mount.pitch_up_rad = -0.1;
  s.perception.segmentation.red.bands = {{cv::Scalar(1, 2, 3), cv::Scalar(4, 5, 6)}};
  s.perception.treat_tag_id = 586;
  s.perception.reach = {0.25, 1.0, -0.5, 0.125};
  s.loop.controller = "profiles/my controller.yaml";
  s.loop.rate_hz = 10.0;
  s.loop.catalog = "catalogs/go1 treat: v2.bin";
  s.loop.catalog_spec = "any";
  s.loop.missing_human = MissingHuman::kOutside;
  s.source = {FrameSourceSetting::Kind::kRecorded, "/data/run #3"};
  return s;
}

TEST(SettingsRoundTrip, PrintedSettingsReadBackIdentically) {
  const Go1Settings original = unusual_settings();
  ASSERT_EQ(check_settings(original), std::vector<Diagnostic>{});
  const std::string text = settings_to_yaml(original);
  const Go1Settings back = parse_settings(text, "printed.yaml");
  EXPECT_EQ(differing_keys(back, original), Keys{}) << text;
  EXPECT_EQ(settings_to_yaml(back), text);
  // Spot checks of the fields themselves, not only of their printed form.
  EXPECT_EQ(back.link.limits.max_yaw_rate, 1.0f / 3.0f);
  EXPECT_EQ(back.link.rate_hz, 1000.0 / 3.0);
  EXPECT_EQ(back.loop.controller, "profiles/my controller.yaml");
  EXPECT_FALSE(back.link.state_level_flag.has_value());
  EXPECT_EQ(back.source.directory, "/data/run #3");
  EXPECT_EQ(back.camera.depth_device, "yes");
  EXPECT_EQ(back.loop.actions, original.loop.actions);
}

TEST(SettingsRoundTrip, DifferingKeysNamesWhatChanged) {
  Go1Settings changed = default_settings();
  changed.link.robot.port = 8083;
  changed.loop.actions[0].velocity.yaw_rate = 0.4f;
  changed.perception.segmentation.yellow.bands[0].low[0] = 21;
  EXPECT_EQ(differing_keys(changed, default_settings()),
            (Keys{"robot.port", "actions.left.yaw_rate", "perception.segmentation.yellow"}));
  changed = default_settings();
  changed.loop.actions.pop_back();
  EXPECT_EQ(differing_keys(changed, default_settings()),
            (Keys{"actions.stop.forward", "actions.stop.lateral", "actions.stop.yaw_rate"}));
}

TEST(SettingsPartial, AbsentKeysKeepTheirDefaults) {
  const Go1Settings s = parse_settings(
      "# only what differs\n"
      "robot:\n"
      "  address: 192.168.12.1\n"
      "  level_flag: 0x00\n"
      "perception:\n"
      "  reach:\n"
      "    x_max_m: 0.9\n"
      "source: synthetic\n",
      "partial.yaml");
  EXPECT_EQ(differing_keys(s, default_settings()),
            (Keys{"robot.address", "robot.level_flag", "perception.reach.x_max_m", "source"}));
  EXPECT_EQ(s.link.robot.address, "192.168.12.1");
  EXPECT_EQ(s.link.level_flag, 0x00);
  EXPECT_EQ(s.perception.reach.x_max_m, 0.9);
  EXPECT_EQ(s.source.kind, FrameSourceSetting::Kind::kSynthetic);
}

TEST(SettingsPartial, EmptyMappingAndEmptySectionsAreAllDefaults) {
  EXPECT_EQ(differing_keys(parse_settings("{}", "empty.yaml"), default_settings()), Keys{});
  EXPECT_EQ(differing_keys(parse_settings("robot:\n# port: 1\nlimits: {}\n", "e.yaml"),
                           default_settings()),
            Keys{});
}

TEST(SettingsPartial, ActionsAreTakenWholeWithAbsentComponentsZero) {
  const Go1Settings s = parse_settings(
      "actions:\n"
      "  forward: {forward: 0.2}\n"
      "  stop:\n",
      "actions.yaml");
  EXPECT_EQ(s.loop.actions, (std::vector<ActionVelocity>{{"forward", {0.2f, 0.0f, 0.0f}},
                                                         {"stop", {0.0f, 0.0f, 0.0f}}}));
}

TEST(SettingsPartial, ScalarSpellings) {
  const Go1Settings s = parse_settings(
      "robot:\n"
      "  level_flag: 238\n"
      "  state_level_flag: any\n"
      "  check_state_crc: False\n"
      "camera:\n"
      "  fps: \"15\"\n"
      "perception:\n"
      "  treat_tag_id: 7\n"
      "loop:\n"
      "  controller: guard\n"
      "  catalog: /opt/oasis/go1_treat.bin\n"
      "  catalog_spec: /opt/oasis/specs/go1_treat.oasis\n"
      "source: recorded:/data/run1\n",
      "spellings.yaml");
  EXPECT_EQ(s.link.level_flag, 0xEE);
  EXPECT_FALSE(s.link.state_level_flag.has_value());
  EXPECT_FALSE(s.link.check_state_crc);
  EXPECT_EQ(s.camera.fps, 15);
  EXPECT_EQ(s.perception.treat_tag_id, 7);
  EXPECT_EQ(s.loop.controller, "guard");
  EXPECT_EQ(s.loop.catalog, "/opt/oasis/go1_treat.bin");
  EXPECT_EQ(s.loop.catalog_spec, "/opt/oasis/specs/go1_treat.oasis");
  EXPECT_EQ(s.source, (FrameSourceSetting{FrameSourceSetting::Kind::kRecorded, "/data/run1"}));
}

TEST(SettingsPartial, FrameSourceSpellings) {
  EXPECT_EQ(parse_frame_source("synthetic"),
            (FrameSourceSetting{FrameSourceSetting::Kind::kSynthetic, ""}));
  EXPECT_EQ(parse_frame_source("recorded:runs/a b"),
            (FrameSourceSetting{FrameSourceSetting::Kind::kRecorded, "runs/a b"}));
  EXPECT_EQ(parse_frame_source("recorded:"), std::nullopt);
  EXPECT_EQ(parse_frame_source("Camera"), std::nullopt);
  EXPECT_EQ(to_string(FrameSourceSetting{FrameSourceSetting::Kind::kRecorded, "runs/a b"}),
            "recorded:runs/a b");
}

TEST(SettingsChecks, CheckSettingsNamesTheBadKeysOfSettingsMadeInCode) {
  Go1Settings s = default_settings();
  s.link.robot.port = 0;
  s.camera.depth_scale_m_per_unit = std::nan("");
  s.loop.actions[2].velocity.forward = 0.7f;
  std::vector<std::string> keys;
  for (const Diagnostic& d : check_settings(s))
    keys.push_back(d.key);
  EXPECT_EQ(keys,
            (Keys{"robot.port", "camera.depth_scale_m_per_unit", "actions.straight.forward"}));
}

}  // namespace
}  // namespace oasis::hw::settings
