// Benchmark of AttentionFilter::step (runtime/include/oasis/rt/attention_filter.hpp).
//
//   BM_PaperStep/N     paper mode on N synthetic abstractions over 64 states (N = 2, 64):
//                      dense switching matrix (stay 0.8, the rest spread evenly), block
//                      rewards chosen so that most observations keep several abstractions alive.
//   BM_RobustDiscrete  robust joint filter on the paper's discrete example (3 states, 2
//                      abstractions, p_correct 0.7).
//   BM_HedgedDiscrete  HedgedFilter (Algorithm 1 + the robust filter, weighed by their reward
//                      evidence) on the same example.
//   BM_Go1Step/mode    the shipped Go1 catalog (generated/go1_treat/go1_treat.bin: 2
//                      abstractions, 84 x 101 cells each) on a walk of readings, paper mode (0)
//                      and the noise-aware robust mode (1) with the spec's sigma(d); the
//                      counter `boxes` is the reward-region boxes integrated per step.
// Reports ns per step (Google Benchmark's time per iteration, one step per iteration).
#include <cmath>
#include <cstdint>
#include <string>
#include <vector>

#include <benchmark/benchmark.h>

#include "oasis/rt/attention_filter.hpp"
#include "oasis/rt/bsp_locator.hpp"
#include "oasis/rt/catalog_file.hpp"
#include "oasis/rt/catalog_validation.hpp"
#include "oasis/rt/catalog_view.hpp"
#include "oasis/rt/grid_locator.hpp"
#include "oasis/rt/hedged_filter.hpp"
#include "oasis/rt/reward_mass.hpp"

namespace {

using namespace oasis::rt;

// Owns the arrays behind a synthetic CatalogView.
struct SyntheticCatalog {
  std::uint32_t n;
  std::uint32_t states;
  std::vector<double> switching;
  std::vector<double> prior;
  std::vector<std::vector<std::uint32_t>> block_of;
  std::vector<std::vector<double>> block_reward;
  std::vector<std::vector<std::uint32_t>> begin;
  std::vector<std::vector<std::uint32_t>> target;
  std::vector<std::vector<double>> probability;
  std::vector<std::vector<double>> reward;
  std::vector<std::vector<std::uint32_t>> policy;
  std::vector<std::vector<double>> value;
  std::vector<AbstractionView> abstractions;
  const char* action_names[2] = {"a", "b"};
  CatalogView view;

