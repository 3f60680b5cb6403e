#include "pipeline/guarantee_compile.hpp"

#include <chrono>
#include <cstdio>

#include "guarantee/objective_cells.hpp"
#include "guarantee/row_classes.hpp"
#include "support/text.hpp"

namespace oasis::pipeline {
namespace {

double seconds_since(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

std::string format(const char* pattern, double a, double b, double c) {
  char text[160];
  std::snprintf(text, sizeof text, pattern, a, b, c);
  return text;
}

}  // namespace

GuaranteeResult compile_guarantee(const model::ModelIR& ir, const GuaranteeOptions& options) {
  GuaranteeResult result;
  auto start = std::chrono::steady_clock::now();
  guarantee::BuildOptions build;
  build.jobs = options.jobs;
  build.memory_budget = options.memory_budget;
  std::size_t reported_tenths = 0;
  if (options.progress) {
    // A line per tenth of the cells: the abstraction of a large grid takes a minute.
    build.progress = [&](std::size_t done, std::size_t all) {
      const std::size_t tenths = all == 0 ? 10 : done * 10 / all;
      if (tenths <= reported_tenths || tenths >= 10) return;
      reported_tenths = tenths;
      options.progress(format("abstraction: %.0f of %.0f cells (%.1f s)", static_cast<double>(done),
                              static_cast<double>(all), seconds_since(start)));
    };
  }
  guarantee::IntervalMdp mdp = guarantee::build_interval_mdp(ir, build);
  result.abstraction_seconds = seconds_since(start);
  result.entries = mdp.entries();
  result.bytes = mdp.bytes();
  result.distinct_rows = guarantee::distinct_rows(mdp);
  if (options.progress) {
    options.progress(format("abstraction: %.0f cells x %.0f actions (%.2f s)",
                            static_cast<double>(mdp.grid.cells),
                            static_cast<double>(mdp.actions.size()), result.abstraction_seconds));
  }
  start = std::chrono::steady_clock::now();
  const guarantee::ObjectiveCells cells = guarantee::objective_cells(*ir.guarantee, ir, mdp.grid);
  result.synthesis = guarantee::synthesise(mdp, *ir.guarantee, cells, options.synthesis);
  result.synthesis_seconds = seconds_since(start);
  result.grid = std::move(mdp.grid);
  result.actions = std::move(mdp.actions);
  return result;
}

std::string describe_cell(const guarantee::UniformGrid& grid, const model::ModelIR& ir,
                          std::size_t cell) {
  std::string text;
  for (std::size_t i = 0; i < grid.dimension(); ++i) {
    const std::size_t k = grid.coordinate(cell, i);
    const bool last = k + 1 == grid.intervals(i);
    text += (i == 0 ? "" : ", ") + ir.continuous[i].name + " in [" +
            shortest_double(grid.breaks[i][k]) + ", " + shortest_double(grid.breaks[i][k + 1]) +
            (last ? "]" : ")");
  }
  return text;
}

}  // namespace oasis::pipeline
