// `oasis-go1 sim`: the Go1 treat experiment in the hallway simulator (hw/sim), Table II over
// seeded trials for each controller, all on the same trials, through oasis-go1's own loop,
// step log and score.

#include <cstdio>
#include <filesystem>
#include <iostream>
#include <memory>
#include <sstream>
#include <stdexcept>
#include <string>
#include <system_error>
#include <utility>
#include <vector>

#include "app/commands.hpp"
#include "command_line/number_options.hpp"
#include "log/step_log_writer.hpp"
#include "log/table2_metrics.hpp"
#include "log/table2_report.hpp"
#include "loop/profile_controller.hpp"
#include "loop/session.hpp"
#include "loop/sim_trial.hpp"
#include "sim/trial_svg.hpp"

namespace oasis::hw::app {
namespace {

struct SimRequest {
  std::string config;    // oasis-go1 settings; empty: the defaults (hw/config/go1.yaml)
  std::string scenario;  // empty: the defaults (hw/config/hallway.yaml)
  std::string catalog;
  std::string catalog_spec;
  std::string no_attention_catalog = OASIS_NO_ATTENTION_CATALOG;
  int trials = 12;
  std::uint64_t seed = 1;
  std::vector<std::string> controllers;  // profile names or .yaml paths; empty: every shipped one
  std::string perception = "fast";
  std::optional<std::uint64_t> steps;
  std::string logs;
  std::string plots;
  bool json = false;
  bool print_scenario = false;
  bool quiet = false;
};

// Trial k of a run seeded S: the same for every controller, so they face the same people.
std::uint64_t trial_seed(std::uint64_t seed, int trial) {
  return seed * 1000u + static_cast<std::uint64_t>(trial);
}

std::string trial_name(const std::string& controller, int trial) {
  char text[64];
  std::snprintf(text, sizeof text, "%s_trial%02d", controller.c_str(), trial + 1);
  return text;
}

loop::SimTrialSetup trial_setup(const SimRequest& request, const settings::Go1Settings& settings,
                                const rt::CatalogView& catalog) {
  loop::SimTrialSetup setup;
  setup.scenario =
      request.scenario.empty() ? sim::HallwayScenario{} : sim::load_scenario(request.scenario);
  setup.path = request.perception == "rendered" ? sim::ObservationPath::kRendered
                                                : sim::ObservationPath::kFast;
  setup.period_s = 1.0 / settings.loop.rate_hz;
  setup.intrinsics = settings.camera.intrinsics;
  setup.depth_scale_m_per_unit = settings.camera.depth_scale_m_per_unit;
  setup.perception = settings.perception;
  setup.controller = loop::controller_settings(settings, catalog);
  setup.max_steps = request.steps;
  return setup;
}

void write_outputs(const SimRequest& request, const std::string& name,
                   const loop::SimTrialResult& result, double hallway_width_m) {
  if (!request.logs.empty()) {
    log::StepLogWriter writer(std::filesystem::path(request.logs) / (name + ".jsonl"));
    for (const log::StepRecord& record : result.records)
      writer.write(record);
  }
  if (!request.plots.empty())
    sim::write_file_atomically(std::filesystem::path(request.plots) / (name + ".svg"),
                               sim::trial_svg(result.trace, name, hallway_width_m));
}

log::Table2Summary run_controller(const SimRequest& request, const loop::SimTrialSetup& setup,
                                  const rt::CatalogView& catalog,
                                  const settings::ControllerProfile& profile) {
  std::vector<log::TrialScore> scores;
  for (int trial = 0; trial < request.trials; ++trial) {
    const loop::SimTrialResult result =
        loop::run_sim_trial(catalog, setup, profile, trial_seed(request.seed, trial));
    write_outputs(request, trial_name(profile.name, trial), result, setup.scenario.hallway.width_m);
    log::ScoreOptions options;
    options.period_s = setup.period_s;
    scores.push_back(log::score_trial(result.records, options));
    if (!request.quiet && !request.json)
      std::cerr << "oasis-go1 sim: " << profile.name << " trial " << trial + 1 << "/"
                << request.trials << ": accuracy "
                << (scores.back().accuracy ? *scores.back().accuracy : 0.0) << ", reward "
                << scores.back().normalized_reward.value_or(0.0) << '\n';
  }
  return log::summarize_trials(scores);
}

// The profiles to run, in the order asked: every shipped one by default.
std::vector<settings::ControllerProfile> requested_profiles(const SimRequest& request) {
  if (request.controllers.empty()) return settings::shipped_controller_profiles();
  std::vector<settings::ControllerProfile> profiles;
  for (const std::string& name : request.controllers) {
    try {
      profiles.push_back(settings::find_controller_profile(name, "--controllers"));
    } catch (const std::invalid_argument& e) {
      throw loop::SetupError(e.what());
    }
  }
  return profiles;
}

void make_output_folders(const SimRequest& request) {
  const std::pair<const char*, const std::string*> folders[] = {{"--logs", &request.logs},
                                                                {"--plots", &request.plots}};
  for (const auto& [option, folder] : folders) {
    if (folder->empty()) continue;
    std::error_code error;
    std::filesystem::create_directories(*folder, error);
    if (error)
      throw loop::SetupError(std::string(option) + ": cannot create the folder " + *folder + ": " +
                             error.message());
  }
}

// What a profile is, as the tables and the JSON say it: where it came from and what it sets.
nlohmann::ordered_json profile_json(const settings::ControllerProfile& profile) {
  return {{"origin", profile.origin},
          {"description", profile.description},
          {"options", settings::profile_summary(profile)}};
}

int simulate(const SimRequest& request) {
  if (request.print_scenario) {
    std::cout << sim::scenario_to_yaml(
        request.scenario.empty() ? sim::HallwayScenario{} : sim::load_scenario(request.scenario));
    return 0;
  }
  const std::vector<settings::ControllerProfile> profiles = requested_profiles(request);
  make_output_folders(request);
  settings::Go1Settings settings = loop::settings_or_defaults(request.config);
  if (!request.catalog.empty()) settings.loop.catalog = request.catalog;
  if (!request.catalog_spec.empty()) settings.loop.catalog_spec = request.catalog_spec;
  const loop::SessionCatalog catalog(settings.loop.catalog, settings.loop.catalog_spec);
  if (!request.quiet && !request.json)
    std::cerr << "oasis-go1 sim: " << catalog.describe() << "; " << request.trials
              << " trial(s) from seed " << request.seed << "; perception " << request.perception
              << '\n';

  // The no-attention catalog, loaded when a controller runs on it.
  std::optional<loop::SessionCatalog> full_state;
  nlohmann::ordered_json json = nlohmann::ordered_json::object();
  for (const settings::ControllerProfile& profile : profiles) {
    const bool full_state_catalog = profile.catalog == settings::ProfileCatalog::kFullState;
    if (full_state_catalog && !full_state)
      full_state.emplace(request.no_attention_catalog, settings.loop.catalog_spec);
    const rt::CatalogView& view = full_state_catalog ? full_state->view() : catalog.view();
    const log::Table2Summary summary =
        run_controller(request, trial_setup(request, settings, view), view, profile);
    if (request.json) {
      json[profile.name] = log::table2_json(summary);
      json[profile.name]["profile"] = profile_json(profile);
      continue;
    }
    std::cout << "\n== " << profile.name << " (" << profile.origin << "): " << profile.description
              << "\n   " << settings::profile_summary(profile) << '\n';
    log::print_table2(std::cout, summary);
  }
  if (request.json) std::cout << json.dump(2) << '\n';
  return 0;
}

std::string controller_help() {
  std::string text =
      "controller profiles, comma-separated, in the order run: shipped ones by name, or .yaml "
      "files of your own (hw/config/controllers/README.md); default: every shipped one:";
  for (const settings::ControllerProfile& profile : settings::shipped_controller_profiles())
    text += "\n  " + profile.name + ": " + profile.description;
  return text;
}

}  // namespace

CommandRunner add_sim_command(CLI::App& app) {
  auto request = std::make_shared<SimRequest>();
  CLI::App* command = app.add_subcommand(
      "sim",
      "the Go1 treat experiment in a simulated hallway: Table II per controller over seeded "
      "trials, through the loop, log and score of run");
  command
      ->add_option("--scenario", request->scenario,
                   "the hallway scenario (hw/config/hallway.yaml documents every key); default: "
                   "the built-in defaults, which equal that file")
      ->check(CLI::ExistingFile);
  command
      ->add_option("--config", request->config,
                   "oasis-go1 settings: actions, loop rate, camera, perception, reach")
      ->check(CLI::ExistingFile);
  command->add_option("--catalog", request->catalog, "'linked' or a .bin catalog");
  command->add_option(
      "--catalog-spec", request->catalog_spec,
      "the spec the catalog must have been compiled from, checked by its spec hash: "
      "'linked' (the linked catalog's spec), a .oasis file, or 'any'; default: "
      "the config's loop.catalog_spec");
  command
      ->add_option("--no-attention-catalog", request->no_attention_catalog,
                   "the catalog the no-attention controller runs on (oasisc compile "
                   "--no-attention; scripts/regen makes the shipped one)")
      ->capture_default_str();
  command->add_option("--trials", request->trials, "seeded trials per controller")
      ->check(oasis::cli::whole_in(1, 100000));
  command->add_option("--seed", request->seed, "trial k uses seed * 1000 + k")
      ->check(oasis::cli::whole_in(0, oasis::cli::max_of<std::uint64_t>() / 1000 - 100000));
  command->add_option("--controllers", request->controllers, controller_help())->delimiter(',');
  command
      ->add_option("--perception", request->perception,
                   "fast (noisy positions drawn directly) or rendered (each frame rendered "
                   "and run through the real perception)")
      ->check(CLI::IsMember({"fast", "rendered"}));
  command->add_option("--steps", request->steps, "cut each trial after this many steps")
      ->check(oasis::cli::whole_in(1, oasis::cli::max_of<std::uint64_t>()));
  command->add_option(
      "--logs", request->logs,
      "write each trial's step log (hw/log/README.md) to DIR/CONTROLLER_trialNN.jsonl");
  command->add_option("--plots", request->plots,
                      "write each trial's picture to DIR/CONTROLLER_trialNN.svg");
  command->add_flag("--json", request->json,
                    "print {CONTROLLER: {accuracy, avg_lag_s, max_lag_s, normalized_reward, "
                    "...}} with each statistic {mean, std}");
  command->add_flag("--print-scenario", request->print_scenario,
                    "print the scenario (every key, commented) and stop");
  command->add_flag("--quiet", request->quiet, "no line per trial");
  command->footer(
      "Every controller runs the same trials (the same people, hand-offs, hiding and noise "
      "for a seed); 'oasis-go1 score DIR/ours_trial*.jsonl' scores the logs again.");
  return [request] { return simulate(*request); };
}

}  // namespace oasis::hw::app
