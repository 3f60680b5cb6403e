// The polytope path end to end on small models: the BSP partition, its finite MDP and its
// error bound, from 1-D to 4-D. The checks are independent of the code under test where it
// matters: cell volumes are estimated by sampling, memberships, successor distributions and
// areas are recomputed here in doubles (polygon clipping in 2-D, sampling above).

#include <algorithm>
#include <chrono>
#include <cmath>
#include <iostream>
#include <optional>
#include <random>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "../../support/spec_models.hpp"
#include "bisim/refinement.hpp"
#include "geom/polytope_geometry.hpp"
#include "geom/polytope_mdp.hpp"
#include "geom/polytope_partition.hpp"
#include "geom/relevance.hpp"

namespace oasis {
namespace {

using Vector = std::vector<double>;

// A cell as plain doubles: rows a·x <= b.
struct PlainCell {
  std::vector<Vector> normals;
  Vector bounds;

  [[nodiscard]] double worst_violation(const Vector& x) const {
    double worst = -1e300;
    for (std::size_t r = 0; r < normals.size(); ++r) {
      double value = -bounds[r];
      for (std::size_t j = 0; j < x.size(); ++j)
        value += normals[r][j] * x[j];
      worst = std::max(worst, value);
    }
    return worst;
  }
};

// Everything a check needs, in doubles, taken from the exact results once.
struct Plain {
  std::vector<PlainCell> cells;
  Vector low;
  Vector high;
  std::vector<std::vector<Vector>> matrix;  // per action
  std::vector<Vector> offset;
  std::vector<std::vector<std::optional<std::pair<double, double>>>> disturbance;

  // The cell whose interior holds x (ties on faces are improbable for random points), or
  // cells.size() for outside.
  [[nodiscard]] std::size_t locate(const Vector& x) const {
    for (std::size_t i = 0; i < x.size(); ++i)
      if (x[i] < low[i] || x[i] > high[i]) return cells.size();
    std::size_t best = 0;
    double best_violation = 1e300;
    for (std::size_t c = 0; c < cells.size(); ++c) {
      const double violation = cells[c].worst_violation(x);
      if (violation < best_violation) {
        best_violation = violation;
        best = c;
      }
    }
    return best;
  }

  [[nodiscard]] Vector mean(std::size_t action, const Vector& x) const {
    Vector m = offset[action];
    for (std::size_t i = 0; i < m.size(); ++i)
      for (std::size_t j = 0; j < x.size(); ++j)
        m[i] += matrix[action][i][j] * x[j];
    return m;
  }
};

Plain plain_of(const geom::PolytopeGeometry& geometry, const geom::BspTree& tree) {
  Plain plain;
  for (const geom::BspCell& cell : tree.cells()) {
    PlainCell c;
    for (const geom::HalfSpace& h : cell.polytope.constraints()) {
      Vector normal;
      for (const Rational& a : h.normal)
        normal.push_back(to_double(a));
      c.normals.push_back(normal);
      c.bounds.push_back(to_double(h.bound));
    }
    plain.cells.push_back(std::move(c));
  }
  for (std::size_t i = 0; i < geometry.dimension(); ++i) {
    plain.low.push_back(to_double(geometry.domain_low[i]));
    plain.high.push_back(to_double(geometry.domain_high[i]));
  }
  for (const geom::AffineStep& step : geometry.actions) {
    std::vector<Vector> matrix;
    for (const auto& row : step.matrix) {
      Vector r;
      for (const Rational& a : row)
        r.push_back(to_double(a));
      matrix.push_back(r);
    }
    plain.matrix.push_back(matrix);
    Vector offset;
    for (const Rational& t : step.offset)
      offset.push_back(to_double(t));
    plain.offset.push_back(offset);
    std::vector<std::optional<std::pair<double, double>>> w;
    for (const auto& d : step.disturbance)
      w.push_back(d ? std::optional(std::pair(to_double(d->low), to_double(d->high)))
                    : std::nullopt);
    plain.disturbance.push_back(w);
  }
  return plain;
}

geom::PolytopeGeometry geometry_of(const model::ModelIR& ir, std::size_t context = 0) {
  std::string error;
  auto geometry = geom::polytope_geometry(ir, context, geom::analyse_relevance(ir, context), error);
  EXPECT_TRUE(geometry) << error;
  return geometry ? std::move(*geometry) : geom::PolytopeGeometry{};
}

// The row of `cell` under `action` as a dense vector of doubles (outside last).
Vector dense_row(const model::ExplicitModel& mdp, std::size_t cell, model::ActionIndex action) {
  const model::TransitionMatrix& matrix = *mdp.contexts[0].transitions;
  Vector row(mdp.num_states(), 0);
  const auto s = static_cast<model::StateIndex>(cell);
  for (auto e = matrix.edges_begin(s, action); e < matrix.edges_end(s, action); ++e)
    row[matrix.edge_target[e]] = to_double(mdp.values[matrix.edge_probability[e]]);
  return row;
}

// A compiled context: geometry, partition and finite MDP, with timings printed.
struct Compiled {
  model::ModelIR ir;
  geom::PolytopeGeometry geometry;
  std::optional<geom::PolytopePartition> partition;
  geom::PolytopeMdp mdp;
  Plain plain;

