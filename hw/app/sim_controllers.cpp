#include "app/sim_controllers.hpp"

#include "app/oracle_controller.hpp"

namespace oasis::hw::app {
namespace {

std::unique_ptr<LoopController> attention_with(const SimControllerInputs& inputs,
                                               const rt::FilterOptions& filter) {
  ControllerSettings settings = inputs.settings;
  settings.filter = filter;
  return std::make_unique<AttentionController>(inputs.catalog, std::move(settings));
}

// Our options: the zero-likelihood guard, and the noise-aware filter on the catalog's
// position-noise model (rt::FilterMode::kRobust, specs/go1_treat.oasis's camera).
rt::FilterOptions ours() {
  rt::FilterOptions options;
  options.zero_likelihood_guard = true;
  options.mode = rt::FilterMode::kRobust;
  return options;
}

}  // namespace

const std::vector<SimControllerKind>& sim_controller_kinds() {
  static const std::vector<SimControllerKind> kinds{
      {"oracle", "told who holds the treat: that context's policy, the upper bound",
       [](const SimControllerInputs& inputs) -> std::unique_ptr<LoopController> {
         return std::make_unique<OracleController>(inputs.catalog, inputs.settings, inputs.truth);
       }},
      {"paper", "OAS with Algorithm 1's defaults (a zero likelihood restarts from the prior)",
       [](const SimControllerInputs& inputs) { return attention_with(inputs, {}); }},
      {"guard",
       "OAS with the zero-likelihood guard on (keep the prediction), Algorithm 1 otherwise",
       [](const SimControllerInputs& inputs) {
         rt::FilterOptions guard;
         guard.zero_likelihood_guard = true;
         return attention_with(inputs, guard);
       }},
      {"ours",
       "OAS with the zero-likelihood guard on (keep the prediction) and the noise-aware filter "
       "(the catalog's sigma(d))",
       [](const SimControllerInputs& inputs) { return attention_with(inputs, ours()); }},
  };
  return kinds;
}

const SimControllerKind* find_sim_controller(const std::string& name) {
  for (const SimControllerKind& kind : sim_controller_kinds())
    if (kind.name == name) return &kind;
  return nullptr;
}

}  // namespace oasis::hw::app