  SyntheticCatalog(std::uint32_t num_abstractions, std::uint32_t num_states)
      : n(num_abstractions), states(num_states) {
    switching.assign(static_cast<std::size_t>(n) * n, n > 1 ? 0.2 / (n - 1) : 0.0);
    for (std::uint32_t i = 0; i < n; ++i)
      switching[i * n + i] = n > 1 ? 0.8 : 1.0;
    prior.assign(n, 1.0 / n);
    // Abstraction i: two blocks, block 1 = {state i mod S} with reward 1, the rest reward 0;
    // each block moves to itself under both actions.
    for (std::uint32_t i = 0; i < n; ++i) {
      std::vector<std::uint32_t> of(states, 0);
      of[i % states] = 1;
      block_of.push_back(of);
      block_reward.push_back({0.0, 1.0});
      begin.push_back({0, 1, 2, 3, 4});
      target.push_back({0, 0, 1, 1});
      probability.push_back({1.0, 1.0, 1.0, 1.0});
      reward.push_back({0.0, 0.0, 1.0, 1.0});
      policy.push_back({0, 1});
      value.push_back({0.0, 10.0});
    }
    abstractions.resize(n);
    for (std::uint32_t i = 0; i < n; ++i) {
      AbstractionView& a = abstractions[i];
      a.context = "synthetic";
      a.num_blocks = 2;
      a.block_of = block_of[i].data();
      a.block_reward = block_reward[i].data();
      a.quotient = {begin[i].data(), target[i].data(), probability[i].data(), 4};
      a.reward = reward[i].data();
      a.policy = policy[i].data();
      a.value = value[i].data();
    }
    view.name = "synthetic";
    view.compiler_version = "bench";
    view.num_states = states;
    view.num_actions = 2;
    view.action_names = action_names;
    view.num_abstractions = n;
    view.switching = switching.data();
    view.prior = prior.data();
    view.abstractions = abstractions.data();
  }
};

void BM_PaperStep(benchmark::State& state) {
  const auto n = static_cast<std::uint32_t>(state.range(0));
  SyntheticCatalog catalog(n, 64);
  std::string why;
  if (!validate(catalog.view, &why)) {
    state.SkipWithError(why.c_str());
    return;
  }
  FilterOptions options;
  options.zero_likelihood_guard = true;
  std::vector<double> workspace(AttentionFilter::workspace_size(catalog.view, options));
  AttentionFilter filter(catalog.view, options, workspace.data(), workspace.size());
  filter.start(0);
  std::uint32_t s = 0;
  std::uint64_t k = 0;
  for (auto _ : state) {
    // Reward 0 at a state no abstraction rewards, now and then reward 1 at state s.
    const double r = (k % 7 == 0) ? 1.0 : 0.0;
    benchmark::DoNotOptimize(filter.step(s, r, static_cast<std::uint32_t>(k & 1)));
    benchmark::DoNotOptimize(filter.action());
    s = (s + 13) % 64;
    ++k;
  }
  state.SetItemsProcessed(state.iterations());
}
BENCHMARK(BM_PaperStep)->Arg(2)->Arg(64);

// The filter a discrete benchmark runs: the robust joint filter, or the hedge of it with
// Algorithm 1 (hedged_filter.hpp).
template <bool Hedged>
struct DiscreteFilter;
template <>
struct DiscreteFilter<false> {
  FixedWorkspace<2, 3> workspace;
  AttentionFilter filter;
  explicit DiscreteFilter(const CatalogView& view) : filter(view, options(), workspace) {}
  static FilterOptions options() {
    FilterOptions robust;
    robust.mode = FilterMode::kJoint;
    return robust;
  }
};
template <>
struct DiscreteFilter<true> {
  std::vector<double> workspace;
  HedgedFilter filter;
  explicit DiscreteFilter(const CatalogView& view)
      : workspace(HedgedFilter::workspace_size(view, {})),
        filter(view, {}, workspace.data(), workspace.size()) {}
};

template <bool Hedged>
void BM_Discrete(benchmark::State& state) {
  static const char* action_names[2] = {"L", "R"};
  static const double switching[4] = {0.8, 0.2, 0.2, 0.8};
  static const double prior[2] = {0.5, 0.5};
  static const std::uint32_t a0_block_of[3] = {0, 0, 1};
  static const std::uint32_t a1_block_of[3] = {0, 1, 1};
  static const double a0_block_reward[2] = {0.0, 1.0};
  static const double a1_block_reward[2] = {1.0, 0.0};
  static const std::uint32_t a0_begin[5] = {0, 1, 3, 4, 5};
  static const std::uint32_t a0_target[5] = {0, 0, 1, 0, 1};
  static const double a0_prob[5] = {1.0, 0.5, 0.5, 1.0, 1.0};
  static const std::uint32_t a1_begin[5] = {0, 1, 2, 4, 5};
  static const std::uint32_t a1_target[5] = {0, 1, 0, 1, 1};
  static const double a1_prob[5] = {1.0, 1.0, 0.5, 0.5, 1.0};
  static const double a0_reward[4] = {0.0, 0.0, 1.0, 1.0};
  static const double a1_reward[4] = {1.0, 1.0, 0.0, 0.0};
  static const std::uint32_t a0_policy[2] = {1, 1};
  static const std::uint32_t a1_policy[2] = {0, 0};
  static const double value[2] = {4.5 / 0.55, 10.0};
  static const std::uint32_t st_begin[7] = {0, 1, 3, 5, 7, 9, 10};
  static const std::uint32_t st_target[10] = {0, 1, 2, 0, 1, 1, 2, 0, 1, 2};
  static const double st_prob[10] = {1.0, 0.5, 0.5, 0.5, 0.5, 0.5, 0.5, 0.5, 0.5, 1.0};
  AbstractionView abstractions[2];
  abstractions[0] = {"object_at_s3",
                     2,
                     a0_block_of,
                     a0_block_reward,
                     {a0_begin, a0_target, a0_prob, 5},
                     a0_reward,
                     a0_policy,
                     value,
                     {st_begin, st_target, st_prob, 10},
                     {0, nullptr, nullptr, nullptr},
                     nullptr,
                     0,
                     0.0,
                     {}};
  abstractions[1] = {"object_at_s1",
                     2,
                     a1_block_of,
                     a1_block_reward,
                     {a1_begin, a1_target, a1_prob, 5},
                     a1_reward,
                     a1_policy,
                     value,
                     {st_begin, st_target, st_prob, 10},
                     {0, nullptr, nullptr, nullptr},
                     nullptr,
                     0,
                     0.0,
                     {}};
  CatalogView view;
  view.name = "discrete_tracking";
  view.compiler_version = "bench";
  view.num_states = 3;
  view.num_actions = 2;
  view.action_names = action_names;
  view.num_abstractions = 2;
  view.switching = switching;
  view.prior = prior;
  view.abstractions = abstractions;
  view.observation.kind = ObservationKind::kSymmetric;
  view.observation.p_correct = 0.7;
  std::string why;
  if (!validate(view, &why)) {
    state.SkipWithError(why.c_str());
    return;
  }
  DiscreteFilter<Hedged> discrete(view);
  auto& filter = discrete.filter;
  filter.start(1);
  // A fixed cycle of plausible (action, observed state, reward) triples.
  static const std::uint32_t cycle_action[6] = {1, 1, 1, 0, 0, 0};
  static const std::uint32_t cycle_state[6] = {1, 2, 2, 1, 0, 0};
  static const double cycle_reward[6] = {0.0, 1.0, 1.0, 0.0, 0.0, 0.0};
  std::uint32_t k = 0;
  for (auto _ : state) {
    benchmark::DoNotOptimize(filter.step(cycle_state[k], cycle_reward[k], cycle_action[k]));
    benchmark::DoNotOptimize(filter.action());
    k = (k + 1) % 6;
  }
  state.SetItemsProcessed(state.iterations());
}
void BM_RobustDiscrete(benchmark::State& state) {
  BM_Discrete<false>(state);
}
void BM_HedgedDiscrete(benchmark::State& state) {
  BM_Discrete<true>(state);
}
BENCHMARK(BM_RobustDiscrete);
BENCHMARK(BM_HedgedDiscrete);

// 4096 points of [0, 5]^dimension, one after the other (xorshift: no <random> needed in the
// runtime's benchmark).
std::vector<double> random_points(std::uint32_t dimension) {
  std::vector<double> points(4096 * std::size_t{dimension});
  std::uint64_t seed = 88172645463325252ULL;
  for (double& x : points) {
    seed ^= seed << 13;
    seed ^= seed >> 7;
    seed ^= seed << 17;
    x = 5.0 * static_cast<double>(seed % 1000000) / 1000000.0;
  }
  return points;
}

// The arrays of a grid over [0, 5]^dimension, `intervals` equal intervals per axis.
struct UniformGrid {
  std::vector<std::uint32_t> axes;
  std::vector<std::uint32_t> begin{0};
  std::vector<double> breaks;

