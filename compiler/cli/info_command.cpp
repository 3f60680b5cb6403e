// `oasisc info FILE [--json]`: the size of every context of a model.

#include <iomanip>
#include <iostream>
#include <memory>
#include <sstream>

#include <nlohmann/json.hpp>

#include "cli/commands.hpp"
#include "model/statistics.hpp"

namespace oasis::cli {
namespace {

struct InfoOptions {
  std::string file;
  bool json = false;
  CommonOptions common;
};

const char* kind_name(const LoadedModel& loaded) {
  if (!loaded.ir) return "imported";
  switch (loaded.ir->kind) {
    case model::ModelKind::Explicit:
      return "explicit";
    case model::ModelKind::Factored:
      return "factored";
    case model::ModelKind::Continuous:
      return "continuous";
  }
  return "?";
}

std::vector<std::string> context_names(const LoadedModel& loaded) {
  std::vector<std::string> names;
  if (loaded.model) {
    for (const auto& context : loaded.model->contexts)
      names.push_back(context.name);
  } else {
    for (const auto& context : loaded.ir->contexts)
      names.push_back(context.name);
  }
  return names;
}

// `stats`: context_statistics() of the explicit model, empty for continuous models; computed
// once by the caller (it walks every choice of every context).
nlohmann::json to_json(const LoadedModel& loaded,
                       const std::vector<model::ContextStatistics>& stats) {
  nlohmann::json out;
  out["file"] = loaded.path;
  out["model"] = loaded.model ? loaded.model->name : loaded.ir->name;
  out["kind"] = kind_name(loaded);
  const std::vector<std::string> names = context_names(loaded);
  const auto& actions = loaded.model ? loaded.model->actions : loaded.ir->actions;
  out["action_names"] = actions;
  out["states"] = loaded.model ? nlohmann::json(loaded.model->num_states()) : nlohmann::json();
  out["actions"] = actions.size();
  if (loaded.ir && loaded.ir->kind == model::ModelKind::Continuous) {
    nlohmann::json variables = nlohmann::json::array();
    for (const auto& var : loaded.ir->continuous) {
      variables.push_back(
          {{"name", var.name}, {"low", to_double(var.low)}, {"high", to_double(var.high)}});
    }
    out["continuous_variables"] = variables;
    out["regions"] = loaded.ir->regions.size();
  }
  nlohmann::json contexts = nlohmann::json::array();
  for (std::size_t c = 0; c < names.size(); ++c) {
    nlohmann::json context{{"name", names[c]}, {"actions", actions.size()}};
    if (c < stats.size()) {
      context["states"] = stats[c].states;
      context["choices"] = stats[c].choices;
      context["transitions"] = stats[c].transitions;
      if (stats[c].reward_min) {
        context["reward_min"] = to_double(*stats[c].reward_min);
        context["reward_max"] = to_double(*stats[c].reward_max);
      }
    } else {  // continuous: no finite state space until the geometry layer partitions it
      context["states"] = nullptr;
      context["transitions"] = nullptr;
    }
    contexts.push_back(context);
  }
  out["contexts"] = contexts;
  const model::SwitchingModel& switching =
      loaded.model ? loaded.model->switching : loaded.ir->switching;
  if (!switching.matrix.empty()) {
    nlohmann::json matrix = nlohmann::json::array();
    for (std::size_t i = 0; i < names.size(); ++i) {
      nlohmann::json row = nlohmann::json::array();
      for (std::size_t j = 0; j < names.size(); ++j)
        row.push_back(to_string(switching.matrix[i * names.size() + j]));
      matrix.push_back(row);
    }
    out["switching"] = matrix;
    nlohmann::json prior = nlohmann::json::array();
    for (const Rational& p : switching.prior)
      prior.push_back(to_string(p));
    out["prior"] = prior;
  }
  return out;
}

std::string reward_range(const model::ContextStatistics& stats) {
  if (!stats.reward_min) return "-";
  return "[" + to_string(*stats.reward_min) + ", " + to_string(*stats.reward_max) + "]";
}

void print_text(const LoadedModel& loaded, const std::vector<model::ContextStatistics>& stats) {
  const nlohmann::json summary = to_json(loaded, stats);
  std::cout << loaded.path << ": model '" << summary["model"].get<std::string>() << "' ("
            << kind_name(loaded) << ")\n";
  std::cout << "  actions: " << summary["actions"] << " (";
  const auto& actions = summary["action_names"];
  for (std::size_t a = 0; a < actions.size(); ++a)
    std::cout << (a ? ", " : "") << actions[a].get<std::string>();
  std::cout << ")\n";
  if (summary.contains("continuous_variables")) {
    std::cout << "  continuous variables: " << summary["continuous_variables"].size()
              << ", regions: " << summary["regions"] << '\n';
  }
  const std::vector<std::string> names = context_names(loaded);
  std::cout << "  " << std::left << std::setw(24) << "context" << std::setw(12) << "states"
            << std::setw(12) << "choices" << std::setw(14) << "transitions"
            << "rewards\n";
  for (std::size_t c = 0; c < names.size(); ++c) {
    std::cout << "  " << std::setw(24) << names[c];
    if (c < stats.size()) {
      std::cout << std::setw(12) << stats[c].states << std::setw(12) << stats[c].choices
                << std::setw(14) << stats[c].transitions << reward_range(stats[c]) << '\n';
    } else {
      std::cout << "(continuous; partitioned by the geometry layer)\n";
    }
  }
}

int run_info(const InfoOptions& options) {
  SourceManager sources;
  DiagnosticEngine diagnostics(sources, std::cerr, options.common.max_errors);
  auto loaded =
      load_model(options.file, sources, diagnostics, effective_load_options(options.common));
  if (!loaded || diagnostics.has_errors()) return 1;
  std::vector<model::ContextStatistics> stats;
  if (loaded->model) stats = model::context_statistics(*loaded->model);
  if (options.json) {
    std::cout << std::setw(2) << to_json(*loaded, stats) << '\n';
  } else {
    print_text(*loaded, stats);
  }
  return 0;
}

}  // namespace

CommandRunner add_info_command(CLI::App& app) {
  auto options = std::make_shared<InfoOptions>();
  CLI::App* command = app.add_subcommand("info",
                                         "Summarise a model: states, actions, "
                                         "transitions and rewards of each context");
  command->footer(
      "Counts are those of the explicit model: every declared state of an explicit spec,\n"
      "the reachable states of a factored one. 'transitions' counts (state, action,\n"
      "successor) triples with positive probability; 'choices' the enabled (state, action)\n"
      "pairs. Continuous models report their variables; their states come from the\n"
      "geometry layer.\n\n"
      "Examples:\n  oasisc info specs/discrete_tracking.oasis\n"
      "  oasisc info specs/discrete_tracking.oasis --json | jq '.contexts[].name'");
  command->add_option("file", options->file, "Spec (.oasis) or model (.aut, .tra) file")
      ->required();
  command->add_flag("--json", options->json,
                    "Print JSON (keys: model, states, actions, contexts[])");
  add_common_options(*command, options->common);
  return [options] { return run_info(*options); };
}

}  // namespace oasis::cli
