// Controller profiles (hw/settings/controller_profile.hpp): the shipped files of
// hw/config/controllers/ are the profiles the program has compiled in, each reads back from its
// printed form, and a profile file's errors are located like a settings file's.
#include "settings/controller_profile.hpp"

#include <filesystem>
#include <stdexcept>

#include <gtest/gtest.h>

#include "settings/settings.hpp"
#include "settings/settings_error.hpp"

namespace oasis::hw::settings {
namespace {

// The compiled-in profiles are the shipped files as they are now: each folder file is one of
// them, read the same, and nothing is compiled in that the folder lacks.
TEST(ControllerProfiles, TheCompiledInProfilesAreTheShippedFiles) {
  const std::filesystem::path folder = OASIS_SHIPPED_CONTROLLERS;
  std::size_t files = 0;
  for (const auto& entry : std::filesystem::directory_iterator(folder)) {
    if (entry.path().extension() != ".yaml") continue;
    ++files;
    const ControllerProfile from_file = load_controller_profile(entry.path());
    const ControllerProfile compiled_in = find_controller_profile(from_file.name);
    EXPECT_TRUE(same_options(from_file, compiled_in)) << from_file.name;
    EXPECT_EQ(from_file.description, compiled_in.description) << from_file.name;
  }
  EXPECT_EQ(files, shipped_controller_profiles().size());
}

TEST(ControllerProfiles, TheShippedProfilesSayWhatTheyAre) {
  const ControllerProfile paper = find_controller_profile("paper");
  EXPECT_TRUE(same_options(paper, ControllerProfile{})) << "paper must be Algorithm 1's defaults";
  const ControllerProfile guard = find_controller_profile("guard");
  EXPECT_TRUE(guard.filter.zero_likelihood_guard);
  EXPECT_EQ(find_controller_profile("oracle").kind, ControllerKind::kOracle);
  EXPECT_EQ(find_controller_profile("no-attention").catalog, ProfileCatalog::kFullState);
  const ControllerProfile ours = find_controller_profile("ours");
  EXPECT_EQ(ours.filter.mode, rt::FilterMode::kNoiseAware);
  EXPECT_EQ(ours.filter.tie_tolerance, 0.05);
  EXPECT_TRUE(ours.filter.zero_likelihood_guard);
  EXPECT_EQ(ours.evidence, (TagEvidence{0.9, 0.1, true}));
  EXPECT_EQ(ours.origin, "hw/config/controllers/ours.yaml");
  EXPECT_EQ(profile_summary(ours),
            "noise_aware filter, zero-likelihood guard, ties within 0.05, tag seen 0.9, tag "
            "unseen 0.1, reward unknown when a tag is cut");
}

TEST(ControllerProfiles, TheRobotsDefaultIsOurs) {
  EXPECT_EQ(default_settings().loop.controller, "ours");
  EXPECT_EQ(kDefaultController, "ours");
}

TEST(ControllerProfiles, APrintedProfileReadsBackToTheSameOptions) {
  for (const ControllerProfile& profile : shipped_controller_profiles()) {
    const std::string text = profile_to_yaml(profile);
    const ControllerProfile back = parse_controller_profile(text, "printed.yaml", profile.name);
    EXPECT_TRUE(same_options(back, profile)) << text;
    EXPECT_EQ(back.description, profile.description);
  }
}

TEST(ControllerProfiles, AProfileFileHoldsOnlyWhatDiffersAndErrorsAreLocated) {
  const ControllerProfile partial =
      parse_controller_profile("filter:\n  zero_likelihood_guard: true\n", "mine.yaml", "mine");
  ControllerProfile expected;
  expected.filter.zero_likelihood_guard = true;
  EXPECT_TRUE(same_options(partial, expected));

  try {
    parse_controller_profile("filter:\n  mode: robust\n", "old.yaml", "old");
    FAIL() << "robust is no longer a mode";
  } catch (const SettingsError& e) {
    EXPECT_NE(std::string(e.what()).find("old.yaml:2:9: error: filter.mode"), std::string::npos)
        << e.what();
    EXPECT_NE(std::string(e.what()).find("paper, joint, noise_aware"), std::string::npos)
        << e.what();
  }
  try {
    parse_controller_profile("filter:\n  detection_epsilon: 1\n", "eps.yaml", "eps");
    FAIL() << "epsilon 1 is out of range";
  } catch (const SettingsError& e) {
    EXPECT_NE(std::string(e.what()).find("eps.yaml:2:22: error: filter.detection_epsilon: "
                                         "expected a number in [0.0, 1.0), got \"1\""),
              std::string::npos)
        << e.what();
  }
  EXPECT_THROW(parse_controller_profile("kind: oracle\ncatalog: full_state\n", "x.yaml", "x"),
               SettingsError);
  EXPECT_THROW(find_controller_profile("psychic"), std::invalid_argument);
}

// The settings no longer hold the filter: a file of the old layout says where it went.
TEST(ControllerProfiles, TheOldFilterSectionOfTheSettingsSaysWhereItWent) {
  try {
    parse_settings("filter:\n  mode: paper\nloop:\n  treat_sighting: 0.9\n", "old.yaml");
    FAIL() << "filter: is no longer a settings section";
  } catch (const SettingsError& e) {
    const std::string text = e.what();
    EXPECT_NE(text.find("old.yaml:1:1: error: filter: no longer a key here: the filter's options"),
              std::string::npos)
        << text;
    EXPECT_NE(text.find("old.yaml:4:3: error: loop.treat_sighting: no longer a key here"),
              std::string::npos)
        << text;
  }
  try {
    parse_settings("loop:\n  controller: psychic\n", "bad.yaml");
    FAIL() << "no such profile";
  } catch (const SettingsError& e) {
    EXPECT_NE(std::string(e.what()).find("bad.yaml:2:15: error: loop.controller"),
              std::string::npos)
        << e.what();
  }
}

// `sim` and `run` print profile_summary() of the profile they drive with; the program test
// compares the two. That proves equal options only if every option shows in the summary.
TEST(ControllerProfiles, EveryOptionShowsInTheSummary) {
  const ControllerProfile base;
  std::vector<ControllerProfile> changed(11, base);
  changed[0].filter.mode = rt::FilterMode::kNoiseAware;
  changed[1].filter.tie_rule = rt::TieRule::kRandom;
  changed[2].filter.tie_rule = rt::TieRule::kRandom;
  changed[2].filter.seed = 7;
  changed[3].filter.tie_tolerance = 0.05;
  changed[4].filter.reward_tolerance = 1e-6;
  changed[5].filter.detection_epsilon = 0.1;
  changed[6].filter.zero_likelihood_guard = true;
  changed[7].evidence.treat_sighting = 0.9;
  changed[8].evidence.tag_unseen_likelihood = 0.1;
  changed[9].evidence.unknown_reward_when_tag_cut = true;
  changed[10].catalog = ProfileCatalog::kFullState;
  changed.push_back(base);
  for (std::size_t i = 0; i < changed.size(); ++i)
    for (std::size_t j = 0; j < i; ++j)
      EXPECT_NE(profile_summary(changed[i]), profile_summary(changed[j])) << i << " vs " << j;
  ControllerProfile close = base;
  close.filter.tie_tolerance = 0.05000000000000001;
  ControllerProfile other = base;
  other.filter.tie_tolerance = 0.05;
  EXPECT_NE(profile_summary(close), profile_summary(other));
}

}  // namespace
}  // namespace oasis::hw::settings
