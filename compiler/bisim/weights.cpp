#include "bisim/weights.hpp"

namespace oasis::bisim {

std::vector<bool> used_values(std::size_t pool_size, std::span<const ValueId> ids) {
  std::vector<bool> used(pool_size, false);
  for (ValueId id : ids)
    used[id] = true;
  return used;
}

bool extend_common_denominator(mpz_class& denominator, const mpz_class& other) {
  mpz_lcm(denominator.get_mpz_t(), denominator.get_mpz_t(), other.get_mpz_t());
  return denominator <= mpz_class(1) << 62;
}

std::optional<mpz_class> common_denominator(const RationalPool& values,
                                            const std::vector<bool>& used) {
  mpz_class denominator = 1;
  for (std::size_t id = 0; id < used.size(); ++id) {
    if (used[id] &&
        !extend_common_denominator(denominator, values[static_cast<ValueId>(id)].get_den()))
      return std::nullopt;
  }
  return denominator;
}

std::vector<std::uint64_t> numerators_over(const RationalPool& values,
                                           const std::vector<bool>& used,
                                           const mpz_class& denominator) {
  std::vector<std::uint64_t> numerators(values.size(), 0);
  for (std::size_t id = 0; id < used.size(); ++id) {
    if (!used[id]) continue;
    const Rational& p = values[static_cast<ValueId>(id)];
    const mpz_class numerator = p.get_num() * (denominator / p.get_den());
    numerators[id] = numerator.get_ui();  // 0 < p <= 1, so 0 < numerator <= denominator
  }
  return numerators;
}

WeightTable WeightTable::choose(const model::ExplicitModel& model,
                                const model::TransitionMatrix& matrix,
                                std::optional<double> rounding_step, bool rational) {
  WeightTable table;
  const std::size_t num_values = model.values.size();
  if (rounding_step) {
    table.mode = WeightMode::Rounded;
    table.rounding_step = *rounding_step;
    table.real.resize(num_values);
    for (std::size_t id = 0; id < num_values; ++id)
      table.real[id] = to_double(model.values[id]);
    return table;
  }
  if (rational) {
    table.mode = WeightMode::Rational;
    return table;
  }
  // The common denominator of the probabilities this context uses (few distinct values).
  const std::vector<bool> used = used_values(num_values, matrix.edge_probability);
  const std::optional<mpz_class> denominator = common_denominator(model.values, used);
  if (!denominator) {
    table.mode = WeightMode::Rational;
    return table;
  }
  table.mode = WeightMode::Integer;
  table.integer = numerators_over(model.values, used, *denominator);
  return table;
}

}  // namespace oasis::bisim
