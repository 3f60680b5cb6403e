#pragma once
// The controllers `oasis-go1 sim` compares on the same seeded trials, by name:
//   oracle  told the true context (oracle_controller.hpp): the upper bound
//   paper   OAS with Algorithm 1's defaults (rt::FilterOptions{}: on a zero likelihood the
//           belief restarts from the prior)
//   guard   OAS with the zero-likelihood guard alone
//   no-attention  OAS (with the guard) on a catalog whose every abstraction partitions the
//           full 4-D state: what the ignored person does to a policy without attention
//   ours    OAS with our options: the zero-likelihood guard on (the belief keeps its
//           prediction when no context explains the observation) and the noise-aware filter
//           (rt::FilterMode::kRobust on the catalog's position noise)
// A baseline is one more entry: a name, a line for --help, and how to build it from the
// trial's catalog, settings and truth.
#include <cstdint>
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "app/attention_controller.hpp"
#include "app/loop_controller.hpp"

namespace oasis::hw::app {

struct SimControllerInputs {
  const rt::CatalogView& catalog;
  ControllerSettings settings;  // action velocities and missing people from oasis-go1's settings
  // The index of the true context of the frame just taken; only the oracle may call it.
  std::function<std::optional<std::uint32_t>()> truth;
};

struct SimControllerKind {
  std::string name;
  std::string description;
  // Runs on the no-attention catalog (every context's policy over the full state, compiled
  // with `oasisc compile --no-attention`) instead of the session's.
  bool full_state_catalog = false;
  std::function<std::unique_ptr<LoopController>(const SimControllerInputs&)> make;
};

// Every controller, in the order the tables list them.
const std::vector<SimControllerKind>& sim_controller_kinds();

// The kind called `name`; nothing if there is none.
const SimControllerKind* find_sim_controller(const std::string& name);

}  // namespace oasis::hw::app
