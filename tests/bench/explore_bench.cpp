// Benchmark of exploration alone, without the CLI's statistics and output: the slippery
// N x N grid of explore_benchmark.py (4 actions, 2 outcomes per move, self-loops at the walls)
// as a .oasis spec and as a PRISM program, checked and explored in memory.
//
//   BM_ExploreSpec/N    frontend::check_spec_text + model::explore
//   BM_ExplorePrism/N   prism::load_program_text (lex, parse, check, explore)
//
// The counter states_per_second is what issues 25 and 41 state their goals in (10^6, then
// 2 * 10^6 on one core, at 10^6 and 10^7 states); it is states over CPU time.
//   build/default/tests/oasis-explore-benchmark --benchmark_filter=/1000
#include <cstdint>
#include <optional>
#include <sstream>
#include <string>

#include <benchmark/benchmark.h>

#include "frontend/load_spec.hpp"
#include "model/explorer.hpp"
#include "prism/load_program.hpp"

namespace {

std::string spec_grid(std::int64_t side) {
  return "mdp grid {\n  const N = " + std::to_string(side) +
         ";\n"
         "  var x : [0 .. N-1];\n  var y : [0 .. N-1];\n"
         "  actions left, right, up, down;\n  default self;\n"
         "  [left]  x > 0     -> 0.9: (x' = x - 1) + 0.1: true;\n"
         "  [right] x < N - 1 -> 0.9: (x' = x + 1) + 0.1: true;\n"
         "  [down]  y > 0     -> 0.9: (y' = y - 1) + 0.1: true;\n"
         "  [up]    y < N - 1 -> 0.9: (y' = y + 1) + 0.1: true;\n"
         "  reward x == N - 1 & y == N - 1 : 1;\n}\n";
}

std::string prism_grid(std::int64_t side) {
  return "mdp\nconst int N = " + std::to_string(side) +
         ";\n"
         "module grid\n  x : [0..N-1] init 0;\n  y : [0..N-1] init 0;\n"
         "  [left]  x > 0   -> 0.9 : (x'=x-1) + 0.1 : true;\n  [left]  x = 0   -> true;\n"
         "  [right] x < N-1 -> 0.9 : (x'=x+1) + 0.1 : true;\n  [right] x = N-1 -> true;\n"
         "  [down]  y > 0   -> 0.9 : (y'=y-1) + 0.1 : true;\n  [down]  y = 0   -> true;\n"
         "  [up]    y < N-1 -> 0.9 : (y'=y+1) + 0.1 : true;\n  [up]    y = N-1 -> true;\n"
         "endmodule\n";
}

// Runs `load` (text in `sources` -> explicit model) once per iteration, fresh each time.
template <typename Load>
void time_exploration(benchmark::State& state, const std::string& name, const std::string& text,
                      Load&& load) {
  std::uint32_t states = 0;
  for (auto _ : state) {
    oasis::SourceManager sources;
    std::ostringstream messages;
    oasis::DiagnosticEngine diagnostics(sources, messages);
    const oasis::FileId file = sources.add(name, text);
    const std::optional<oasis::model::ExplicitModel> model = load(file, diagnostics);
    if (!model) state.SkipWithError(messages.str().c_str());
    if (model) states = model->num_states();
    benchmark::DoNotOptimize(model);
  }
  state.counters["states"] = states;
  state.counters["states_per_second"] = benchmark::Counter(
      static_cast<double>(states), benchmark::Counter::kIsIterationInvariantRate);
}

void BM_ExploreSpec(benchmark::State& state) {
  time_exploration(state, "grid.oasis", spec_grid(state.range(0)),
                   [](oasis::FileId file, oasis::DiagnosticEngine& diagnostics) {
                     const auto ir = oasis::frontend::check_spec_text(file, diagnostics);
                     return ir ? oasis::model::explore(*ir, diagnostics) : std::nullopt;
                   });
}

void BM_ExplorePrism(benchmark::State& state) {
  time_exploration(state, "grid.nm", prism_grid(state.range(0)),
                   [](oasis::FileId file, oasis::DiagnosticEngine& diagnostics) {
                     return oasis::prism::load_program_text(file, "grid", diagnostics, {});
                   });
}

// 10^4, 10^5, 10^6 and 10^7 states (3163^2 = 10,004,569, the size explore_benchmark.py --large
// explores); the last takes a few seconds and about 2 GiB per iteration.
BENCHMARK(BM_ExploreSpec)->Arg(100)->Arg(316)->Arg(1000)->Arg(3163)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_ExplorePrism)->Arg(100)->Arg(316)->Arg(1000)->Arg(3163)->Unit(benchmark::kMillisecond);

}  // namespace

BENCHMARK_MAIN();
