#include "geom/grid_product_rows.hpp"

#include <algorithm>
#include <optional>
#include <utility>

#if defined(__SSE2__)
#include <emmintrin.h>
#endif

#include "geom/grid_axis_rows.hpp"

namespace oasis::geom {
namespace {

// Σ_k p[k] x[k] in four running sums, s_j over the k = j (mod 4): four independent chains of
// additions keep the floating-point unit busy where one would wait on each addition's
// latency. The SSE2 form holds the same four sums two to a register and rounds exactly as the
// plain form does, so results do not depend on the build.
double dot(const double* p, const double* x, std::uint32_t n) {
  std::uint32_t k = 0;
#if defined(__SSE2__)
  __m128d low = _mm_setzero_pd();   // s0, s1
  __m128d high = _mm_setzero_pd();  // s2, s3
  for (; k + 4 <= n; k += 4) {
    low = _mm_add_pd(low, _mm_mul_pd(_mm_loadu_pd(p + k), _mm_loadu_pd(x + k)));
    high = _mm_add_pd(high, _mm_mul_pd(_mm_loadu_pd(p + k + 2), _mm_loadu_pd(x + k + 2)));
  }
  double sums[4];
  _mm_storeu_pd(sums, low);
  _mm_storeu_pd(sums + 2, high);
  double s0 = sums[0], s1 = sums[1], s2 = sums[2], s3 = sums[3];
#else
  double s0 = 0, s1 = 0, s2 = 0, s3 = 0;
  for (; k + 4 <= n; k += 4) {
    s0 += p[k] * x[k];
    s1 += p[k + 1] * x[k + 1];
    s2 += p[k + 2] * x[k + 2];
    s3 += p[k + 3] * x[k + 3];
  }
#endif
  for (; k < n; ++k)
    s0 += p[k] * x[k];
  return (s0 + s1) + (s2 + s3);
}

// dot(p, x, n) and dot(p, y, n) at once, each summed exactly as dot() sums it: two rows'
// chains interleaved, so that neither waits on its own additions.
std::pair<double, double> dot_pair(const double* p, const double* x, const double* y,
                                   std::uint32_t n) {
#if defined(__SSE2__)
  std::uint32_t k = 0;
  __m128d x_low = _mm_setzero_pd(), x_high = _mm_setzero_pd();
  __m128d y_low = _mm_setzero_pd(), y_high = _mm_setzero_pd();
  for (; k + 4 <= n; k += 4) {
    const __m128d p_low = _mm_loadu_pd(p + k);
    const __m128d p_high = _mm_loadu_pd(p + k + 2);
    x_low = _mm_add_pd(x_low, _mm_mul_pd(p_low, _mm_loadu_pd(x + k)));
    y_low = _mm_add_pd(y_low, _mm_mul_pd(p_low, _mm_loadu_pd(y + k)));
    x_high = _mm_add_pd(x_high, _mm_mul_pd(p_high, _mm_loadu_pd(x + k + 2)));
    y_high = _mm_add_pd(y_high, _mm_mul_pd(p_high, _mm_loadu_pd(y + k + 2)));
  }
  double xs[4], ys[4];
  _mm_storeu_pd(xs, x_low);
  _mm_storeu_pd(xs + 2, x_high);
  _mm_storeu_pd(ys, y_low);
  _mm_storeu_pd(ys + 2, y_high);
  for (; k < n; ++k) {
    xs[0] += p[k] * x[k];
    ys[0] += p[k] * y[k];
  }
  return {(xs[0] + xs[1]) + (xs[2] + xs[3]), (ys[0] + ys[1]) + (ys[2] + ys[3])};
#else
  return {dot(p, x, n), dot(p, y, n)};
#endif
}

// True when axis i's image depends on no other axis under `action`: then its axis row is the
// same for every cell with the same interval on that axis.
bool separable(const AxisDynamics& action, std::size_t i) {
  for (std::size_t j = 0; j < action.matrix[i].size(); ++j)
    if (j != i && sgn(action.matrix[i][j]) != 0) return false;
  return true;
}

}  // namespace

ProductRows::ProductRows(const GridGeometry& geometry, const Grid& grid, std::uint32_t num_actions)
    : num_cells_(static_cast<std::uint32_t>(grid.num_cells())), num_actions_(num_actions) {
  const std::size_t d = grid.dimension();
  for (std::size_t i = 0; i < d; ++i)
    extent_.push_back(static_cast<std::uint32_t>(grid.intervals(i)));
  spans_.resize(std::size_t{num_cells_} * num_actions_ * d);
  outside_id_.resize(std::size_t{num_cells_} * num_actions_);
  reward_.assign(num_states(), RationalPool::kZero);

  AxisRowBuilder axis_rows(grid, values_);
  // Per (action, axis) that is separable, the span and mass of each interval, once computed.
  std::vector<std::vector<std::optional<std::pair<AxisSpan, Rational>>>> known(num_actions_ * d);
  for (std::uint32_t a = 0; a < num_actions_; ++a)
    for (std::size_t i = 0; i < d; ++i)
      if (separable(geometry.actions[a], i)) known[a * d + i].resize(extent_[i]);
  std::vector<std::uint32_t> index(d);
  AxisRow row;
  for (std::uint32_t cell = 0; cell < num_cells_; ++cell) {
    grid.index_of(cell, index);
    const std::vector<Rational> centre = cell_centre(grid, index);
    reward_[cell] = values_.intern(cell_reward(geometry, grid, index));
    for (std::uint32_t a = 0; a < num_actions_; ++a) {
      const std::size_t choice = std::size_t{cell} * num_actions_ + a;
      Rational inside = 1;
      for (std::size_t i = 0; i < d; ++i) {
        std::vector<std::optional<std::pair<AxisSpan, Rational>>>& cache = known[a * d + i];
        if (!cache.empty() && cache[index[i]]) {  // computed for an earlier cell
          spans_[choice * d + i] = cache[index[i]]->first;
          inside *= cache[index[i]]->second;
          continue;
        }
        axis_rows.axis_row(geometry.actions[a], i, centre, row);
        spans_[choice * d + i] = add_axis_row(row);
        inside *= row.inside;
        if (!cache.empty()) cache[index[i]].emplace(spans_[choice * d + i], row.inside);
      }
      outside_id_[choice] = values_.intern(1 - inside);
      count_choice(choice);
    }
  }
  num_edges_ += num_actions_;  // outside's self-loops
  round_numbers();
}

ProductRows::AxisSpan ProductRows::add_axis_row(const AxisRow& row) {
  AxisSpan span;
  span.first = row.entries.empty() ? 0 : row.entries.front().first;
  span.count = static_cast<std::uint32_t>(row.entries.size());
  span.offset = probability_id_.size();
  for (const auto& [k, p] : row.entries)
    probability_id_.push_back(p);
  return span;
}

void ProductRows::count_choice(std::size_t choice) {
  const std::size_t d = extent_.size();
  std::size_t targets = 1;
  std::uint32_t path = 3;  // the outside term: its conversion, product and addition
  for (std::size_t i = 0; i < d; ++i) {
    targets *= spans_[choice * d + i].count;
    path += spans_[choice * d + i].count + 2;  // an axis's conversions, product and additions
  }
  if (targets == 0) {  // no mass stays on some axis: none stays at all
    for (std::size_t i = 0; i < d; ++i)
      spans_[choice * d + i].count = 0;
  }
  num_edges_ += targets + (outside_id_[choice] != RationalPool::kZero ? 1 : 0);
  rounding_depth_ = std::max(rounding_depth_, path);
}

void ProductRows::round_numbers() {
  const std::size_t d = extent_.size();
  std::vector<double> as_double(values_.size());
  for (ValueId id = 0; id < as_double.size(); ++id)
    as_double[id] = to_double(values_[id]);
  probability_.reserve(probability_id_.size());
  for (const ValueId id : probability_id_)
    probability_.push_back(as_double[id]);
  outside_.reserve(outside_id_.size());
  for (const ValueId id : outside_id_)
    outside_.push_back(as_double[id]);
  std::vector<double> smallest(d, 1);
  for (std::size_t s = 0; s < spans_.size(); ++s) {
    const AxisSpan& span = spans_[s];
    for (std::uint32_t k = 0; k < span.count; ++k)
      smallest[s % d] = std::min(smallest[s % d], probability_[span.offset + k]);
  }
  for (const double p : smallest)
    smallest_term_ *= p;
  for (const double p : outside_)
    if (p > 0) smallest_term_ = std::min(smallest_term_, p);
}

double ProductRows::axis_sum(const AxisSpan* spans, std::size_t axis, std::size_t prefix,
                             const double* x) const {
  const AxisSpan& span = spans[axis];
  const double* p = probability_.data() + span.offset;
  const std::size_t start = prefix * extent_[axis] + span.first;
  if (axis + 1 == extent_.size()) return dot(p, x + start, span.count);
  double sum = 0;
  for (std::uint32_t k = 0; k < span.count; ++k)
    sum += p[k] * axis_sum(spans, axis + 1, start + k, x);
  return sum;
}

double ProductRows::expectation(std::uint32_t s, std::uint32_t a, const double* x) const {
  if (s == num_cells_) return x[num_cells_];  // outside is absorbing
  const std::size_t choice = std::size_t{s} * num_actions_ + a;
  const AxisSpan* spans = spans_.data() + choice * extent_.size();
  double inside = 0;
  if (spans[0].count == 0) {
    inside = 0;
  } else if (extent_.size() == 2) {  // the common case, without the recursion
    const double* p = probability_.data() + spans[0].offset;
    const double* q = probability_.data() + spans[1].offset;
    const std::size_t stride = extent_[1];
    const double* row = x + spans[0].first * stride + spans[1].first;
    std::uint32_t k = 0;
    for (; k + 2 <= spans[0].count; k += 2, row += 2 * stride) {
      const auto [first, second] = dot_pair(q, row, row + stride, spans[1].count);
      inside += p[k] * first;
      inside += p[k + 1] * second;
    }
    if (k < spans[0].count) inside += p[k] * dot(q, row, spans[1].count);
  } else {
    inside = axis_sum(spans, 0, 0, x);
  }
  return inside + outside_[choice] * x[num_cells_];
}

}  // namespace oasis::geom
