// Benchmark of one whole perception step (hw/perception/perception.hpp) at 640x480 on one
// thread: HSV segmentation of both shirts, localisation, the tag search, holder and reward.
//
//   BM_PerceptionStep/D   both people in view, the near one (the treat holder) at D/10 m
//                         (D = 5, 20, 40), with RealSense-like depth noise.
// Reports time per step (one frame per iteration); the goal is >= 60 frames/s.
#include <benchmark/benchmark.h>
#include <opencv2/core/utility.hpp>

#include "perception/perception.hpp"
#include "perception/synthetic_renderer.hpp"

namespace {

using namespace oasis::hw;

Frame scene_with_holder_at(double holder_x_m) {
  SyntheticScene scene;
  scene.people[0] = PersonPlacement{holder_x_m, 0.0};
  scene.people[1] = PersonPlacement{holder_x_m + 1.0, -0.6 * (holder_x_m + 1.0)};
  scene.holder = TreatHolder::kHuman1;
  RenderSettings settings;
  settings.depth_noise = DepthNoise::realsense_like();
  return render_scene(scene, settings);
}

void BM_PerceptionStep(benchmark::State& state) {
  cv::setNumThreads(1);
  const Frame frame = scene_with_holder_at(static_cast<double>(state.range(0)) / 10.0);
  Perception perception;
  for (auto _ : state)
    benchmark::DoNotOptimize(perception.step(frame));
  state.SetItemsProcessed(state.iterations());  // items/s = frames/s
}
BENCHMARK(BM_PerceptionStep)->Arg(5)->Arg(20)->Arg(40)->Unit(benchmark::kMillisecond);

}  // namespace

BENCHMARK_MAIN();
