#pragma once
// One context of a continuous model for the polytope path: the box domain, the rewards as
// polytopes (any conjunction of linear inequalities), and per action the affine step and the
// uniform disturbances, all restricted to the context's relevant axes (geom/relevance.hpp).
// Unlike geom/grid_geometry.hpp (the grid path), nothing here needs product structure:
// reward regions may be rotated or triangular and deterministic moves may mix axes.
// Gaussian disturbances are still refused.

#include <cstddef>
#include <optional>
#include <string>
#include <vector>

#include "geom/polytope.hpp"
#include "geom/relevance.hpp"
#include "model/model_ir.hpp"

namespace oasis::geom {

// w uniform on [low, high], low < high.
struct UniformDisturbance {
  Rational low;
  Rational high;

  [[nodiscard]] Rational width() const { return high - low; }
};

// x'_i = Σ_j matrix[i][j] x_j + offset[i] + w_i over the relevant axes; w_i is uniform on
// disturbance[i], or 0 when that is nullopt (the axis moves deterministically).
struct AffineStep {
  std::vector<std::vector<Rational>> matrix;
  std::vector<Rational> offset;
  std::vector<std::optional<UniformDisturbance>> disturbance;

  [[nodiscard]] bool has_undisturbed_axis() const;
};

// A reward `value` on `region` (a polytope inside the domain; a strict inequality is taken
// as non-strict, which changes the region by a set of measure zero).
struct PolytopeReward {
  Polytope region;
  Rational value;
};

struct PolytopeGeometry {
  std::string context;
  Relevance relevance;
  std::vector<std::string> axis_names;  // the relevant variables, in order
  Point domain_low;                     // per relevant axis
  Point domain_high;
  std::vector<PolytopeReward> rewards;
  std::vector<AffineStep> actions;  // per action of the model

  [[nodiscard]] std::size_t dimension() const { return domain_low.size(); }
  [[nodiscard]] Polytope domain() const { return Polytope::box(domain_low, domain_high); }
};

// The geometry of context `context` on the axes `relevance` keeps. nullopt with `error` set
// (a sentence) for what this path does not handle: a reward that is not a constant on a
// polyhedral condition, an action-dependent reward, a reward reading an ignored variable,
// a Gaussian disturbance, an action without dynamics, or no relevant variable.
std::optional<PolytopeGeometry> polytope_geometry(const model::ModelIR& ir, std::size_t context,
                                                  const Relevance& relevance, std::string& error);

}  // namespace oasis::geom
