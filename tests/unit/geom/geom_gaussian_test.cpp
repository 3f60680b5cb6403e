// Gaussian disturbances in the grid path (docs/geometry.md): the interval probabilities
// against the normal CDF and their tolerance, rows that sum to exactly 1, the error bound from
// every vertex of sampled cells, a Monte-Carlo check of successors against the rows, and a
// spec compiled and verified through oasisc (and a wrong one caught by verify).

#include <cmath>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <numbers>
#include <optional>
#include <random>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "../../support/run_oasisc.hpp"
#include "../../support/scratch_directory.hpp"
#include "../../support/spec_models.hpp"
#include "geom/grid_gaussian_axis.hpp"
#include "geom/grid_geometry.hpp"
#include "geom/grid_mdp.hpp"
#include "geom/grid_refinement.hpp"
#include "geom/relevance.hpp"
#include "oasis/rt/catalog_file.hpp"
#include "verify/continuous_check.hpp"

namespace oasis {
namespace {

const std::string kLineSpecPath = std::string(OASIS_SOURCE_DIR) + "/tests/data/gaussian_line.oasis";

// Two axes, both Gaussian under `turn` (a rotation that mixes them); under `go`, x is Gaussian
// and y uniform (the block's disturbance overrides the model's).
constexpr const char* kPlaneSpec = R"(
mdp gaussian_plane {
  continuous x : [0 .. 4];
  continuous y : [0 .. 4];
  actions turn, go;
  discount 0.9;
  disturbance x ~ gaussian(0, 0.3);
  disturbance y ~ gaussian(0.1, 0.2);
  dynamics [turn] { x' = 0.9 * x + 0.2 * y; y' = -0.2 * x + 0.9 * y + 0.4; }
  dynamics [go] { x' = x + 0.5; disturbance y in [-0.2 .. 0.2]; }
  region goal = x >= 1 & x <= 2 & y >= 1 & y <= 2;
}
catalog { context at_goal { reward goal : 1; } }
)";

// The standard normal distribution function in long double, apart from compiler/geom's code.
long double normal_cdf(long double z) {
  return 0.5L * std::erfc(-z / std::sqrt(2.0L));
}

long double normal_between(long double low, long double high) {
  if (low > 0) return normal_cdf(-low) - normal_cdf(-high);
  return normal_cdf(high) - normal_cdf(low);
}

// A context of a spec, gridded to a target, and its finite MDP.
struct Gridded {
  model::ModelIR ir;
  geom::GridGeometry geometry;
  geom::GridPartition partition;
  model::ExplicitModel mdp;
  double epsilon = 0;
};

Gridded gridded(model::ModelIR ir, std::size_t context, double target) {
  Gridded out{std::move(ir), {}, {}, {}, 0};
  std::string error;
  auto geometry =
      geom::grid_geometry(out.ir, context, geom::analyse_relevance(out.ir, context), error);
  EXPECT_TRUE(geometry) << error;
  if (!geometry) return out;
  out.geometry = std::move(*geometry);
  auto partition = geom::partition_grid(out.geometry, {target, 100000}, error);
  EXPECT_TRUE(partition) << error;
  if (!partition) return out;
  out.partition = std::move(*partition);
  out.epsilon = to_double(out.partition.epsilon);
  out.mdp =
      geom::grid_finite_mdp(out.geometry, out.partition.grid, out.ir.actions, out.ir.objective);
  return out;
}

// The two specs' first contexts, gridded once.
const Gridded& line() {
  static const Gridded gridded_line = gridded(test::load_spec_ir(kLineSpecPath), 0, 0.1);
  return gridded_line;
}

const Gridded& plane() {
  static const Gridded gridded_plane = gridded(test::check_spec_text_ir(kPlaneSpec), 0, 0.25);
  return gridded_plane;
}

// The row of `cell` under `action` as a dense vector over cells and outside.
std::vector<double> row_of(const Gridded& g, std::size_t cell, model::ActionIndex action) {
  const model::TransitionMatrix& matrix = *g.mdp.contexts[0].transitions;
  std::vector<double> row(g.partition.grid.num_cells() + 1, 0);
  const auto state = static_cast<model::StateIndex>(cell);
  for (auto e = matrix.edges_begin(state, action); e < matrix.edges_end(state, action); ++e)
    row[matrix.edge_target[e]] = to_double(g.mdp.values[matrix.edge_probability[e]]);
  return row;
}

// Per axis, the probability of each interval for the successor of `x`, recomputed here from
// the geometry in long double.
std::vector<std::vector<long double>> axis_distributions(const Gridded& g,
                                                         const geom::AxisDynamics& step,
                                                         const std::vector<double>& x) {
  const geom::Grid& grid = g.partition.grid;
  std::vector<std::vector<long double>> axes(grid.dimension());
  for (std::size_t i = 0; i < grid.dimension(); ++i) {
    long double image = to_double(step.offset[i]);
    for (std::size_t j = 0; j < grid.dimension(); ++j)
      image += static_cast<long double>(to_double(step.matrix[i][j])) * x[j];
    const std::vector<double>& t = grid.breaks_double(i);
    const geom::Disturbance& w = step.disturbance[i];
    for (std::size_t k = 0; k + 1 < t.size(); ++k) {
      if (w.kind == geom::Disturbance::Kind::None) {
        const bool last = k + 2 == t.size();
        axes[i].push_back(t[k] <= image && (image < t[k + 1] || (last && image == t[k + 1])));
      } else if (w.kind == geom::Disturbance::Kind::Gaussian) {
        const long double mean = image + to_double(w.gaussian.mean);
        const long double deviation = to_double(w.gaussian.deviation);
        axes[i].push_back(normal_between((t[k] - mean) / deviation, (t[k + 1] - mean) / deviation));
      } else {
        const long double low = image + to_double(w.uniform.low);
        const long double high = image + to_double(w.uniform.high);
        axes[i].push_back(std::max(0.0L, std::min<long double>(high, t[k + 1]) -
                                             std::max<long double>(low, t[k])) /
                          (high - low));
      }
    }
  }
  return axes;
}

// The successor distribution over cells and outside from the point `x` under `action`.
std::vector<long double> successor_from(const Gridded& g, model::ActionIndex action,
                                        const std::vector<double>& x) {
  const geom::Grid& grid = g.partition.grid;
  const auto axes = axis_distributions(g, g.geometry.actions[action], x);
  std::vector<long double> p(grid.num_cells() + 1, 0);
  std::vector<std::uint32_t> index(grid.dimension());
  long double inside = 0;
  for (std::size_t cell = 0; cell < grid.num_cells(); ++cell) {
    grid.index_of(cell, index);
    long double mass = 1;
    for (std::size_t i = 0; i < grid.dimension(); ++i)
      mass *= axes[i][index[i]];
    p[cell] = mass;
    inside += mass;
  }
  p[grid.num_cells()] = 1 - inside;
  return p;
}

long double total_variation(const std::vector<long double>& p, const std::vector<double>& q) {
  long double sum = 0;
  for (std::size_t k = 0; k < p.size(); ++k)
    sum += std::fabs(p[k] - q[k]);
  return sum / 2;
}

// The vertices of a cell, or its centre when `corner` is 2^d.
std::vector<double> corner_of(const geom::Grid& grid, std::size_t cell, std::size_t corner) {
  std::vector<std::uint32_t> index(grid.dimension());
  grid.index_of(cell, index);
  std::vector<double> x(grid.dimension());
  for (std::size_t i = 0; i < grid.dimension(); ++i) {
    const double low = grid.breaks_double(i)[index[i]];
    const double high = grid.breaks_double(i)[index[i] + 1];
    x[i] = corner == (std::size_t{1} << grid.dimension()) ? (low + high) / 2
           : ((corner >> i) & 1U) != 0                    ? high
                                                          : low;
  }
  return x;
}

TEST(GeomGaussian, SqrtTwoPiIsBoundedFromBelowTightly) {
  const double below = to_double(geom::sqrt_two_pi_below());
  const double exact = std::sqrt(2 * std::numbers::pi);
  EXPECT_LT(below, exact);
  EXPECT_GT(below, exact - 1e-6);
}

// Against the normal CDF in long double: each entry within a few 1e-14, the entries only
// under the truncated support, their sum at most 1, and the whole axis distribution (the rest
// counted as leaving the domain) within the stated tolerance in total variation.
TEST(GeomGaussian, IntervalProbabilitiesAreWithinTheirTolerance) {
  std::vector<Rational> breaks;
  for (int k = 0; k <= 400; ++k)
    breaks.emplace_back(k, 4);  // [0, 100] in quarters
  const std::size_t intervals = breaks.size() - 1;
  for (const auto& [mean, deviation] : std::vector<std::pair<Rational, Rational>>{
           {Rational(503, 10), Rational(1, 2)},  // in the middle
           {Rational(3, 10), Rational(7, 10)},   // by the low wall: much mass leaves
           {Rational(-3), Rational(1, 2)},       // outside the domain: only a far tail enters
           {Rational(997, 10), Rational(2)}}) {
    const auto entries = geom::gaussian_interval_probabilities(mean, deviation, breaks);
    const long double mu = to_double(mean);
    const long double s = to_double(deviation);
    const long double reach = to_double(geom::truncation_deviations()) * s;
    std::vector<long double> computed(intervals, 0);
    Rational sum = 0;
    for (const auto& [k, p] : entries) {
      ASSERT_LT(k, intervals);
      EXPECT_GT(sgn(p), 0);
      const long double low = to_double(breaks[k]);
      const long double high = to_double(breaks[k + 1]);
      EXPECT_GT(high, mu - reach) << "interval " << k;
      EXPECT_LT(low, mu + reach) << "interval " << k;
      computed[k] = to_double(p);
      sum += p;
    }
    EXPECT_LE(sum, 1);
    long double variation = 0;
    long double inside = 0;
    long double truncated = 0;
    for (std::size_t k = 0; k < intervals; ++k) {
      const long double low = to_double(breaks[k]);
      const long double high = to_double(breaks[k + 1]);
      const long double exact = normal_between((low - mu) / s, (high - mu) / s);
      if (high > mu - reach && low < mu + reach) {
        EXPECT_NEAR(static_cast<double>(computed[k]), static_cast<double>(exact), 3e-14)
            << "interval " << k;
      } else {
        truncated += exact;
      }
      variation += std::fabs(computed[k] - exact);
      inside += exact;
    }
    EXPECT_LT(truncated, 1e-12);
    variation += std::fabs((1 - to_double(sum)) - (1 - inside));
    EXPECT_LE(variation / 2, to_double(geom::gaussian_row_tolerance(intervals)));
  }
}

TEST(GeomGaussian, EveryRowSumsToExactlyOne) {
  for (const Gridded* g_pointer : {&line(), &plane()}) {
    const Gridded& g = *g_pointer;
    ASSERT_GT(g.partition.grid.num_cells(), 1U);
    EXPECT_FALSE(model::find_structural_problem(g.mdp)) << *model::find_structural_problem(g.mdp);
    const model::TransitionMatrix& matrix = *g.mdp.contexts[0].transitions;
    for (model::StateIndex s = 0; s < g.mdp.num_states(); ++s) {
      for (model::ActionIndex a = 0; a < g.ir.actions.size(); ++a) {
        Rational sum = 0;
        for (auto e = matrix.edges_begin(s, a); e < matrix.edges_end(s, a); ++e) {
          EXPECT_GT(sgn(g.mdp.values[matrix.edge_probability[e]]), 0);
          sum += g.mdp.values[matrix.edge_probability[e]];
        }
        ASSERT_EQ(sum, 1) << "state " << s << ", action " << g.ir.actions[a];
      }
    }
  }
}

// From every vertex (and the centre) of the cells, the successor distribution recomputed here
// stays within epsilon of the cell's row in total variation, and somewhere comes near it.
void expect_vertices_within_the_bound(const Gridded& g, std::size_t samples) {
  const geom::Grid& grid = g.partition.grid;
  ASSERT_GT(grid.num_cells(), 1U);
  std::mt19937_64 random(11);
  double closest = 0;
  for (std::size_t trial = 0; trial < samples; ++trial) {
    const std::size_t cell =
        samples >= grid.num_cells() ? trial % grid.num_cells() : random() % grid.num_cells();
    for (model::ActionIndex a = 0; a < g.ir.actions.size(); ++a) {
      const std::vector<double> row = row_of(g, cell, a);
      for (std::size_t corner = 0; corner <= (std::size_t{1} << grid.dimension()); ++corner) {
        const long double variation =
            total_variation(successor_from(g, a, corner_of(grid, cell, corner)), row);
        ASSERT_LE(variation, g.epsilon + 1e-12)
            << "cell " << cell << ", action " << g.ir.actions[a] << ", corner " << corner;
        closest = std::max(closest, static_cast<double>(variation) / g.epsilon);
      }
    }
  }
  std::cout << grid.num_cells() << " cells, epsilon " << g.epsilon << ", worst vertex at "
            << closest << " epsilon\n";
  EXPECT_GT(closest, 0.5) << "the bound is far looser than the worst vertex";
}

TEST(GeomGaussian, LineVerticesStayWithinTheBound) {
  EXPECT_TRUE(line().partition.met);
  expect_vertices_within_the_bound(line(), line().partition.grid.num_cells());
}

TEST(GeomGaussian, PlaneVerticesStayWithinTheBound) {
  EXPECT_TRUE(plane().partition.met);
  expect_vertices_within_the_bound(plane(), 40);
}

// One successor of `x` under `action`, drawn with the standard library's samplers.
std::optional<std::size_t> sampled_successor(const Gridded& g, model::ActionIndex action,
                                             const std::vector<double>& x,
                                             std::mt19937_64& random) {
  const geom::AxisDynamics& step = g.geometry.actions[action];
  std::vector<double> next(x.size());
  for (std::size_t i = 0; i < x.size(); ++i) {
    next[i] = to_double(step.offset[i]);
    for (std::size_t j = 0; j < x.size(); ++j)
      next[i] += to_double(step.matrix[i][j]) * x[j];
    const geom::Disturbance& w = step.disturbance[i];
    if (w.kind == geom::Disturbance::Kind::None) continue;
    if (w.kind == geom::Disturbance::Kind::Gaussian) {
      next[i] += std::normal_distribution<double>(to_double(w.gaussian.mean),
                                                  to_double(w.gaussian.deviation))(random);
    } else {
      next[i] += std::uniform_real_distribution<double>(to_double(w.uniform.low),
                                                        to_double(w.uniform.high))(random);
    }
  }
  return g.partition.grid.locate(std::span<const double>(next));
}

// From points sampled in a cell, the successor's frequency in every target (and outside)
// stays within epsilon of the row, plus sampling error.
TEST(GeomGaussian, MonteCarloSuccessorsAgreeWithTheRowsWithinEpsilon) {
  const Gridded& g = plane();
  const geom::Grid& grid = g.partition.grid;
  std::mt19937_64 random(20261125);
  constexpr int kSamples = 10000;
  const double sampling = 5 * std::sqrt(0.25 / kSamples);  // 5 sigma of any frequency
  std::vector<std::uint32_t> index(grid.dimension());
  for (int trial = 0; trial < 8; ++trial) {
    const std::size_t cell = random() % grid.num_cells();
    grid.index_of(cell, index);
    for (model::ActionIndex a = 0; a < g.ir.actions.size(); ++a) {
      std::vector<double> counts(grid.num_cells() + 1, 0);
      for (int k = 0; k < kSamples; ++k) {
        std::vector<double> x(grid.dimension());
        for (std::size_t i = 0; i < x.size(); ++i)
          x[i] = std::uniform_real_distribution<double>(
              grid.breaks_double(i)[index[i]], grid.breaks_double(i)[index[i] + 1])(random);
        const auto target = sampled_successor(g, a, x, random);
        counts[target ? *target : grid.num_cells()] += 1;
      }
      const std::vector<double> row = row_of(g, cell, a);
      for (std::size_t t = 0; t < row.size(); ++t)
        ASSERT_LE(std::abs(counts[t] / kSamples - row[t]), g.epsilon + sampling)
            << "cell " << cell << ", action " << g.ir.actions[a] << ", target " << t;
    }
  }
}

// Through the command line: compile with the transition rows, then verify, which recomputes
// the Gaussian rows with its own normal CDF.
class GaussianCli : public ::testing::Test {
 protected:
  std::string compile(const std::string& spec, const std::string& name,
                      const std::string& epsilon) {
    const std::filesystem::path out = scratch_.path() / name;
    const auto compiled =
        test::run_oasisc("compile " + spec + " -o " + out.string() +
                         " --format bin,json --with-transitions --epsilon " + epsilon);
    EXPECT_EQ(compiled.status, 0) << compiled.output;
    for (const auto& entry : std::filesystem::directory_iterator(out))
      if (entry.path().extension() == ".bin") return entry.path().string();
    ADD_FAILURE() << "no catalog in " << out;
    return "";
  }

