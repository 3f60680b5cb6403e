#include "verify/controller_simulation.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <stdexcept>
#include <string>
#include <utility>

#include "support/rational.hpp"

namespace oasis::verify {
namespace {

std::vector<HalfSpace> half_spaces(const std::vector<model::LinearConstraint>& constraints) {
  std::vector<HalfSpace> set;
  for (const model::LinearConstraint& constraint : constraints) {
    HalfSpace half{{}, to_double(constraint.bound), constraint.strict};
    for (const Rational& coefficient : constraint.coefficients)
      half.coefficients.push_back(to_double(coefficient));
    set.push_back(std::move(half));
  }
  return set;
}

AxisDisturbance axis_disturbance(const model::DisturbanceModel& disturbance) {
  return {disturbance.kind, to_double(disturbance.first), to_double(disturbance.second)};
}

SimulatedAction simulated_action(const model::ModelIR& ir, const model::MapDynamics& map,
                                 std::vector<double> inputs) {
  SimulatedAction action;
  const std::size_t n = ir.continuous.size();
  if (map.next.size() != n || map.disturbance.size() != n)
    throw std::invalid_argument("a map without one coordinate and one disturbance per variable");
  for (std::size_t i = 0; i < n; ++i) {
    try {
      action.next.push_back(DoubleProgram::compile(map.next[i], n, ir.inputs.size()));
    } catch (const std::invalid_argument& e) {
      throw std::invalid_argument("the map of " + ir.continuous[i].name + "' holds " + e.what());
    }
    action.noise.push_back(axis_disturbance(map.disturbance[i]));
  }
  action.inputs = std::move(inputs);
  return action;
}

// The inputs' values of combination `c`, the last input varying fastest.
std::vector<double> input_combination(const model::ModelIR& ir, std::size_t c) {
  std::vector<double> values(ir.inputs.size());
  for (std::size_t i = ir.inputs.size(); i-- > 0;) {
    const std::size_t count = ir.inputs[i].values.size();
    values[i] = to_double(ir.inputs[i].values[c % count]);
    c /= count;
  }
  return values;
}

// One step: x <- f_a(x) + w, through `next` (a buffer of x's size).
void step(const SimulatedAction& action, std::vector<double>& x, std::vector<double>& next,
          NoiseSource& noise) {
  for (std::size_t i = 0; i < x.size(); ++i)
    next[i] = action.next[i].evaluate(x, action.inputs) + sample(action.noise[i], noise);
  x.swap(next);
}

}  // namespace

NoiseSource::NoiseSource(std::uint64_t seed, std::uint64_t stream) {
  std::seed_seq sequence{static_cast<std::uint32_t>(seed), static_cast<std::uint32_t>(seed >> 32),
                         static_cast<std::uint32_t>(stream),
                         static_cast<std::uint32_t>(stream >> 32)};
  engine_.seed(sequence);
}

double NoiseSource::uniform() {
  return static_cast<double>(engine_() >> 11) * 0x1p-53;
}

double NoiseSource::standard_normal() {
  if (has_spare_) {
    has_spare_ = false;
    return spare_;
  }
  const double u1 = 1 - uniform();  // (0, 1]: the logarithm stays finite
  const double u2 = uniform();
  const double radius = std::sqrt(-2 * std::log(u1));
  const double angle = 2 * std::numbers::pi * u2;
  spare_ = radius * std::sin(angle);
  has_spare_ = true;
  return radius * std::cos(angle);
}

std::uint64_t NoiseSource::below(std::uint64_t n) {
  // Draws under 2^64 mod n would make the small residues likelier: they are drawn again.
  const std::uint64_t threshold = (0 - n) % n;
  for (;;) {
    const std::uint64_t draw = engine_();
    if (draw >= threshold) return draw % n;
  }
}

double sample(const AxisDisturbance& disturbance, NoiseSource& noise) {
  switch (disturbance.kind) {
    case model::DisturbanceModel::Kind::Gaussian:
      return disturbance.first + disturbance.second * noise.standard_normal();
    case model::DisturbanceModel::Kind::Bounded:
      return disturbance.first + (disturbance.second - disturbance.first) * noise.uniform();
    default:
      return 0;
  }
}

bool contains(const std::vector<HalfSpace>& set, std::span<const double> x) {
  for (const HalfSpace& half : set) {
    double sum = 0;
    for (std::size_t i = 0; i < x.size(); ++i)
      sum += half.coefficients[i] * x[i];
    if (half.strict ? !(sum < half.bound) : !(sum <= half.bound)) return false;
  }
  return true;
}

SimulatedSystem simulated_system(const model::ModelIR& ir) {
  if (!ir.guarantee || ir.contexts.empty())
    throw std::invalid_argument("the spec states no objective");
  SimulatedSystem system;
  std::size_t combinations = 1;
  for (const model::InputVariable& input : ir.inputs)
    combinations *= input.values.size();
  for (const std::optional<model::MapDynamics>& map : ir.contexts.front().maps) {
    if (!map) continue;
    for (std::size_t c = 0; c < combinations; ++c)
      system.actions.push_back(simulated_action(ir, *map, input_combination(ir, c)));
  }
  const model::GuaranteeObjective& objective = *ir.guarantee;
  system.safe = half_spaces(objective.safe);
  system.target = half_spaces(objective.target);
  system.reach = objective.kind == model::GuaranteeObjective::Kind::ReachAvoid;
  system.steps = objective.steps;
  system.exactly_at_step = objective.exactly_at_step;
  return system;
}

GridLocator::GridLocator(std::vector<std::vector<double>> breaks)
    : breaks_(std::move(breaks)), strides_(breaks_.size(), 1) {
  for (std::size_t i = breaks_.size(); i-- > 0;) {
    strides_[i] = cells_;
    cells_ *= breaks_[i].size() - 1;
  }
}

std::optional<std::size_t> GridLocator::cell_of(std::span<const double> x) const {
  std::size_t cell = 0;
  for (std::size_t i = 0; i < breaks_.size(); ++i) {
    const std::vector<double>& t = breaks_[i];
    if (!(x[i] >= t.front() && x[i] <= t.back())) return std::nullopt;  // NaN too
    // The interval [t_k, t_{k+1}) holding x; x = t_n belongs to the last, closed one.
    const auto above = std::upper_bound(t.begin(), t.end(), x[i]);
    const auto k =
        std::min<std::size_t>(static_cast<std::size_t>(above - t.begin()) - 1, t.size() - 2);
    cell += k * strides_[i];
  }
  return cell;
}

std::vector<double> GridLocator::random_point(std::size_t cell, NoiseSource& noise) const {
  std::vector<double> point(breaks_.size());
  for (std::size_t i = 0; i < breaks_.size(); ++i) {
    const std::vector<double>& t = breaks_[i];
    const std::size_t k = cell / strides_[i] % (t.size() - 1);
    const double x = t[k] + (t[k + 1] - t[k]) * noise.uniform();
    // Rounding may land on t_{k+1}, which belongs to the next interval (but the last).
    point[i] = x < t[k + 1] || k + 2 == t.size() ? std::min(x, t[k + 1]) : t[k];
  }
  return point;
}

RunEnd simulate_run(const SimulatedSystem& system, const GridLocator& grid,
                    const ControllerRows& rows, std::span<const double> start,
                    std::uint64_t max_steps, NoiseSource& noise) {
  std::vector<double> x(start.begin(), start.end());
  std::vector<double> next(x.size());
  const bool bounded = system.steps.has_value();
  for (std::uint64_t k = 0;; ++k) {
    const bool last = bounded && k == *system.steps;
    if (system.reach) {
      if ((!system.exactly_at_step || last) && contains(system.target, x)) return RunEnd::Success;
      if (last) return RunEnd::Failure;
    }
    if (!contains(system.safe, x)) return RunEnd::Failure;
    const std::optional<std::size_t> cell = grid.cell_of(x);
    // S empty is the domain, the box itself: leaving it is leaving S.
    if (!cell) return system.safe.empty() ? RunEnd::Failure : RunEnd::LeftBox;
    if (last) return RunEnd::Success;  // safety: in S at steps 0..N
    if (!bounded && k == max_steps) return RunEnd::Unfinished;
    step(system.actions[rows[bounded ? k : 0][*cell]], x, next, noise);
  }
}

RunCounts simulate_runs(const SimulatedSystem& system, const GridLocator& grid,
                        const ControllerRows& rows, std::span<const double> start,
                        std::uint64_t runs, std::uint64_t max_steps, NoiseSource& noise) {
  RunCounts counts;
  counts.runs = runs;
  for (std::uint64_t r = 0; r < runs; ++r) {
    switch (simulate_run(system, grid, rows, start, max_steps, noise)) {
      case RunEnd::Success:
        ++counts.successes;
        break;
      case RunEnd::LeftBox:
        ++counts.left_box;
        break;
      case RunEnd::Unfinished:
        ++counts.unfinished;
        break;
      case RunEnd::Failure:
        break;
    }
  }
  return counts;
}

}  // namespace oasis::verify
