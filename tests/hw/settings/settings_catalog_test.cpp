// validate_against_catalog() and velocity_table() on a tiny hand-made catalog view.
#include <stdexcept>

#include <gtest/gtest.h>

#include "settings/settings.hpp"

namespace oasis::hw::settings {
namespace {

// Only the fields the checks read: the name, the action names, no robust section.
struct TinyCatalog {
  const char* names[3] = {"stop", "left", "hop"};
  rt::CatalogView view;

  TinyCatalog() {
    view.name = "tiny";
    view.num_actions = 3;
    view.action_names = names;
  }
};

TEST(SettingsCatalog, ReportsBothListsAndWhatDiffers) {
  const TinyCatalog catalog;
  const std::string text = validate_against_catalog(default_settings(), catalog.view);
  EXPECT_EQ(text,
            "actions: the catalog \"tiny\" has actions [stop, left, hop] but the settings give "
            "velocities for [left, right, straight, left_straight, right_straight, stop]; "
            "no velocity for [hop]; not catalog actions: [right, straight, left_straight, "
            "right_straight]");
  EXPECT_THROW(velocity_table(default_settings(), catalog.view), std::invalid_argument);
}

TEST(SettingsCatalog, MatchingActionsGiveATableInCatalogOrder) {
  const TinyCatalog catalog;
  Go1Settings settings = default_settings();
  settings.loop.actions = {
      {"left", {0.0f, 0.0f, 0.5f}}, {"hop", {0.2f, 0.0f, 0.0f}}, {"stop", {0.0f, 0.0f, 0.0f}}};
  EXPECT_EQ(validate_against_catalog(settings, catalog.view), "");
  EXPECT_EQ(velocity_table(settings, catalog.view),
            (std::vector<go1::VelocityCommand>{
                {0.0f, 0.0f, 0.0f}, {0.0f, 0.0f, 0.5f}, {0.2f, 0.0f, 0.0f}}));
}

TEST(SettingsCatalog, AProfilesFilterModeMustFitTheCatalog) {
  const TinyCatalog catalog;  // discrete, without a robust section
  ControllerProfile profile = find_controller_profile("guard");
  EXPECT_EQ(validate_profile_against_catalog(profile, catalog.view), "");
  profile.filter.mode = rt::FilterMode::kJoint;
  EXPECT_EQ(validate_profile_against_catalog(profile, catalog.view),
            "controller guard (hw/config/controllers/guard.yaml): filter.mode joint needs the "
            "catalog's noise model, and \"tiny\" has none (the spec's observation block); use a "
            "profile whose filter.mode is paper, such as guard");
  profile.filter.mode = rt::FilterMode::kNoiseAware;
  EXPECT_EQ(validate_profile_against_catalog(profile, catalog.view),
            "controller guard (hw/config/controllers/guard.yaml): filter.mode noise_aware runs on "
            "continuous catalogs, and \"tiny\" is discrete: use joint");
}

}  // namespace
}  // namespace oasis::hw::settings
