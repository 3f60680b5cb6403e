#include <algorithm>
#include <stdexcept>

#include "settings/settings.hpp"

namespace oasis::hw::settings {

namespace {

std::vector<std::string> catalog_actions(const rt::CatalogView& catalog) {
  std::vector<std::string> names;
  if (catalog.action_names == nullptr) return names;
  for (std::uint32_t a = 0; a < catalog.num_actions; ++a)
    names.push_back(catalog.action_names[a] != nullptr ? catalog.action_names[a] : "");
  return names;
}

std::vector<std::string> settings_actions(const Go1Settings& settings) {
  std::vector<std::string> names;
  for (const ActionVelocity& entry : settings.loop.actions)
    names.push_back(entry.action);
  return names;
}

bool contains(const std::vector<std::string>& names, const std::string& name) {
  return std::find(names.begin(), names.end(), name) != names.end();
}

std::string list(const std::vector<std::string>& names) {
  std::string text = "[";
  for (std::size_t i = 0; i < names.size(); ++i)
    text += (i == 0 ? "" : ", ") + names[i];
  return text + "]";
}

// "" when every catalog action has a velocity and every velocity a catalog action.
std::string action_problems(const Go1Settings& settings, const rt::CatalogView& catalog) {
  const std::vector<std::string> in_catalog = catalog_actions(catalog);
  const std::vector<std::string> in_settings = settings_actions(settings);
  std::vector<std::string> missing;
  std::vector<std::string> extra;
  for (const std::string& name : in_catalog)
    if (!contains(in_settings, name)) missing.push_back(name);
  for (const std::string& name : in_settings)
    if (!contains(in_catalog, name)) extra.push_back(name);
  if (missing.empty() && extra.empty()) return {};
  const std::string catalog_name = catalog.name != nullptr ? catalog.name : "?";
  std::string text = "actions: the catalog \"" + catalog_name + "\" has actions " +
                     list(in_catalog) + " but the settings give velocities for " +
                     list(in_settings);
  if (!missing.empty()) text += "; no velocity for " + list(missing);
  if (!extra.empty()) text += "; not catalog actions: " + list(extra);
  return text;
}

}  // namespace

std::string validate_against_catalog(const Go1Settings& settings, const rt::CatalogView& catalog) {
  return action_problems(settings, catalog);
}

std::vector<go1::VelocityCommand> velocity_table(const Go1Settings& settings,
                                                 const rt::CatalogView& catalog) {
  const std::string problems = action_problems(settings, catalog);
  if (!problems.empty()) throw std::invalid_argument(problems);
  std::vector<go1::VelocityCommand> table;
  for (const std::string& name : catalog_actions(catalog)) {
    const auto entry =
        std::find_if(settings.loop.actions.begin(), settings.loop.actions.end(),
                     [&](const ActionVelocity& candidate) { return candidate.action == name; });
    table.push_back(entry->velocity);
  }
  return table;
}

}  // namespace oasis::hw::settings
