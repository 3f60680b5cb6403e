#include "guarantee/interval_mdp.hpp"

#include <algorithm>
#include <atomic>
#include <stdexcept>
#include <thread>

#include "model/enclosure_program.hpp"

namespace oasis::guarantee {
namespace {

std::vector<double> axis_breaks(const model::ContinuousVariable& variable, std::uint64_t cells) {
  std::vector<double> breaks;
  const Rational width = (variable.high - variable.low) / Rational(static_cast<long>(cells));
  for (std::uint64_t k = 0; k <= cells; ++k) {
    const Rational point = variable.low + Rational(static_cast<long>(k)) * width;
    breaks.push_back(to_double(point));
    if (k > 0 && !(breaks[k] > breaks[k - 1])) {
      throw std::invalid_argument("the grid of " + variable.name +
                                  " has cells narrower than a double can tell apart");
    }
  }
  return breaks;
}

// The rows of cells [begin, end), into per-thread arenas that are joined afterwards.
struct Chunk {
  std::vector<AxisSlice> slices;
  std::vector<double> lower;
  std::vector<double> upper;
};

// What one thread reuses from cell to cell: the cell, its enclosure, the programs' scratch.
struct Workspace {
  std::vector<model::Interval> box;
  std::vector<model::Interval> mean;
  model::EnclosureScratch scratch;
};

class RowBuilder {
 public:
  RowBuilder(const model::ModelIR& ir, const UniformGrid& grid,
             const std::vector<ActionChoice>& actions)
      : grid_(grid), actions_(actions) {
    const model::ContextIR& context = ir.contexts.front();
    for (const ActionChoice& choice : actions) {
      const model::MapDynamics& map = *context.maps[choice.action];
      std::vector<AxisNoise> noise;
      for (const auto& disturbance : map.disturbance)
        noise.push_back(axis_noise(disturbance));
      noise_.push_back(std::move(noise));
      std::vector<model::Interval> inputs;
      for (const Rational& value : choice.inputs)
        inputs.push_back(model::from_rational(value));
      // Compiled once per action and inputs: the map over every cell is then a flat program
      // with the input-only parts evaluated (model/enclosure_program.hpp).
      programs_.emplace_back(map.next, grid.dimension(), inputs);
    }
  }

  void build(std::size_t cell, Chunk& out, Workspace& work) const {
    const std::size_t d = grid_.dimension();
    std::vector<model::Interval>& box = work.box;
    box.resize(d);
    for (std::size_t i = 0; i < d; ++i) {
      const std::size_t k = grid_.coordinate(cell, i);
      box[i] = model::Interval{grid_.breaks[i][k], grid_.breaks[i][k + 1]};
    }
    std::vector<model::Interval>& mean = work.mean;
    for (std::size_t a = 0; a < actions_.size(); ++a) {
      mean.resize(programs_[a].components());
      programs_[a].enclose(box, work.scratch, mean);
      for (std::size_t i = 0; i < d; ++i) {
        AxisRow row = axis_row(noise_[a][i], mean[i].lo, mean[i].hi, grid_.breaks[i]);
        AxisSlice slice;
        slice.first = row.first;
        slice.count = static_cast<std::uint32_t>(row.lower.size());
        slice.offset = out.lower.size();
        slice.outside_lower = row.outside_lower;
        slice.outside_upper = row.outside_upper;
        slice.truncated = row.truncated;
        out.lower.insert(out.lower.end(), row.lower.begin(), row.lower.end());
        out.upper.insert(out.upper.end(), row.upper.begin(), row.upper.end());
        out.slices.push_back(slice);
      }
    }
  }

