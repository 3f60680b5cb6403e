#include "guarantee/end_components.hpp"

#include <cstddef>

namespace oasis::guarantee {
namespace {

// Upper bounds are rounded outward and summed in doubles: a row whose upper bounds on the
// staying outcomes reach 1 within this counts as able to stay.
constexpr double kRoomSlack = 1e-9;

// Each pass costs one row per cell; a chain of removals longer than this is cut short.
constexpr std::size_t kPassLimit = 1000;

class StayTest {
 public:
  StayTest(const IntervalMdp& mdp, const std::vector<std::uint8_t>& in_set)
      : mdp_(mdp), in_set_(in_set) {}

  // Whether some distribution of `row` puts all its mass on the set.
  [[nodiscard]] bool can_stay(const AxisSlice* row) const { return stays(row, 0, 0); }

 private:
  // Axes axis.. given the cell offset `base` of the earlier axes' outcomes.
  [[nodiscard]] bool stays(const AxisSlice* row, std::size_t axis, std::size_t base) const {
    const AxisSlice& slice = row[axis];
    if (slice.outside_lower > 0 || slice.truncated > 0) return false;
    const bool last = axis + 1 == mdp_.grid.dimension();
    const std::size_t stride = mdp_.grid.strides[axis];
    const double* lower = mdp_.lower.data() + slice.offset;
    const double* upper = mdp_.upper.data() + slice.offset;
    double room = 0;
    for (std::uint32_t k = 0; k < slice.count; ++k) {
      const std::size_t at = base + (slice.first + k) * stride;
      const bool good = last ? in_set_[at] != 0 : stays(row, axis + 1, at);
      if (good) {
        room += upper[k];
      } else if (lower[k] > 0) {
        return false;  // this outcome must get mass, and it leaves the set
      }
    }
    return room >= 1.0 - kRoomSlack;
  }

  const IntervalMdp& mdp_;
  const std::vector<std::uint8_t>& in_set_;
};

}  // namespace

std::vector<std::uint8_t> greatest_trap(const IntervalMdp& mdp,
                                        const std::vector<std::uint8_t>& undecided,
                                        const std::vector<std::uint32_t>& policy) {
  std::vector<std::uint8_t> trap = undecided;
  const StayTest test(mdp, trap);
  // Removing a cell can only make others leave too; the set shrinks until a pass changes
  // nothing, which is the greatest trap (every set with the property stays inside). Past the
  // pass limit the set left still contains the greatest trap, which is all a caller relies on.
  bool changed = true;
  for (std::size_t pass = 0; changed && pass < kPassLimit; ++pass) {
    changed = false;
    for (std::size_t c = 0; c < trap.size(); ++c) {
      if (trap[c] == 0 || test.can_stay(mdp.row(c, policy[c]))) continue;
      trap[c] = 0;
      changed = true;
    }
  }
  return trap;
}

}  // namespace oasis::guarantee
