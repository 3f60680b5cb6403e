#pragma once
// Seeded packet loss for the fake Go1: the same seed drops the same packets (by arrival order)
// on every run and every standard library, because the generator (the runtime's SplitMix64) is
// our own.

#include <cstdint>

#include "oasis/rt/split_mix64.hpp"

namespace oasis::hw::go1 {

class LossModel {
 public:
  LossModel(double loss_probability, std::uint64_t seed)
      : loss_probability_(loss_probability), bits_(seed) {}

  // Whether the next packet is lost.
  bool drop_next();

  // The next number of the same stream, uniform in [0, 1): the fake's other faults draw here.
  double next_uniform();

 private:
  double loss_probability_;
  rt::SplitMix64 bits_;
};

}  // namespace oasis::hw::go1
