#include "go1/loss_model.hpp"

namespace oasis::hw::go1 {

bool LossModel::drop_next() {
  return next_uniform() < loss_probability_;
}

double LossModel::next_uniform() {
  // SplitMix64 (Steele, Lea, Flood 2014): one step, then the top 53 bits as a double in [0, 1).
  state_ += 0x9E3779B97F4A7C15ull;
  std::uint64_t mixed = state_;
  mixed = (mixed ^ (mixed >> 30)) * 0xBF58476D1CE4E5B9ull;
  mixed = (mixed ^ (mixed >> 27)) * 0x94D049BB133111EBull;
  mixed ^= mixed >> 31;
  return static_cast<double>(mixed >> 11) * 0x1.0p-53;
}

}  // namespace oasis::hw::go1
