#pragma once
// The compile of an explicit model, end to end: every context's coarsest bisimulation
// (bisim/), its quotient and the policy solved on it (policy/), then the catalog in the
// runtime's schema (model/catalog_data.hpp). `oasisc compile`, `oasisc quotient` and
// `oasis-sim` all run this one path; contexts are independent and run in parallel.

#include <cstddef>
#include <cstdint>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "bisim/refinement.hpp"
#include "model/catalog_data.hpp"
#include "model/explicit_model.hpp"
#include "model/partition.hpp"
#include "policy/objective.hpp"
#include "policy/value_iteration.hpp"

namespace oasis::pipeline {

struct DiscreteOptions {
  // Approximate refinement for floating-point models (the user's --epsilon): sums are compared
  // after rounding to multiples of this step (docs/bisimulation.md); unset: exact.
  std::optional<double> rounding_step;
  // Also build each quotient and solve its policy; false stops at the partition (`quotient`).
  bool solve = true;
  unsigned jobs = 0;  // threads; 0: one per hardware thread, at most one per context
  policy::PolicyOptions policy;
  // Called now and then by the thread refining `context` (from several threads at once).
  std::function<void(std::size_t context, const bisim::RefinementProgress&)> progress;
  // The states' classes of respected labels (model::label_classes); empty: none respected.
  std::vector<std::uint32_t> label_class;
  // Storm's MDP semantics (bisim::RefinementOptions::unlabelled_choices); partitions only.
  bool unlabelled_choices = false;
};

struct DiscreteAbstraction {
  std::size_t context = 0;  // index into the model's contexts
  model::Partition partition;
  bisim::RefinementStatistics statistics;
  double refinement_seconds = 0;
  // With DiscreteOptions::solve only:
  model::ExplicitModel quotient;  // one context, over blocks (bisim/quotient.hpp)
  policy::Policy policy;          // on the quotient
};

// Every context of `model`, in order.
std::vector<std::size_t> all_contexts(const model::ExplicitModel& model);

// Abstracts `contexts` (indices into the model's contexts), results in the same order.
// nullopt with `error` naming the first context whose policy did not converge.
std::optional<std::vector<DiscreteAbstraction>> abstract_contexts(
    const model::ExplicitModel& model, const std::vector<std::size_t>& contexts,
    const DiscreteOptions& options, std::string& error);

struct CatalogOptions {
  // Add the robust filter's section: the full-state transitions of every context and a
  // symmetric observation model that reports the true state with this probability. It
  // replaces the state model of the spec's `observation` block, if any (whose reward source
  // stays); unset, the catalog carries the spec's observation model, or none.
  std::optional<double> p_correct;
};

// The catalog of abstractions made by abstract_contexts(model, all_contexts(model), ...) with
// `solve`. nullopt with `error` when the model cannot be a catalog: states of one block with
// different state rewards R(s) (the detection model compares an observed reward with one
// R(s) per abstract state), or several contexts without a switching model.
std::optional<model::CatalogData> catalog_data(const model::ExplicitModel& model,
                                               const std::vector<DiscreteAbstraction>& abstractions,
                                               std::uint64_t spec_hash,
                                               const CatalogOptions& options, std::string& error);

struct BuildOptions {
  DiscreteOptions abstraction;
  CatalogOptions catalog;
};

// abstract_contexts on every context, then catalog_data. nullopt with `error` also when the
// model has no states or no contexts.
std::optional<model::CatalogData> build_catalog(const model::ExplicitModel& model,
                                                std::uint64_t spec_hash,
                                                const BuildOptions& options, std::string& error);

}  // namespace oasis::pipeline
