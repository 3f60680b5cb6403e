#include "loop/sim_trial.hpp"

#include <stdexcept>

#include "loop/control_loop.hpp"
#include "loop/robot_link.hpp"
#include "loop/treat_contexts.hpp"

namespace oasis::hw::loop {
namespace {

struct Contexts {
  std::uint32_t human1 = 0;
  std::uint32_t human2 = 1;

  std::uint32_t of(TreatHolder holder) const {
    return holder == TreatHolder::kHuman1 ? human1 : human2;
  }
  int holder_of(std::uint32_t context) const { return context == human1 ? 1 : 2; }
};

Contexts contexts_of(const rt::CatalogView& catalog) {
  const std::optional<std::uint32_t> one = context_index(catalog, TreatHolder::kHuman1);
  const std::optional<std::uint32_t> two = context_index(catalog, TreatHolder::kHuman2);
  if (!one || !two)
    throw std::invalid_argument(
        "the simulator needs a catalog with the contexts human1_holds_treat and "
        "human2_holds_treat (specs/go1_treat.oasis)");
  return {*one, *two};
}

sim::HallwayWorldOptions world_options(const SimTrialSetup& setup, std::uint64_t seed) {
  sim::HallwayWorldOptions options;
  options.scenario = setup.scenario;
  options.seed = seed;
  options.period_s = setup.period_s;
  options.camera.intrinsics = setup.intrinsics;
  options.camera.mount = setup.perception.mount;
  options.camera.reach = setup.perception.reach;
  options.render.intrinsics = setup.intrinsics;
  options.render.mount = setup.perception.mount;
  options.render.depth_scale_m_per_unit = setup.depth_scale_m_per_unit;
  options.path = setup.path;
  return options;
}

sim::TraceStep trace_step(const log::StepRecord& record, const sim::FrameTruth& truth,
                          const Contexts& contexts) {
  sim::TraceStep step;
  step.time_s = record.time_s;
  step.true_holder = truth.scene.holder == TreatHolder::kHuman1 ? 1 : 2;
  step.inferred_holder = contexts.holder_of(record.abstraction);
  step.belief_human1 = contexts.human1 < record.belief.size() ? record.belief[contexts.human1] : 0;
  step.rewarded = truth.holder_in_reach;
  step.robot = truth.robot;
  step.people = truth.people;
  return step;
}

}  // namespace

SimTrialResult run_sim_trial(const rt::CatalogView& catalog, const SimTrialSetup& setup,
                             const settings::ControllerProfile& controller, std::uint64_t seed) {
  const Contexts contexts = contexts_of(catalog);
  DryRunLink link;
  sim::HallwayWorld world(world_options(setup, seed), [&link] { return link.pose(); });
  sim::SimulatedPerception simulated(world);
  Perception real(setup.perception);
  PerceptionStage& perception =
      setup.path == sim::ObservationPath::kFast ? static_cast<PerceptionStage&>(simulated) : real;

  auto truth_context = [&world, contexts]() -> std::optional<std::uint32_t> {
    const std::optional<sim::FrameTruth>& truth = world.truth_of_last_frame();
    if (!truth) return std::nullopt;
    return contexts.of(truth->scene.holder);
  };
  const std::unique_ptr<LoopController> decider =
      make_controller(controller, {catalog, setup.controller, truth_context});

  SimTrialResult result;
  LoopParts parts{
      world,
      perception,
      *decider,
      link,
      [&]() -> std::optional<log::GroundTruth> {
        const std::optional<sim::FrameTruth>& truth = world.truth_of_last_frame();
        if (!truth) return std::nullopt;
        return log::GroundTruth{contexts.of(truth->scene.holder),
                                truth->holder_in_reach ? 1.0 : 0.0};
      },
      [&](const log::StepRecord& record) {
        result.records.push_back(record);
        result.trace.push_back(trace_step(record, *world.truth_of_last_frame(), contexts));
      },
      {}};
  LoopOptions options;
  options.period_s = setup.period_s;
  options.realtime = false;
  options.max_steps = setup.max_steps;
  run_loop(parts, options);
  return result;
}

}  // namespace oasis::hw::loop