  UniformGrid(std::uint32_t intervals, std::uint32_t dimension) {
    for (std::uint32_t i = 0; i < dimension; ++i) {
      axes.push_back(i);
      for (std::uint32_t k = 0; k <= intervals; ++k)
        breaks.push_back(5.0 * k / intervals);
      begin.push_back(static_cast<std::uint32_t>(breaks.size()));
    }
  }
  [[nodiscard]] oasis::rt::GridView view() const {
    return {static_cast<std::uint32_t>(axes.size()), axes.data(), begin.data(), breaks.data()};
  }
};

// Point location in a gridded continuous abstraction (grid_locator.hpp): the Go1 catalog's
// grid at epsilon 0.1 has 84 x 101 intervals over (x, y); the argument is the number of
// intervals per axis, over `dimension` axes, at random points of the domain.
void BM_LocateCell(benchmark::State& state) {
  const auto intervals = static_cast<std::uint32_t>(state.range(0));
  const auto dimension = static_cast<std::uint32_t>(state.range(1));
  const UniformGrid arrays(intervals, dimension);
  const oasis::rt::GridView grid = arrays.view();
  const std::vector<double> points = random_points(dimension);
  std::size_t next = 0;
  for (auto _ : state) {
    benchmark::DoNotOptimize(oasis::rt::locate_cell(grid, points.data() + next, dimension));
    next = (next + dimension) % points.size();
  }
}
BENCHMARK(BM_LocateCell)->Args({84, 2})->Args({101, 2})->Args({1000, 2})->Args({15, 4});

// Point location in polytope cells (bsp_locator.hpp): the domain box, then a walk down the
// BSP, one dot product per level. The cost depends on the depth reached, so the tree here is
// complete: 2^depth cells over `dimension` axes, slanted hyperplanes through [0, 5]^d.
void BM_LocateBsp(benchmark::State& state) {
  const auto depth = static_cast<std::uint32_t>(state.range(0));
  const auto dimension = static_cast<std::uint32_t>(state.range(1));
  const UniformGrid arrays(1, dimension);  // the domain box: the BSP refines its one cell
  const oasis::rt::GridView grid = arrays.view();
  const std::uint32_t internal = (1U << depth) - 1;
  const std::uint32_t nodes = 2 * internal + 1;
  std::vector<double> normal(std::size_t{nodes} * dimension, 0.0);
  std::vector<double> bound(nodes, 0.0);
  std::vector<std::uint32_t> below(nodes, 0);
  std::vector<std::uint32_t> above(nodes, 0);
  std::vector<std::uint32_t> cell(nodes, oasis::rt::kInternalNode);
  for (std::uint32_t n = 0; n < nodes; ++n) {
    if (n >= internal) {
      cell[n] = n - internal;
      continue;
    }
    below[n] = 2 * n + 1;
    above[n] = 2 * n + 2;
    for (std::uint32_t i = 0; i < dimension; ++i)
      normal[std::size_t{n} * dimension + i] = 1.0 + 0.1 * ((n + i) % 7);
    bound[n] = 2.5 * (1.0 + 0.1 * dimension);
  }
  const oasis::rt::BspView bsp{nodes,        1U << depth,  normal.data(), bound.data(),
                               below.data(), above.data(), cell.data()};
  const std::vector<double> points = random_points(dimension);
  std::size_t next = 0;
  for (auto _ : state) {
    benchmark::DoNotOptimize(
        oasis::rt::locate_partition_cell(grid, bsp, points.data() + next, dimension));
    next = (next + dimension) % points.size();
  }
}
BENCHMARK(BM_LocateBsp)->Args({10, 2})->Args({16, 2})->Args({10, 4});

}  // namespace