  Compiled(const std::string& spec, geom::PolytopePartitionOptions options)
      : ir(test::check_spec_text_ir(spec)), geometry(geometry_of(ir)) {
    std::string error;
    const auto start = std::chrono::steady_clock::now();
    partition = geom::partition_polytopes(geometry, options, error);
    EXPECT_TRUE(partition) << error;
    if (!partition) return;
    const auto partitioned = std::chrono::steady_clock::now();
    mdp = geom::polytope_finite_mdp(geometry, *partition, ir.actions, ir.objective);
    const auto built = std::chrono::steady_clock::now();
    plain = plain_of(geometry, partition->tree);
    auto seconds = [](auto a, auto b) { return std::chrono::duration<double>(b - a).count(); };
    std::cout << geometry.dimension() << "-D: cells " << partition->tree.num_cells() << ", epsilon "
              << to_double(partition->epsilon) << " (met " << partition->met << ", stable "
              << partition->stable << "), splits " << partition->reward_splits << "/"
              << partition->bisimulation_splits << "/" << partition->error_splits << "; partition "
              << seconds(start, partitioned) << " s, mdp " << seconds(partitioned, built) << " s\n";
  }
};

Vector sample_in_cell(const Compiled& c, std::size_t cell, std::mt19937_64& random) {
  const geom::BspCell& exact = c.partition->tree.cells()[cell];
  const std::size_t d = c.geometry.dimension();
  Vector low(d, 1e300);
  Vector high(d, -1e300);
  for (const geom::Point& v : exact.vertices) {
    for (std::size_t j = 0; j < d; ++j) {
      low[j] = std::min(low[j], to_double(v[j]));
      high[j] = std::max(high[j], to_double(v[j]));
    }
  }
  for (;;) {
    Vector x(d);
    for (std::size_t j = 0; j < d; ++j)
      x[j] = std::uniform_real_distribution<double>(low[j], high[j])(random);
    if (c.plain.cells[cell].worst_violation(x) < 0) return x;
  }
}

Vector sample_successor(const Compiled& c, std::size_t action, const Vector& x,
                        std::mt19937_64& random) {
  Vector next = c.plain.mean(action, x);
  for (std::size_t i = 0; i < next.size(); ++i) {
    if (const auto& w = c.plain.disturbance[action][i])
      next[i] += std::uniform_real_distribution<double>(w->first, w->second)(random);
  }
  return next;
}

// The partition's invariants, checked in doubles and by sampling.
void check_partition(const Compiled& c, int samples) {
  ASSERT_TRUE(c.partition);
  const geom::BspTree& tree = c.partition->tree;
  const std::size_t d = c.geometry.dimension();
  const std::size_t n = tree.num_cells();
  // Exact volumes sum to the domain's volume.
  Rational total = 0;
  Rational domain = 1;
  for (const geom::BspCell& cell : tree.cells())
    total += cell.volume;
  for (std::size_t i = 0; i < d; ++i)
    domain *= c.geometry.domain_high[i] - c.geometry.domain_low[i];
  EXPECT_EQ(total, domain);
  // Random points of the domain: in exactly one cell's interior (cover, disjoint), the BSP
  // walk (exact and rounded) agrees, and each cell's share of the points matches its volume.
  std::mt19937_64 random(12345);
  std::vector<double> hits(n, 0);
  const auto rounded = tree.rounded_nodes();
  for (int k = 0; k < samples; ++k) {
    Vector x(d);
    geom::Point exact(d);
    for (std::size_t j = 0; j < d; ++j) {
      x[j] = std::uniform_real_distribution<double>(c.plain.low[j], c.plain.high[j])(random);
      exact[j] = Rational(x[j]);
    }
    int inside = 0;
    for (std::size_t cell = 0; cell < n; ++cell)
      inside += c.plain.cells[cell].worst_violation(x) < -1e-9 ? 1 : 0;
    ASSERT_LE(inside, 1) << "overlapping cells";
    const std::size_t cell = c.plain.locate(x);
    ASSERT_LT(c.plain.cells[cell].worst_violation(x), 1e-9) << "a point in no cell";
    hits[cell] += 1;
    EXPECT_EQ(tree.locate(exact), cell);
    EXPECT_EQ(geom::locate_rounded(rounded, c.plain.low, c.plain.high, x), cell);
  }
  for (std::size_t cell = 0; cell < n; ++cell) {
    const double share = to_double(tree.cells()[cell].volume / domain);
    EXPECT_NEAR(hits[cell] / samples, share, 5 * std::sqrt(0.25 / samples) + 1e-3) << cell;
  }
  // The reward is constant on each cell: every region holds all of its vertices, or one of
  // the region's faces has all of them on its far side.
  for (std::size_t cell = 0; cell < n; ++cell) {
    Rational expected = 0;
    for (const geom::PolytopeReward& reward : c.geometry.rewards) {
      const auto& vertices = tree.cells()[cell].vertices;
      bool all_in = true;
      bool separated = false;
      for (const geom::HalfSpace& h : reward.region.constraints()) {
        bool all_beyond = true;
        for (const geom::Point& v : vertices) {
          const Rational value = geom::dot(h.normal, v);
          all_in = all_in && value <= h.bound;
          all_beyond = all_beyond && value >= h.bound;
        }
        separated = separated || all_beyond;
      }
      ASSERT_TRUE(all_in || separated) << "a reward region cuts cell " << cell;
      if (all_in) expected += reward.value;
    }
    EXPECT_EQ(c.partition->cell_reward[cell], expected);
    EXPECT_EQ(c.mdp.mdp.values[c.mdp.mdp.contexts[0].rewards.state[cell]], expected);
  }
  // Rows exact, summing to exactly 1.
  EXPECT_FALSE(model::find_structural_problem(c.mdp.mdp));
  EXPECT_EQ(c.mdp.epsilon, c.partition->epsilon);
}

// One-step successors of points sampled in cells against the rows: within epsilon plus
// sampling error.
void check_monte_carlo(const Compiled& c, int cells_to_try, int samples) {
  const std::size_t n = c.partition->tree.num_cells();
  const double epsilon = to_double(c.mdp.epsilon);
  const double sampling = 5 * std::sqrt(0.25 / samples);
  std::mt19937_64 random(2026);
  for (int trial = 0; trial < cells_to_try; ++trial) {
    const std::size_t cell = random() % n;
    for (std::size_t a = 0; a < c.geometry.actions.size(); ++a) {
      Vector counts(n + 1, 0);
      for (int k = 0; k < samples; ++k) {
        const Vector x = sample_in_cell(c, cell, random);
        counts[c.plain.locate(sample_successor(c, a, x, random))] += 1;
      }
      const Vector row = dense_row(c.mdp.mdp, cell, static_cast<model::ActionIndex>(a));
      for (std::size_t t = 0; t <= n; ++t)
        ASSERT_LE(std::abs(counts[t] / samples - row[t]), epsilon + sampling)
            << "cell " << cell << ", action " << a << ", target " << t;
    }
  }
}

// A point of the cell next to vertex v: v moved towards the representative by 1e-6 of the
// way, so that it is interior (a vertex itself may belong to a neighbour by the boundary
// rule).
Vector near_vertex(const geom::BspCell& cell, const geom::Point& v) {
  Vector x;
  for (std::size_t j = 0; j < v.size(); ++j)
    x.push_back(to_double(v[j] + (cell.representative[j] - v[j]) / 1'000'000));
  return x;
}

// 2-D: the area of polygon ∩ box by clipping (Sutherland-Hodgman) and the shoelace formula.
double clipped_area(const PlainCell& cell, const Vector& low, const Vector& high) {
  std::vector<std::pair<double, double>> polygon{
      {low[0], low[1]}, {high[0], low[1]}, {high[0], high[1]}, {low[0], high[1]}};
  for (std::size_t r = 0; r < cell.normals.size() && !polygon.empty(); ++r) {
    const double a = cell.normals[r][0];
    const double b = cell.normals[r][1];
    const double bound = cell.bounds[r];
    auto side = [&](const std::pair<double, double>& p) {
      return a * p.first + b * p.second - bound;
    };
    std::vector<std::pair<double, double>> kept;
    for (std::size_t i = 0; i < polygon.size(); ++i) {
      const auto& p = polygon[i];
      const auto& q = polygon[(i + 1) % polygon.size()];
      const double sp = side(p);
      const double sq = side(q);
      if (sp <= 0) kept.push_back(p);
      if ((sp < 0 && sq > 0) || (sp > 0 && sq < 0)) {
        const double t = sp / (sp - sq);
        kept.emplace_back(p.first + t * (q.first - p.first), p.second + t * (q.second - p.second));
      }
    }
    polygon = std::move(kept);
  }
  double twice = 0;
  for (std::size_t i = 0; i < polygon.size(); ++i) {
    const auto& p = polygon[i];
    const auto& q = polygon[(i + 1) % polygon.size()];
    twice += p.first * q.second - q.first * p.second;
  }
  return std::abs(twice) / 2;
}

// 2-D, every axis disturbed: from points next to every vertex of every cell, the successor
// distribution recomputed here is within epsilon of the row in total variation. Returns the
// largest total variation seen as a fraction of epsilon.
double check_vertices_2d(const Compiled& c) {
  const std::size_t n = c.partition->tree.num_cells();
  const double epsilon = to_double(c.mdp.epsilon);
  double closest = 0;
  for (std::size_t cell = 0; cell < n; ++cell) {
    const geom::BspCell& exact = c.partition->tree.cells()[cell];
    for (std::size_t a = 0; a < c.geometry.actions.size(); ++a) {
      const Vector row = dense_row(c.mdp.mdp, cell, static_cast<model::ActionIndex>(a));
      for (const geom::Point& v : exact.vertices) {
        const Vector m = c.plain.mean(a, near_vertex(exact, v));
        Vector low(2);
        Vector high(2);
        for (std::size_t i = 0; i < 2; ++i) {
          low[i] = m[i] + c.plain.disturbance[a][i]->first;
          high[i] = m[i] + c.plain.disturbance[a][i]->second;
        }
        const double area = (high[0] - low[0]) * (high[1] - low[1]);
        double variation = 0;
        double inside = 0;
        for (std::size_t t = 0; t < n; ++t) {
          const double p = clipped_area(c.plain.cells[t], low, high) / area;
          inside += p;
          variation += std::abs(p - row[t]);
        }
        variation += std::abs((1 - inside) - row[n]);
        variation /= 2;
        EXPECT_LE(variation, epsilon + 1e-9) << "cell " << cell << ", action " << a;
        closest = std::max(closest, variation / std::max(epsilon, 1e-300));
      }
    }
  }
  return closest;
}

// 3-D and 4-D: from points next to the vertices of sampled cells, successors sampled here
// against the row, within epsilon plus sampling error per target.
void check_vertices_by_sampling(const Compiled& c, int cells_to_try, int samples) {
  const std::size_t n = c.partition->tree.num_cells();
  const double epsilon = to_double(c.mdp.epsilon);
  const double sampling = 5 * std::sqrt(0.25 / samples);
  std::mt19937_64 random(99);
  for (int trial = 0; trial < cells_to_try; ++trial) {
    const std::size_t cell = random() % n;
    const geom::BspCell& exact = c.partition->tree.cells()[cell];
    for (std::size_t a = 0; a < c.geometry.actions.size(); ++a) {
      const Vector row = dense_row(c.mdp.mdp, cell, static_cast<model::ActionIndex>(a));
      for (const geom::Point& v : exact.vertices) {
        const Vector x = near_vertex(exact, v);
        Vector counts(n + 1, 0);
        for (int k = 0; k < samples; ++k)
          counts[c.plain.locate(sample_successor(c, a, x, random))] += 1;
        for (std::size_t t = 0; t <= n; ++t)
          ASSERT_LE(std::abs(counts[t] / samples - row[t]), epsilon + sampling)
              << "cell " << cell << ", action " << a << ", target " << t;
      }
    }
  }
}

// Unit shifts of a line with a reward on [3, 4]: the coarsest bisimulation is the ten unit
// intervals and outside, and every row is exact.
TEST(GeomPolytopePartition, DeterministicLineGivesTheAnalyticCells) {
  const Compiled c(test::kDeterministicLineSpec, {.epsilon = Rational(1, 10), .max_cells = 100});
  ASSERT_TRUE(c.partition);
  EXPECT_TRUE(c.partition->stable);
  EXPECT_TRUE(c.partition->met);
  EXPECT_EQ(c.mdp.epsilon, 0);
  EXPECT_TRUE(c.mdp.exact());
  const geom::BspTree& tree = c.partition->tree;
  ASSERT_EQ(tree.num_cells(), 10U);
  std::vector<int> lower_ends;
  for (const geom::BspCell& cell : tree.cells()) {
    ASSERT_EQ(cell.vertices.size(), 2U);
    EXPECT_EQ(cell.vertices[1][0] - cell.vertices[0][0], 1);
    EXPECT_EQ(cell.vertices[0][0].get_den(), 1);
    lower_ends.push_back(static_cast<int>(cell.vertices[0][0].get_num().get_si()));
  }
  std::sort(lower_ends.begin(), lower_ends.end());
  EXPECT_EQ(lower_ends, (std::vector<int>{0, 1, 2, 3, 4, 5, 6, 7, 8, 9}));
  check_partition(c, 2000);
  // Each row is one edge: to the neighbouring interval, or outside at the ends.
  for (std::size_t cell = 0; cell < 10; ++cell) {
    const int low = static_cast<int>(tree.cells()[cell].vertices[0][0].get_num().get_si());
    for (model::ActionIndex a = 0; a < 2; ++a) {
      const Vector row = dense_row(c.mdp.mdp, cell, a);
      const int target = low + (a == 0 ? -1 : 1);
      const std::size_t expected =
          target < 0 || target > 9 ? 10 : *tree.locate({Rational(2 * target + 1, 2)});
      EXPECT_EQ(row[expected], 1.0) << cell << " " << a;
    }
    EXPECT_EQ(c.partition->cell_reward[cell], low == 3 ? 1 : 0);
  }
  EXPECT_EQ(bisim::coarsest_bisimulation(c.mdp.mdp, 0).num_blocks, 11U);
}

// Quarter turns of the square [0, 2]^2 about its centre, with a triangular reward: a
// deterministic rotation, which the grid path refuses. The orbit of the triangle's edges
// closes, so the bisimulation step is stable and every row exact.
TEST(GeomPolytopePartition, DeterministicRotationClosesWithExactRows) {
  const Compiled c(R"(
mdp turn {
  continuous x : [0 .. 2];
  continuous y : [0 .. 2];
  actions turn, stay;
  discount 0.9;
  dynamics [turn] { x' = 2 - y; y' = x; }
  dynamics [stay] { }
  region corner = x + y <= 1;
}
catalog { context c { reward corner : 1; } }
)",
                   {.epsilon = Rational(1, 10), .max_cells = 200});
  ASSERT_TRUE(c.partition);
  EXPECT_TRUE(c.partition->stable);
  EXPECT_TRUE(c.mdp.exact());
  check_partition(c, 4000);
  check_monte_carlo(c, 6, 400);
  // The four rotated triangles are bisimilar to each other only through their rewards: the
  // corner with the reward and the three others, each its own block, plus the rest.
  EXPECT_GE(bisim::coarsest_bisimulation(c.mdp.mdp, 0).num_blocks, 5U);
}

// A triangular reward under a uniform disturbance and a rotation-like drift: the general
// path reaches the target, and the bound holds from every vertex and for sampled points.
constexpr const char* kTriangleSpec = R"(
mdp triangle {
  continuous x : [0 .. 2];
  continuous y : [0 .. 2];
  actions stay, drift;
  discount 0.9;
  disturbance x in [-0.5 .. 0.5];
  disturbance y in [-0.5 .. 0.5];
  dynamics [stay] { }
  dynamics [drift] { x' = 0.8 * x - 0.6 * y + 0.6; y' = 0.6 * x + 0.8 * y - 0.4; }
  region goal = x + y <= 1 & x >= 0.2 & y >= 0.1;
}
catalog { context c { reward goal : 1; } }
)";

