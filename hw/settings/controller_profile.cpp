// Controller profiles: the reader and writer walk profile_schema.hpp; the shipped profiles are
// the texts CMake compiled in from hw/config/controllers/ (shipped_profiles.hpp).

#include "settings/controller_profile.hpp"

#include <sstream>
#include <stdexcept>
#include <string>

#include "settings/profile_schema.hpp"
#include "settings/settings_error.hpp"
#include "settings/shipped_profiles.hpp"
#include "yaml_schema/schema_reader.hpp"
#include "yaml_schema/schema_writer.hpp"

namespace oasis::hw::settings {
namespace {

constexpr std::string_view kSections = "description:, kind:, catalog:, filter:, evidence:";

std::vector<yaml_schema::CrossProblem> profile_problems(const ControllerProfile& profile) {
  std::vector<yaml_schema::CrossProblem> problems;
  if (profile.kind == ControllerKind::kOracle && profile.catalog == ProfileCatalog::kFullState)
    problems.push_back({"catalog", "kind", "the oracle runs on the session's catalog"});
  return problems;
}

// Enough digits to tell any two doubles apart, the fewest that do for the usual ones.
std::string format_number(double value) {
  std::ostringstream text;
  text.precision(17);
  text << value;
  std::string longest = text.str();
  for (int digits = 1; digits < 17; ++digits) {
    std::ostringstream shorter;
    shorter.precision(digits);
    shorter << value;
    if (std::stod(shorter.str()) == value) return shorter.str();
  }
  return longest;
}

}  // namespace

bool is_profile_path(std::string_view text) {
  const auto ends_with = [&](std::string_view suffix) {
    return text.size() > suffix.size() && text.substr(text.size() - suffix.size()) == suffix;
  };
  return ends_with(".yaml") || ends_with(".yml");
}

std::string shipped_profile_names() {
  std::string names;
  for (const detail::ShippedProfileText& shipped : detail::shipped_profile_texts())
    names += (names.empty() ? "" : ", ") + std::string(shipped.name);
  return names;
}

bool same_options(const ControllerProfile& a, const ControllerProfile& b) {
  const rt::FilterOptions& f = a.filter;
  const rt::FilterOptions& g = b.filter;
  return a.kind == b.kind && a.catalog == b.catalog && a.evidence == b.evidence &&
         f.mode == g.mode && f.tie_rule == g.tie_rule && f.seed == g.seed &&
         f.tie_tolerance == g.tie_tolerance && f.reward_tolerance == g.reward_tolerance &&
         f.detection_epsilon == g.detection_epsilon &&
         f.zero_likelihood_guard == g.zero_likelihood_guard &&
         f.mass_limits.tolerance == g.mass_limits.tolerance &&
         f.mass_limits.max_boxes == g.mass_limits.max_boxes;
}

ControllerProfile parse_controller_profile(std::string_view yaml_text, std::string_view file_name,
                                           std::string name) {
  ControllerProfile profile;
  profile.name = std::move(name);
  profile.origin = std::string(file_name);
  yaml_schema::parse_with_schema(
      yaml_text, file_name, profile,
      [](auto& visitor, auto& values) { detail::describe_profile(visitor, values); },
      profile_problems, kSections);
  return profile;
}

ControllerProfile load_controller_profile(const std::filesystem::path& file) {
  return parse_controller_profile(yaml_schema::read_yaml_file(file), file.string(),
                                  file.stem().string());
}

const std::vector<ControllerProfile>& shipped_controller_profiles() {
  static const std::vector<ControllerProfile> profiles = [] {
    std::vector<ControllerProfile> parsed;
    for (const detail::ShippedProfileText& shipped : detail::shipped_profile_texts())
      parsed.push_back(parse_controller_profile(shipped.text, shipped.path, shipped.name));
    return parsed;
  }();
  return profiles;
}

ControllerProfile find_controller_profile(std::string_view name_or_path, std::string_view where) {
  if (is_profile_path(name_or_path))
    return load_controller_profile(std::filesystem::path(name_or_path));
  for (const ControllerProfile& profile : shipped_controller_profiles())
    if (profile.name == name_or_path) return profile;
  throw std::invalid_argument(std::string(where) + ": no controller profile \"" +
                              std::string(name_or_path) + "\"; the shipped ones are " +
                              shipped_profile_names() +
                              " (hw/config/controllers/), or give a path to a .yaml profile");
}

std::string profile_to_yaml(const ControllerProfile& profile) {
  yaml_schema::Writer writer{
      "# Controller profile \"" + profile.name +
      "\" (hw/config/controllers/README.md), written by profile_to_yaml().\n"};
  detail::describe_profile(writer, profile);
  return writer.text();
}

std::string profile_summary(const ControllerProfile& profile) {
  if (profile.kind == ControllerKind::kOracle) return "told the true context";
  std::vector<std::string> parts;
  parts.push_back(detail::kModeCodec.format(profile.filter.mode) + " filter");
  if (profile.catalog == ProfileCatalog::kFullState) parts.push_back("full-state catalog");
  if (profile.filter.zero_likelihood_guard) parts.push_back("zero-likelihood guard");
  if (profile.filter.tie_tolerance != rt::FilterOptions{}.tie_tolerance)
    parts.push_back("ties within " + format_number(profile.filter.tie_tolerance));
  if (profile.filter.tie_rule == rt::TieRule::kRandom)
    parts.push_back("random ties, seed " + std::to_string(profile.filter.seed));
  if (profile.filter.reward_tolerance != rt::FilterOptions{}.reward_tolerance)
    parts.push_back("reward tolerance " + format_number(profile.filter.reward_tolerance));
  if (profile.filter.detection_epsilon > 0.0)
    parts.push_back("detection epsilon " + format_number(profile.filter.detection_epsilon));
  const TagEvidence& evidence = profile.evidence;
  if (evidence.treat_sighting > 0.0)
    parts.push_back("tag seen " + format_number(evidence.treat_sighting));
  if (evidence.tag_unseen_likelihood < 1.0)
    parts.push_back("tag unseen " + format_number(evidence.tag_unseen_likelihood));
  if (evidence.unknown_reward_when_tag_cut) parts.push_back("reward unknown when a tag is cut");
  std::string text;
  for (const std::string& part : parts)
    text += (text.empty() ? "" : ", ") + part;
  return text;
}

std::string validate_profile_against_catalog(const ControllerProfile& profile,
                                             const rt::CatalogView& catalog) {
  const rt::FilterMode mode = profile.filter.mode;
  if (profile.kind != ControllerKind::kAttention || mode == rt::FilterMode::kPaper) return "";
  const std::string catalog_name = catalog.name != nullptr ? catalog.name : "?";
  const std::string where = "controller " + profile.name + " (" + profile.origin +
                            "): filter.mode " + detail::kModeCodec.format(mode);
  if (mode != rt::noise_model_mode(catalog))
    return where + " runs on " + (catalog.is_continuous() ? "discrete" : "continuous") +
           " catalogs, and \"" + catalog_name + "\" is " +
           (catalog.is_continuous() ? "continuous: use noise_aware" : "discrete: use joint");
  if (!catalog.has_noise_model())
    return where + " needs the catalog's noise model, and \"" + catalog_name + "\" has none (" +
           (catalog.is_continuous() ? "the spec's object items" : "the spec's observation block") +
           "); use a profile whose filter.mode is paper, such as guard";
  return "";
}

}  // namespace oasis::hw::settings
