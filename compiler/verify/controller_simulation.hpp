#pragma once
// Simulating the true system of a continuous model under a controller file, for the
// Monte-Carlo check of its bounds (controller_check.hpp; docs/guarantees.md for the
// semantics). Everything here is the verifier's own: the map in doubles (map_evaluation.hpp),
// the noise from a 64-bit Mersenne Twister through our own transforms, the sets read as
// half-spaces in doubles, the cell of a state found by binary search on the file's
// breakpoints.
//
// A run from x_0 follows x_{k+1} = f(x_k, u_k) + w_k, u_k the controller's action in the cell of
// x_k (at step k for a bounded objective, the one table otherwise), w_k independent per axis.
// It ends
//   - in success: reach-avoid, x_k in T (within N steps; `at N`: at step N only); safety, x_0
//     .. x_N all in S;
//   - in failure: x_k outside S before success, or the bound N passed;
//   - having left the box: x_k in S but outside the grid's box, where the controller has no
//     cell (S stated; the default S is the domain, the box itself). It counts as a failure, the
//     pessimistic reading, and is counted apart so that the check can say how often it
//     happened;
//   - unfinished: an unbounded objective still undecided after the step cap; counted as a
//     failure, and apart.

#include <cstddef>
#include <cstdint>
#include <optional>
#include <random>
#include <span>
#include <vector>

#include "model/model_ir.hpp"
#include "verify/map_evaluation.hpp"

namespace oasis::verify {

// Uniform and Gaussian numbers from std::mt19937_64. The transforms are ours, so that a seed
// gives the same numbers with every standard library: a uniform double is the top 53 bits of
// one draw, a Gaussian pair comes from two uniforms by the Box-Muller transform.
class NoiseSource {
 public:
  // Stream `stream` of seed `seed`: distinct streams are independent for the check's purpose.
  NoiseSource(std::uint64_t seed, std::uint64_t stream);

  double uniform();  // [0, 1)
  double standard_normal();
  std::uint64_t below(std::uint64_t n);  // uniform in [0, n), n > 0 (rejection, no bias)

 private:
  std::mt19937_64 engine_;
  double spare_ = 0;  // Box-Muller's second number of the pair
  bool has_spare_ = false;
};

// One axis's w: Gaussian(first = mean, second = deviation), uniform on [first, second], none.
struct AxisDisturbance {
  model::DisturbanceModel::Kind kind = model::DisturbanceModel::Kind::None;
  double first = 0;
  double second = 0;
};

double sample(const AxisDisturbance& disturbance, NoiseSource& noise);

// sum coefficients[i] * x_i <= bound (< when strict), in doubles.
struct HalfSpace {
  std::vector<double> coefficients;
  double bound = 0;
  bool strict = false;
};

// In every half-space (the empty conjunction holds everywhere).
bool contains(const std::vector<HalfSpace>& set, std::span<const double> x);

// One finite action of the controller: a declared action with its inputs' values.
struct SimulatedAction {
  std::vector<DoubleProgram> next;  // f_i per axis
  std::vector<double> inputs;
  std::vector<AxisDisturbance> noise;  // per axis
};

struct SimulatedSystem {
  std::vector<SimulatedAction> actions;  // in the order of the controller's action indices
  std::vector<HalfSpace> safe;           // empty: the domain (with the box, below)
  std::vector<HalfSpace> target;         // reach-avoid
  bool reach = false;
  std::optional<std::uint64_t> steps;  // bounded
  bool exactly_at_step = false;
};

// The spec's system: each declared action with dynamics (the first context's maps) times each
// combination of the inputs' values, the last input varying fastest; the inputs' values and
// every constant rounded to the nearest double. Throws std::invalid_argument (one sentence)
// when a map holds what DoubleProgram does not evaluate or the spec states no objective.
SimulatedSystem simulated_system(const model::ModelIR& ir);

// The controller's cells: products of [t_k, t_{k+1}) (the last interval closed) of the file's
// breakpoints, numbered with the last axis varying fastest.
class GridLocator {
 public:
  // `breaks` per axis, each strictly increasing with at least two entries.
  explicit GridLocator(std::vector<std::vector<double>> breaks);

  [[nodiscard]] std::size_t cells() const { return cells_; }
  // The cell holding x, or nullopt outside the box (or at a NaN coordinate).
  [[nodiscard]] std::optional<std::size_t> cell_of(std::span<const double> x) const;
  // A uniformly random point of `cell`.
  [[nodiscard]] std::vector<double> random_point(std::size_t cell, NoiseSource& noise) const;

 private:
  std::vector<std::vector<double>> breaks_;
  std::vector<std::size_t> strides_;
  std::size_t cells_ = 1;
};

enum class RunEnd { Success, Failure, LeftBox, Unfinished };

struct RunCounts {
  std::uint64_t runs = 0;
  std::uint64_t successes = 0;
  std::uint64_t left_box = 0;    // failures only because the box was left (in S)
  std::uint64_t unfinished = 0;  // failures only because the step cap came first
};

// The table of the controller file: rows[k][cell] for a bounded objective, rows[0][cell]
// otherwise; every index below system.actions.size(), every row one entry per cell.
using ControllerRows = std::vector<std::vector<std::uint64_t>>;

// One run from `start`; `max_steps` caps an unbounded objective.
RunEnd simulate_run(const SimulatedSystem& system, const GridLocator& grid,
                    const ControllerRows& rows, std::span<const double> start,
                    std::uint64_t max_steps, NoiseSource& noise);

// `runs` runs from `start`.
RunCounts simulate_runs(const SimulatedSystem& system, const GridLocator& grid,
                        const ControllerRows& rows, std::span<const double> start,
                        std::uint64_t runs, std::uint64_t max_steps, NoiseSource& noise);

}  // namespace oasis::verify