TEST(GeomPolytopePartition, TriangularRewardWithDisturbanceMeetsTheTarget) {
  const Compiled c(kTriangleSpec, {.epsilon = Rational(1, 2), .max_cells = 400});
  ASSERT_TRUE(c.partition);
  EXPECT_TRUE(c.partition->met);
  EXPECT_LE(c.mdp.epsilon, Rational(1, 2));
  EXPECT_GT(c.mdp.epsilon, 0);
  check_partition(c, 4000);
  const double closest = check_vertices_2d(c);
  EXPECT_GT(closest, 0.3) << "the bound is far looser than the worst vertex";
  check_monte_carlo(c, 5, 2000);
}

TEST(GeomPolytopePartition, TheCellBudgetWinsAndSaysSo) {
  const Compiled c(kTriangleSpec, {.epsilon = Rational(1, 100), .max_cells = 30});
  ASSERT_TRUE(c.partition);
  EXPECT_FALSE(c.partition->met);
  EXPECT_GE(c.partition->tree.num_cells(), 30U);
  EXPECT_GT(c.partition->epsilon, Rational(1, 100));
}

// x' = 2x: pre-images halve towards 0 and never close; the bisimulation step stops at the
// budget and says it is not stable.
TEST(GeomPolytopePartition, PreimagesThatDoNotCloseStopAtTheBudget) {
  std::string spec = test::kDeterministicLineSpec;
  spec.replace(spec.find("x' = x - 1;"), 11, "x' = 2 * x;");
  const Compiled c(spec, {.epsilon = Rational(1, 10), .max_cells = 60});
  ASSERT_TRUE(c.partition);
  EXPECT_FALSE(c.partition->stable);
  EXPECT_FALSE(c.partition->met);
  EXPECT_EQ(c.partition->epsilon, 1);
}

