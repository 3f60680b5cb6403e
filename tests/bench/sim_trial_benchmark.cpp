// Benchmark of one `oasis-go1 sim` trial on the fast path (hw/loop/sim_trial.hpp): 300 steps
// (one minute at 5 Hz) of the hallway world, the simulated camera, the controller and the loop,
// everything but the output files. Issue 14 asks for well under a second of CPU per trial.
//
//   BM_FastTrial/oracle|paper|ours   one whole trial per iteration (time per trial)
//   BM_RenderedSteps                 10 steps of the rendered path (renderer + real perception)
//
// Run by hand: build/default/hw/loop/oasis-sim-trial-benchmark
#include <string>

#include <benchmark/benchmark.h>

#include "go1_treat_catalog.hpp"
#include "loop/sim_trial.hpp"
#include "settings/settings.hpp"

namespace {

using namespace oasis::hw;

loop::SimTrialSetup fast_setup() {
  loop::SimTrialSetup setup;
  setup.controller.action_velocity =
      settings::velocity_table(settings::default_settings(), go1_treat::catalog());
  return setup;
}

void run_trials(benchmark::State& state, const std::string& controller,
                const loop::SimTrialSetup& setup) {
  const settings::ControllerProfile kind = settings::find_controller_profile(controller);
  std::uint64_t seed = 1;
  std::size_t steps = 0;
  for (auto _ : state) {
    const loop::SimTrialResult result =
        loop::run_sim_trial(go1_treat::catalog(), setup, kind, seed++);
    steps += result.records.size();
    benchmark::DoNotOptimize(result.records.data());
  }
  state.counters["steps"] =
      benchmark::Counter(static_cast<double>(steps), benchmark::Counter::kAvgIterations);
  state.counters["steps/s"] =
      benchmark::Counter(static_cast<double>(steps), benchmark::Counter::kIsRate);
}

void BM_FastTrial(benchmark::State& state, const char* controller) {
  run_trials(state, controller, fast_setup());
}
BENCHMARK_CAPTURE(BM_FastTrial, oracle, "oracle")->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_FastTrial, paper, "paper")->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_FastTrial, ours, "ours")->Unit(benchmark::kMillisecond);

void BM_RenderedSteps(benchmark::State& state) {
  loop::SimTrialSetup setup = fast_setup();
  setup.path = sim::ObservationPath::kRendered;
  setup.max_steps = 10;
  run_trials(state, "ours", setup);
}
BENCHMARK(BM_RenderedSteps)->Unit(benchmark::kMillisecond);

}  // namespace

BENCHMARK_MAIN();
