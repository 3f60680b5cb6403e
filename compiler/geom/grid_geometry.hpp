#pragma once
// One context of a continuous model, seen on the variables it attends to: the box domain,
// the reward boxes and, per action, the affine step and the disturbance, all restricted to
// the relevant axes (geom/relevance.hpp). Everything the partition and the probabilities
// need, checked once, in exact rationals.
//
// This first geometry path handles product structure: reward conditions that are boxes
// (every inequality reads one variable) and, per axis, a uniform or a Gaussian disturbance or
// none. Variables
// without a disturbance must move on their own axis (x' = a x + b, a != 0), so that the
// pre-image of an interval is an interval. Anything else is refused with a sentence saying
// what the grid cannot follow; the pipeline then takes the polytope path
// (geom/polytope_partition.hpp).

#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "geom/relevance.hpp"
#include "model/model_ir.hpp"

namespace oasis::geom {

struct Interval {
  Rational low;
  Rational high;
};

// A reward r on the box Π [low_i, high_i] (bounds clipped to the domain; a strict inequality
// differs from a non-strict one only on a boundary, which has measure zero).
struct RewardBox {
  std::vector<Interval> box;  // per relevant axis
  Rational value;
};

// w ~ Normal(mean, deviation²), deviation > 0.
struct Gaussian {
  Rational mean;
  Rational deviation;
};

// The disturbance w_i of one axis under one action: none (w_i = 0), uniform on an interval of
// positive width, or Gaussian. Only the member its kind names is meaningful.
struct Disturbance {
  enum class Kind { None, Uniform, Gaussian };
  Kind kind = Kind::None;
  Interval uniform;
  Gaussian gaussian;

  [[nodiscard]] bool present() const { return kind != Kind::None; }
};

// x'_i = Σ_j matrix[i][j] x_j + offset[i] + w_i over the relevant axes.
struct AxisDynamics {
  std::vector<std::vector<Rational>> matrix;
  std::vector<Rational> offset;
  std::vector<Disturbance> disturbance;  // per relevant axis
  // Per relevant axis: a bound on |f_i(x) - (A x + b)_i| when the spec's coefficients are
  // irrational and A, b round them (model::AffineDynamics::approximation); 0 when exact.
  std::vector<Rational> approximation;
};

struct GridGeometry {
  std::string context;
  Relevance relevance;
  std::vector<std::string> axis_names;  // the relevant variables, in order
  std::vector<Interval> domain;         // per relevant axis
  std::vector<RewardBox> rewards;
  std::vector<AxisDynamics> actions;  // per action of the model

  [[nodiscard]] std::size_t dimension() const { return domain.size(); }
  // True when axis i has no disturbance under any action: its cells come from pre-images.
  [[nodiscard]] bool deterministic(std::size_t axis) const;
};

// The geometry of context `context`; `relevance` says which axes to keep (analyse_relevance,
// or full_state for the no-attention baseline). nullopt with `error` set when the context is
// outside what this path handles.
std::optional<GridGeometry> grid_geometry(const model::ModelIR& ir, std::size_t context,
                                          const Relevance& relevance, std::string& error);

}  // namespace oasis::geom
