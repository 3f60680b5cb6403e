#include "go1/loss_model.hpp"

namespace oasis::hw::go1 {

bool LossModel::drop_next() {
  return next_uniform() < loss_probability_;
}

double LossModel::next_uniform() {
  return bits_.uniform();
}

}  // namespace oasis::hw::go1
