#include "guarantee/row_classes.hpp"

#include <algorithm>
#include <cstdint>
#include <cstring>
#include <unordered_map>
#include <vector>

#include "oasis/rt/spec_hash.hpp"

namespace oasis::guarantee {
namespace {

class RowView {
 public:
  RowView(const IntervalMdp& mdp, std::size_t cell) : mdp_(mdp), cell_(cell) {}

  [[nodiscard]] std::uint64_t hash() const {
    std::uint64_t h = rt::kFnv1a64Basis;
    const auto mix = [&h](const void* data, std::size_t size) {
      h = rt::fnv1a64(static_cast<const unsigned char*>(data), size, h);
    };
    for_each_slice([&](const AxisSlice& slice) {
      mix(&slice.first, sizeof slice.first);
      mix(&slice.count, sizeof slice.count);
      mix(&slice.outside_lower, sizeof slice.outside_lower);
      mix(&slice.outside_upper, sizeof slice.outside_upper);
      mix(&slice.truncated, sizeof slice.truncated);
      mix(mdp_.lower.data() + slice.offset, slice.count * sizeof(double));
      mix(mdp_.upper.data() + slice.offset, slice.count * sizeof(double));
    });
    return h;
  }

  [[nodiscard]] bool operator==(const RowView& other) const {
    const std::size_t slices = mdp_.actions.size() * mdp_.grid.dimension();
    const AxisSlice* a = mdp_.row(cell_, 0);
    const AxisSlice* b = mdp_.row(other.cell_, 0);
    for (std::size_t i = 0; i < slices; ++i) {
      if (a[i].first != b[i].first || a[i].count != b[i].count ||
          a[i].outside_lower != b[i].outside_lower || a[i].outside_upper != b[i].outside_upper ||
          a[i].truncated != b[i].truncated)
        return false;
      const std::size_t bytes = a[i].count * sizeof(double);
      if (std::memcmp(mdp_.lower.data() + a[i].offset, mdp_.lower.data() + b[i].offset, bytes) !=
              0 ||
          std::memcmp(mdp_.upper.data() + a[i].offset, mdp_.upper.data() + b[i].offset, bytes) != 0)
        return false;
    }
    return true;
  }

 private:
  template <typename Visit>
  void for_each_slice(const Visit& visit) const {
    const std::size_t slices = mdp_.actions.size() * mdp_.grid.dimension();
    const AxisSlice* row = mdp_.row(cell_, 0);
    for (std::size_t i = 0; i < slices; ++i)
      visit(row[i]);
  }

  const IntervalMdp& mdp_;
  std::size_t cell_;
};

}  // namespace

std::size_t distinct_rows(const IntervalMdp& mdp) {
  // Cells by hash; within a hash, one representative per class of equal rows.
  std::unordered_map<std::uint64_t, std::vector<std::size_t>> classes;
  std::size_t count = 0;
  for (std::size_t cell = 0; cell < mdp.grid.cells; ++cell) {
    const RowView row(mdp, cell);
    std::vector<std::size_t>& representatives = classes[row.hash()];
    const bool known = std::any_of(representatives.begin(), representatives.end(),
                                   [&](std::size_t other) { return RowView(mdp, other) == row; });
    if (known) continue;
    representatives.push_back(cell);
    ++count;
  }
  return count;
}

}  // namespace oasis::guarantee
