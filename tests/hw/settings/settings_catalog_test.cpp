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

TEST(SettingsCatalog, RobustFilterNeedsARobustSection) {
  const TinyCatalog catalog;
  Go1Settings settings = default_settings();
  settings.loop.actions = {{"stop", {}}, {"left", {}}, {"hop", {}}};
  settings.filter.mode = rt::FilterMode::kRobust;
  EXPECT_EQ(validate_against_catalog(settings, catalog.view),
            "filter.mode: robust needs a catalog with a robust section, and \"tiny\" has none (a "
            "continuous catalog never has one); use paper");
}

}  // namespace
}  // namespace oasis::hw::settings
