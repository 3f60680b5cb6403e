#include "property/engine_call.hpp"

namespace oasis::property {

modelcheck::Result run(const EngineCall& call, const model::TransitionMatrix& matrix,
                       const RationalPool& values, const model::RewardTable* rewards,
                       const modelcheck::Options& options) {
  const modelcheck::Problem problem{matrix, values, call.optimum};
  switch (call.op) {
    case EngineCall::Op::kNext:
      return modelcheck::next(problem, call.psi, options);
    case EngineCall::Op::kUntil:
      return modelcheck::until(problem, call.phi, call.psi, options);
    case EngineCall::Op::kBoundedUntil:
      return modelcheck::bounded_until(problem, call.phi, call.psi, call.steps, options);
    case EngineCall::Op::kReachabilityReward:
      return modelcheck::reachability_reward(problem, *rewards, call.psi, options);
    case EngineCall::Op::kCumulative:
      return modelcheck::cumulative_reward(problem, *rewards, call.steps, options);
    case EngineCall::Op::kInstantaneous:
      return modelcheck::instantaneous_reward(problem, *rewards, call.steps, options);
  }
  return {};
}

}  // namespace oasis::property
