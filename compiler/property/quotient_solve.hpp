#pragma once
// Answers on the bisimulation quotient (`oasisc query --bisimulation`, Storm's --bisimulation):
// the coarsest bisimulation of the model (Definition 1, action by action, bisim/) whose
// blocks respect the engine call's state sets and its rewards; the call is solved on the
// quotient and lifted back, every state taking its block's value and its block's action.
// Bisimilar states satisfy the same PCTL and reward properties (Baier and Katoen, Principles
// of Model Checking, 10.4.2), so the lifted values are the model's own, rational for rational.
//
// A lifted scheduler is checked again on the model: the Markov chain it induces there is
// solved and must give every state the lifted value (scheduler_reproduces).

#include <cstdint>
#include <vector>

#include "model/explicit_model.hpp"
#include "property/engine_call.hpp"

namespace oasis::property {

struct QuotientSize {
  std::uint32_t states = 0;
  std::uint32_t blocks = 0;
};

modelcheck::Result solve_on_quotient(const model::ExplicitModel& model, const EngineCall& call,
                                     const modelcheck::Options& options, QuotientSize& size);

// The action a memoryless scheduler takes in s: its own, or the first enabled one where it
// leaves s free (kAnyAction); num_actions where s has no enabled action.
model::ActionIndex scheduled_action(const model::TransitionMatrix& matrix,
                                    const std::vector<model::ActionIndex>& actions,
                                    model::StateIndex s);

// Whether the chain `scheduler` induces on the model (its first context's transitions) gives
// every state the value `result` holds for it: equal rationals in exact mode, overlapping
// intervals in sound mode. Memoryless schedulers only (step-bounded ones are not checked).
bool scheduler_reproduces(const model::ExplicitModel& model, const EngineCall& call,
                          const modelcheck::Result& result, const modelcheck::Options& options);

}  // namespace oasis::property