 private:
  const UniformGrid& grid_;
  const std::vector<ActionChoice>& actions_;
  std::vector<std::vector<AxisNoise>> noise_;
  std::vector<model::EnclosureProgram> programs_;
};

void append(IntervalMdp& mdp, Chunk& chunk) {
  const std::uint64_t base = mdp.lower.size();
  for (AxisSlice& slice : chunk.slices)
    slice.offset += base;
  mdp.slices.insert(mdp.slices.end(), chunk.slices.begin(), chunk.slices.end());
  mdp.lower.insert(mdp.lower.end(), chunk.lower.begin(), chunk.lower.end());
  mdp.upper.insert(mdp.upper.end(), chunk.upper.begin(), chunk.upper.end());
  chunk = Chunk{};
}

void check_budget(const Chunk& sample, std::size_t sampled_cells, std::size_t cells,
                  std::uint64_t budget) {
  if (budget == 0 || sampled_cells == 0) return;
  const double per_cell = static_cast<double>(sample.slices.size() * sizeof(AxisSlice) +
                                              2 * sample.lower.size() * sizeof(double)) /
                          static_cast<double>(sampled_cells);
  const double estimate = per_cell * static_cast<double>(cells);
  if (estimate > static_cast<double>(budget)) {
    throw std::length_error(
        "the interval MDP would take about " +
        std::to_string(static_cast<std::uint64_t>(estimate / (1 << 20))) + " MiB, more than the " +
        std::to_string(budget >> 20) +
        " MiB its rows may have (half the memory budget: raise it with --memory-budget, or use "
        "a coarser grid)");
  }
}

}  // namespace

UniformGrid uniform_grid(const model::ModelIR& ir) {
  UniformGrid grid;
  const std::size_t d = ir.continuous.size();
  grid.strides.assign(d, 1);
  grid.cells = 1;
  for (std::size_t i = 0; i < d; ++i) {
    grid.breaks.push_back(axis_breaks(ir.continuous[i], ir.grid_cells[i]));
    grid.cells *= ir.grid_cells[i];
  }
  for (std::size_t i = d; i-- > 1;)
    grid.strides[i - 1] = grid.strides[i] * ir.grid_cells[i];
  return grid;
}

std::vector<ActionChoice> action_choices(const model::ModelIR& ir) {
  std::vector<ActionChoice> choices;
  const model::ContextIR& context = ir.contexts.front();
  std::size_t combinations = 1;
  for (const model::InputVariable& input : ir.inputs)
    combinations *= input.values.size();
  for (model::ActionIndex a = 0; a < context.maps.size(); ++a) {
    if (!context.maps[a]) continue;
    for (std::size_t c = 0; c < combinations; ++c) {
      ActionChoice choice{a, std::vector<Rational>(ir.inputs.size())};
      std::size_t rest = c;
      for (std::size_t i = ir.inputs.size(); i-- > 0;) {
        const std::size_t count = ir.inputs[i].values.size();
        choice.inputs[i] = ir.inputs[i].values[rest % count];
        rest /= count;
      }
      choices.push_back(std::move(choice));
    }
  }
  return choices;
}

IntervalMdp build_interval_mdp(const model::ModelIR& ir, const BuildOptions& options) {
  IntervalMdp mdp;
  mdp.grid = uniform_grid(ir);
  mdp.actions = action_choices(ir);
  const RowBuilder builder(ir, mdp.grid, mdp.actions);
  const std::size_t cells = mdp.grid.cells;
  // A first sample of cells spread over the grid sizes the abstraction before it is built.
  {
    Chunk sample;
    Workspace workspace;
    const std::size_t step = std::max<std::size_t>(1, cells / 64);
    std::size_t sampled = 0;
    for (std::size_t cell = 0; cell < cells; cell += step, ++sampled)
      builder.build(cell, sample, workspace);
    check_budget(sample, sampled, cells, options.memory_budget);
  }
  const unsigned jobs = std::max(1u, options.jobs);
  constexpr std::size_t kBlock = 1024;  // cells per unit of work, joined in order
  for (std::size_t begin = 0; begin < cells; begin += kBlock * jobs) {
    std::vector<Chunk> chunks(jobs);
    std::vector<std::exception_ptr> errors(jobs);
    auto work = [&](unsigned j) {
      try {
        const std::size_t from = begin + j * kBlock;
        const std::size_t to = std::min(cells, from + kBlock);
        Workspace workspace;
        for (std::size_t cell = from; cell < to; ++cell)
          builder.build(cell, chunks[j], workspace);
      } catch (...) {
        errors[j] = std::current_exception();
      }
    };
    std::vector<std::thread> threads;
    for (unsigned j = 1; j < jobs; ++j)
      threads.emplace_back(work, j);
    work(0);
    for (auto& thread : threads)
      thread.join();
    for (const auto& error : errors)
      if (error) std::rethrow_exception(error);
    for (Chunk& chunk : chunks)
      append(mdp, chunk);
    if (options.progress) options.progress(std::min(cells, begin + kBlock * jobs), cells);
  }
  return mdp;
}

}  // namespace oasis::guarantee
