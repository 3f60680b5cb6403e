#pragma once
// One call of the numeric engine (modelcheck/engine.hpp), as a value: the evaluator describes
// what it needs once, and it is run on the model itself or on its bisimulation quotient
// (quotient_solve.hpp) the same way.

#include <cstdint>

#include "modelcheck/engine.hpp"

namespace oasis::property {

struct EngineCall {
  enum class Op { kNext, kUntil, kBoundedUntil, kReachabilityReward, kCumulative, kInstantaneous };
  Op op = Op::kUntil;
  modelcheck::Optimum optimum = modelcheck::Optimum::kNone;
  modelcheck::StateSet phi;  // kUntil, kBoundedUntil: the states a path may pass through
  modelcheck::StateSet
      psi;  // kNext, kUntil, kBoundedUntil: the goal; kReachabilityReward: the target
  std::uint32_t steps = 0;                      // the bounded operators
  const model::RewardTable* rewards = nullptr;  // the reward operators

  [[nodiscard]] bool reads_rewards() const {
    return op == Op::kReachabilityReward || op == Op::kCumulative || op == Op::kInstantaneous;
  }
};

// Runs `call` on `matrix`, whose rewards are `rewards` (for the reward operators).
modelcheck::Result run(const EngineCall& call, const model::TransitionMatrix& matrix,
                       const RationalPool& values, const model::RewardTable* rewards,
                       const modelcheck::Options& options);

}  // namespace oasis::property