// Readings of two people walking around in front of the robot (deterministic), with the
// reward of human 1 in reach.
std::vector<std::vector<double>> go1_readings() {
  std::vector<std::vector<double>> readings;
  for (int t = 0; t < 256; ++t) {
    const double phase = 0.05 * t;
    readings.push_back({0.55 + 0.4 * std::sin(phase), 0.3 * std::cos(1.3 * phase),
                        2.0 + 1.5 * std::sin(0.7 * phase), 1.5 * std::cos(0.4 * phase)});
  }
  return readings;
}

void BM_Go1Step(benchmark::State& state) {
  static const LoadedCatalog catalog = LoadedCatalog::from_file(
      std::string(OASIS_SOURCE_DIR) + "/generated/go1_treat/go1_treat.bin");
  if (!catalog.ok()) {
    state.SkipWithError(catalog.error().c_str());
    return;
  }
  FilterOptions options;
  options.mode = state.range(0) == 1 ? FilterMode::kNoiseAware : FilterMode::kPaper;
  options.zero_likelihood_guard = true;
  std::vector<double> workspace(AttentionFilter::workspace_size(catalog.view(), options));
  AttentionFilter filter(catalog.view(), options, workspace.data(), workspace.size());
  const std::vector<std::vector<double>> readings = go1_readings();
  filter.start(readings[0].data(), 4);
  std::size_t t = 0;
  for (auto _ : state) {
    const std::vector<double>& reading = readings[t++ % readings.size()];
    const double reward = reading[0] >= 0.3 && reading[0] <= 0.8 && std::fabs(reading[1]) <= 0.25;
    benchmark::DoNotOptimize(filter.step(reading.data(), 4, reward, 0));
  }
  if (options.mode == FilterMode::kNoiseAware) {
    // Boxes per step, measured on the same readings outside the timed loop.
    std::vector<double> mass_workspace(RewardMass::workspace_size(catalog.view()));
    RewardMass mass(catalog.view(), {}, mass_workspace.data());
    double boxes = 0;
    for (const std::vector<double>& reading : readings) {
      mass.measure(reading.data());
      for (std::uint32_t i = 0; i < catalog.view().num_abstractions; ++i) {
        const AbstractionView& abs = catalog.view().abstractions[i];
        boxes += mass.match_mass(abs, reading.data(),
                                 [&](std::uint32_t b) { return abs.block_reward[b] == 1.0; })
                     .boxes;
      }
    }
    state.counters["boxes"] = boxes / static_cast<double>(readings.size());
  }
}
BENCHMARK(BM_Go1Step)->Arg(0)->Arg(1);

BENCHMARK_MAIN();
