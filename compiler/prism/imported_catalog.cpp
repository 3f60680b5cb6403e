#include "prism/imported_catalog.hpp"

#include <algorithm>
#include <filesystem>

#include "support/text.hpp"

namespace oasis::prism {
namespace {

// The spec's constants in the form --const gives them, each located at its `const` item.
std::vector<ConstantOverride> spec_constants(const model::ImportedProgram& imported) {
  std::vector<ConstantOverride> given;
  for (const auto& constant : imported.constants) {
    const bool is_bool = constant.type == model::Type::Bool;
    const std::string text =
        is_bool ? (constant.value != 0 ? "true" : "false") : constant.value.get_str();
    given.push_back({constant.name, text, constant.type, constant.value, constant.range});
  }
  return given;
}

// The reward structures the catalog names, each once, with where it first names it.
void select_rewards(const model::ModelIR& ir, LoadOptions& options) {
  options.rewards = model::LabelSelection{model::LabelSelection::Kind::kNamed, {}};
  options.reward_ranges.clear();
  for (const model::ContextIR& context : ir.contexts) {
    if (!context.reward_structure) continue;
    const auto& names = options.rewards.names;
    if (std::find(names.begin(), names.end(), *context.reward_structure) != names.end()) continue;
    options.rewards.names.push_back(*context.reward_structure);
    options.reward_ranges.push_back(context.reward_structure_range);
  }
  if (options.rewards.names.empty()) options.rewards.kind = model::LabelSelection::Kind::kNone;
}

// The explored program has one context per selected reward structure (or one without
// rewards when none is selected), all over the same transitions: make the catalog's.
std::vector<model::Context> catalog_contexts(const model::ModelIR& ir,
                                             const model::ExplicitModel& explored) {
  const auto& transitions = explored.contexts.front().transitions;
  std::vector<model::Context> contexts;
  for (const model::ContextIR& wanted : ir.contexts) {
    model::Context context{wanted.name, transitions, {}};
    if (wanted.reward_structure) {
      const auto source =
          std::find_if(explored.contexts.begin(), explored.contexts.end(),
                       [&](const model::Context& c) { return c.name == *wanted.reward_structure; });
      context.rewards = source->rewards;  // the checker refused names the program lacks
    } else {
      context.rewards.state.assign(explored.num_states(), RationalPool::kZero);
    }
    contexts.push_back(std::move(context));
  }
  return contexts;
}

}  // namespace

std::string imported_program_path(const std::string& spec_path, const std::string& imported) {
  const std::filesystem::path file(imported);
  if (file.is_absolute()) return imported;
  return (std::filesystem::path(spec_path).parent_path() / file).lexically_normal().string();
}

std::optional<model::ExplicitModel> load_imported_catalog(const model::ModelIR& ir,
                                                          const std::string& spec_path,
                                                          SourceManager& sources,
                                                          DiagnosticEngine& diagnostics,
                                                          LoadOptions options) {
  const model::ImportedProgram& imported = *ir.imported;
  if (!is_program_path(imported.path)) {
    diagnostics.error(imported.path_range, "can import a PRISM program (.pm, .nm or .prism), not " +
                                               quoted(std::string_view(imported.path)));
    return std::nullopt;
  }
  options.spec_constants = spec_constants(imported);
  options.imported_at = imported.path_range;
  select_rewards(ir, options);
  auto explored =
      load_program(imported_program_path(spec_path, imported.path), sources, diagnostics, options);
  if (!explored) return std::nullopt;

  model::ExplicitModel model = std::move(*explored);
  model.contexts = catalog_contexts(ir, model);
  model.switching = ir.switching;
  model.objective = ir.objective;
  model.observation = ir.observation;
  model.properties = ir.properties;
  return model;
}

}  // namespace oasis::prism
