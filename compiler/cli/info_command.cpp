// `oasisc info FILE [--json]`: the size of every context of a model.

#include <iomanip>
#include <iostream>
#include <memory>
#include <sstream>

#include <nlohmann/json.hpp>

#include "cli/commands.hpp"
#include "geom/relevance.hpp"
#include "model/statistics.hpp"

namespace oasis::cli {
namespace {

struct InfoOptions {
  std::string file;
  bool json = false;
  CommonOptions common;
};

const char* kind_name(const LoadedModel& loaded) {
  // A PRISM program is explored like a factored spec; .aut and .tra files are imported.
  if (!loaded.ir) return loaded.prism_program ? "prism" : "imported";
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

// Attention by exact projection (geom/relevance.hpp): which variables the context reads.
void add_relevance(const model::ModelIR& ir, std::size_t context, nlohmann::json& out) {
  const geom::Relevance relevance = geom::analyse_relevance(ir, context);
  auto names = [&](const std::vector<std::uint32_t>& indices) {
    nlohmann::json list = nlohmann::json::array();
    for (const std::uint32_t v : indices)
      list.push_back(ir.continuous[v].name);
    return list;
  };
  out["relevant_variables"] = names(relevance.relevant);
  out["ignored_variables"] = names(relevance.ignored);
  nlohmann::json reasons = nlohmann::json::object();
  for (std::size_t i = 0; i < relevance.relevant.size(); ++i)
    reasons[ir.continuous[relevance.relevant[i]].name] = relevance.reasons[i];
  out["relevance_reasons"] = reasons;
  out["exact_projection"] = relevance.exact();
  out["failed_conditions"] = relevance.failed_conditions;
}

// A continuous model's measured objects: name, variables, sigma(d) = a + b d + c d^2 as exact
// numbers [a, b, c], detection probability.
nlohmann::json objects_json(const model::ModelIR& ir) {
  nlohmann::json objects = nlohmann::json::array();
  for (const model::MeasuredObject& object : ir.observation.objects) {
    nlohmann::json variables = nlohmann::json::array();
    for (const std::uint32_t v : object.variables)
      variables.push_back(ir.continuous[v].name);
    objects.push_back(
        {{"name", object.name},
         {"variables", variables},
         {"sigma",
          {to_string(object.sigma[0]), to_string(object.sigma[1]), to_string(object.sigma[2])}},
         {"detection", to_string(object.detection)}});
  }
  return objects;
}

// The spec's observation model: null when it declares none.
nlohmann::json observation_json(const model::ObservationSpec& observation,
                                const model::StateSpace* states, const model::ModelIR* ir) {
  using Kind = model::ObservationSpec::Kind;
  if (!observation.objects.empty() && ir != nullptr)
    return {{"kind", "objects"},
            {"objects", objects_json(*ir)},
            {"reward_follows", observation.reward_follows_observed ? "observed" : "true"}};
  if (observation.kind == Kind::kNone) return nlohmann::json();
  nlohmann::json out;
  if (observation.kind == Kind::kSymmetric) {
    out["kind"] = "symmetric";
    out["noise"] = to_string(observation.noise);
  } else {
    out["kind"] = "matrix";
    const std::size_t n = states != nullptr ? states->size : 0;
    nlohmann::json rows = nlohmann::json::object();
    for (std::size_t s = 0; s < n; ++s) {
      nlohmann::json row = nlohmann::json::object();
      for (std::size_t o = 0; o < n; ++o) {
        const Rational& p = observation.confusion[s * n + o];
        if (p != 0) row[states->name(static_cast<model::StateIndex>(o))] = to_string(p);
      }
      rows[states->name(static_cast<model::StateIndex>(s))] = row;
    }
    out["confusion"] = rows;
  }
  out["reward_follows"] = observation.reward_follows_observed ? "observed" : "true";
  return out;
}

// A model with an objective (docs/guarantees.md): its inputs, finite actions, objective and grid.
nlohmann::json objective_json(const model::ModelIR& ir) {
  const model::GuaranteeObjective& objective = *ir.guarantee;
  nlohmann::json inputs = nlohmann::json::array();
  std::size_t combinations = 1;
  for (const model::InputVariable& input : ir.inputs) {
    inputs.push_back({{"name", input.name}, {"values", input.values.size()}});
    combinations *= input.values.size();
  }
  std::size_t with_dynamics = 0;
  for (const auto& map : ir.contexts.front().maps)
    with_dynamics += map ? 1 : 0;
  std::uint64_t cells = 1;
  for (const std::uint64_t n : ir.grid_cells)
    cells *= n;
  const bool safety = objective.kind == model::GuaranteeObjective::Kind::Safety;
  return {{"kind", safety ? "safety" : "reach-avoid"},
          {"steps", objective.steps ? nlohmann::json(*objective.steps) : nlohmann::json()},
          {"exactly_at_step", objective.exactly_at_step},
          {"inputs", inputs},
          {"finite_actions", with_dynamics * combinations},
          {"grid", ir.grid_cells},
          {"cells", cells}};
}

void print_objective(const nlohmann::json& objective) {
  const bool bounded = !objective["steps"].is_null();
  const bool at_step = objective["exactly_at_step"].get<bool>();
  std::cout << "  objective: " << objective["kind"].get<std::string>();
  if (bounded) {
    std::cout << (at_step ? ", exactly at step " : ", ") << objective["steps"]
              << (at_step ? "" : " steps");
  } else {
    std::cout << ", unbounded";
  }
  std::cout << "\n  inputs:";
  for (const auto& input : objective["inputs"])
    std::cout << ' ' << input["name"].get<std::string>() << " (" << input["values"] << " values)";
  if (objective["inputs"].empty()) std::cout << " none";
  std::cout << "; finite actions: " << objective["finite_actions"] << "\n  grid:";
  for (std::size_t i = 0; i < objective["grid"].size(); ++i)
    std::cout << (i == 0 ? " " : " x ") << objective["grid"][i];
  std::cout << " (" << objective["cells"] << " cells)\n";
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
    if (loaded.ir->guarantee) out["objective"] = objective_json(*loaded.ir);
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
      if (!loaded.ir->guarantee) add_relevance(*loaded.ir, c, context);
    }
    contexts.push_back(context);
  }
  out["contexts"] = contexts;
  // The stated properties (docs/spec-language.md, "Properties"); their values are the
  // catalog's, which `compile` prints and writes.
  nlohmann::json properties = nlohmann::json::array();
  for (std::size_t k = 0; k < loaded.properties.size(); ++k) {
    const auto& stated = loaded.model ? loaded.model->properties : loaded.ir->properties;
    properties.push_back(
        {{"name", stated[k].name}, {"property", loaded.properties[k].properties.front().text}});
  }
  out["properties"] = properties;
  out["observation"] = observation_json(
      loaded.model ? loaded.model->observation : loaded.ir->observation,
      loaded.model ? &loaded.model->states : nullptr, loaded.ir ? &*loaded.ir : nullptr);
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

std::string joined(const nlohmann::json& names) {
  std::string text;
  for (const auto& name : names)
    text += (text.empty() ? "" : ", ") + name.get<std::string>();
  return text.empty() ? "none" : text;
}

void print_relevance(const nlohmann::json& context) {
  std::cout << "continuous: attends to " << joined(context["relevant_variables"]) << "; ignores "
            << joined(context["ignored_variables"])
            << (context["exact_projection"].get<bool>() ? " (exact projection)\n"
                                                        : " (NOT an exact projection)\n");
  for (const auto& [name, reason] : context["relevance_reasons"].items()) {
    std::cout << "  " << std::setw(24) << "" << name << ": read by " << reason.get<std::string>()
              << '\n';
  }
  for (const auto& condition : context["failed_conditions"])
    std::cout << "  " << std::setw(24) << ""
              << "fails: " << condition.get<std::string>() << '\n';
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
  const nlohmann::json& observation = summary["observation"];
  if (!observation.is_null() && observation["kind"] == "objects") {
    std::cout << "  observation: reward follows "
              << observation["reward_follows"].get<std::string>() << '\n';
    for (const auto& object : observation["objects"]) {
      const auto& sigma = object["sigma"];
      std::cout << "    object " << object["name"].get<std::string>() << " ("
                << joined(object["variables"]) << "): sigma(d) = " << sigma[0].get<std::string>()
                << " + " << sigma[1].get<std::string>() << " d + " << sigma[2].get<std::string>()
                << " d^2, detection " << object["detection"].get<std::string>() << '\n';
    }
  } else if (!observation.is_null()) {
    std::cout << "  observation: "
              << (observation["kind"] == "symmetric"
                      ? "state noise " + observation["noise"].get<std::string>()
                      : std::string("state confusion matrix"))
              << ", reward follows " << observation["reward_follows"].get<std::string>() << '\n';
  }
  if (summary.contains("objective")) {
    // No catalog, hence no contexts to attend with: the objective is solved on the whole grid.
    print_objective(summary["objective"]);
    return;
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
      print_relevance(summary["contexts"][c]);
    }
  }
  for (const auto& property : summary["properties"]) {
    std::cout << "  property " << property["name"].get<std::string>() << " = "
              << property["property"].get<std::string>() << '\n';
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
      "pairs. Continuous models report their variables and, per context, the variables it\n"
      "attends to: those its rewards read, closed under the dynamics (relevant_variables,\n"
      "ignored_variables; docs/geometry.md); their states come from the geometry layer.\n\n"
      "Examples:\n  oasisc info specs/discrete_tracking.oasis\n"
      "  oasisc info specs/discrete_tracking.oasis --json | jq '.contexts[].name'");
  command
      ->add_option(
          "file", options->file,
          "Spec (.oasis), PRISM program (.pm, .nm, .prism) or model (.aut, .tra, .drn, .umb) "
          "file")
      ->required();
  command->add_flag("--json", options->json,
                    "Print JSON (keys: model, states, actions, contexts[])");
  add_common_options(*command, options->common);
  return [options] { return run_info(*options); };
}

}  // namespace oasis::cli
