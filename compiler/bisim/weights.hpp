#pragma once
// How refinement adds up probabilities. Three exact-or-declared-approximate representations
// behind one small interface, chosen once per context:
//   - Integer: every probability of the context is k / D for one common denominator D that
//     fits in 62 bits, so a sum of probabilities (at most 1) is an exact integer <= D.
//     This is the fast path and covers every model written with decimals or small fractions.
//   - Rational: exact GMP sums, for denominators whose common multiple is too large.
//   - Rounded (the user's --epsilon): doubles, compared after rounding to a multiple of the
//     rounding step.

#include <cmath>
#include <cstdint>
#include <optional>
#include <span>
#include <vector>

#include "model/explicit_model.hpp"

namespace oasis::bisim {

// The pieces of the Integer representation, shared with the distributed engine, which finds
// the common denominator over all ranks' probabilities.

// Which ids of a pool of `pool_size` values `ids` uses.
std::vector<bool> used_values(std::size_t pool_size, std::span<const ValueId> ids);
// Makes `denominator` the least common multiple of itself and `other`; false when that passes
// 2^62, past which a sum of probabilities over it could overflow.
bool extend_common_denominator(mpz_class& denominator, const mpz_class& other);
// The least common denominator of the values `used` marks, or nullopt past 2^62.
std::optional<mpz_class> common_denominator(const RationalPool& values,
                                            const std::vector<bool>& used);
// Each used value (a probability) as its numerator over `denominator`, a multiple of its
// denominator; 0 for the ids not used.
std::vector<std::uint64_t> numerators_over(const RationalPool& values,
                                           const std::vector<bool>& used,
                                           const mpz_class& denominator);

enum class WeightMode { Integer, Rational, Rounded };

// Per probability id of the model's pool: its value in the chosen representation.
struct WeightTable {
  WeightMode mode = WeightMode::Integer;
  std::vector<std::uint64_t> integer;  // Integer: numerator over the common denominator
  std::vector<double> real;            // Rounded: the nearest double
  double rounding_step = 0;            // Rounded: sums are compared as multiples of this

  // Picks Integer when the common denominator of the probabilities used by `matrix` fits,
  // Rational otherwise; Rounded when `rounding_step` is given.
  // `rational` forces the Rational representation.
  static WeightTable choose(const model::ExplicitModel& model,
                            const model::TransitionMatrix& matrix,
                            std::optional<double> rounding_step, bool rational = false);

  // The key a summed weight is compared by in Rounded mode.
  [[nodiscard]] std::int64_t rounded_key(double weight) const {
    return std::llround(weight / rounding_step);
  }
};

}  // namespace oasis::bisim