  std::string write_spec(const std::string& text, const std::string& name) {
    const std::filesystem::path path = scratch_.path() / name;
    std::ofstream(path) << text;
    return path.string();
  }

  test::ScratchDirectory scratch_{"oasis_gaussian_cli"};
};

TEST_F(GaussianCli, CompiledCatalogsVerify) {
  const std::string plane_spec = write_spec(kPlaneSpec, "plane.oasis");
  for (const auto& [spec, epsilon] : {std::pair{kLineSpecPath, "0.1"}, {plane_spec, "0.3"}}) {
    const std::string catalog = compile(spec, std::filesystem::path(spec).stem().string(), epsilon);
    const auto verified = test::run_oasisc("verify " + spec + " " + catalog);
    EXPECT_EQ(verified.status, 0) << verified.output;
    EXPECT_NE(verified.output.find("rows within epsilon"), std::string::npos) << verified.output;
  }
}

// A catalog compiled with the slip's mean moved by 0.8 (1.6 deviations) does not pass for the
// spec as written: the verifier recomputes the Gaussian rows rather than trusting the file.
// (The command line refuses the pair before that, by the spec's hash, so the check is called
// directly.)
TEST_F(GaussianCli, VerifyCatchesRowsOfAnotherGaussian) {
  std::string text = test::read_text_file(kLineSpecPath);
  const std::string slip = "gaussian(0, 0.5)";
  text.replace(text.find(slip), slip.size(), "gaussian(0.8, 0.5)");
  const std::string path = compile(write_spec(text, "shifted.oasis"), "shifted", "0.1");
  const auto catalog = rt::LoadedCatalog::from_file(path);
  ASSERT_TRUE(catalog.ok()) << catalog.error();
  std::string failures;
  for (const verify::CatalogCheck& check :
       verify::check_continuous_catalog(test::load_spec_ir(kLineSpecPath), catalog.view()))
    if (!check.ok) failures += check.item + ": " + check.verdict + "\n";
  EXPECT_NE(failures.find("more than epsilon"), std::string::npos) << failures;
}

}  // namespace
}  // namespace oasis