TEST(GeomPolytopePartition, ThreeDimensionsWithASlantedReward) {
  const Compiled c(R"(
mdp cube {
  continuous x : [0 .. 1];
  continuous y : [0 .. 1];
  continuous z : [0 .. 1];
  actions stay, shear;
  discount 0.9;
  disturbance x in [-0.4 .. 0.4];
  disturbance y in [-0.4 .. 0.4];
  disturbance z in [-0.4 .. 0.4];
  dynamics [stay] { }
  dynamics [shear] { x' = x + 0.25 * y; z' = 0.5 * z + 0.2; }
  region goal = x + y + z <= 1;
}
catalog { context c { reward goal : 1; } }
)",
                   {.epsilon = Rational(7, 10), .max_cells = 60});
  ASSERT_TRUE(c.partition);
  EXPECT_TRUE(c.partition->met);
  check_partition(c, 3000);
  check_vertices_by_sampling(c, 2, 400);
  check_monte_carlo(c, 3, 400);
}

TEST(GeomPolytopePartition, FourDimensionsStayWithinTheBound) {
  const Compiled c(R"(
mdp tesseract {
  continuous a : [0 .. 1];
  continuous b : [0 .. 1];
  continuous c : [0 .. 1];
  continuous d : [0 .. 1];
  actions stay, mix;
  discount 0.9;
  disturbance a in [-1 .. 1];
  disturbance b in [-1 .. 1];
  disturbance c in [-1 .. 1];
  disturbance d in [-1 .. 1];
  dynamics [stay] { }
  dynamics [mix] { a' = 0.5 * a + 0.5 * b; b' = 0.5 * a - 0.5 * b + 0.5; }
  region goal = a + b <= 1 & c - d >= 0;
}
catalog { context c { reward goal : 1; } }
)",
                   {.epsilon = Rational(3, 4), .max_cells = 24});
  ASSERT_TRUE(c.partition);
  EXPECT_EQ(c.geometry.dimension(), 4U);
  EXPECT_TRUE(c.partition->met);
  check_partition(c, 2000);
  check_vertices_by_sampling(c, 1, 300);
  check_monte_carlo(c, 2, 300);
}

}  // namespace
}  // namespace oasis
