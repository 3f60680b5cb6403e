#include "bisim/weights.hpp"

namespace oasis::bisim {

WeightTable WeightTable::choose(const model::ExplicitModel& model,
                                const model::TransitionMatrix& matrix,
                                std::optional<double> epsilon, bool rational) {
  WeightTable table;
  const std::size_t num_values = model.values.size();
  if (epsilon) {
    table.mode = WeightMode::Rounded;
    table.epsilon = *epsilon;
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
  std::vector<bool> used(num_values, false);
  for (ValueId id : matrix.edge_probability)
    used[id] = true;
  mpz_class denominator = 1;
  const mpz_class limit = mpz_class(1) << 62;
  for (std::size_t id = 0; id < num_values; ++id) {
    if (!used[id]) continue;
    mpz_lcm(denominator.get_mpz_t(), denominator.get_mpz_t(), model.values[id].get_den_mpz_t());
    if (denominator > limit) {
      table.mode = WeightMode::Rational;
      return table;
    }
  }
  table.mode = WeightMode::Integer;
  table.integer.assign(num_values, 0);
  for (std::size_t id = 0; id < num_values; ++id) {
    if (!used[id]) continue;
    const mpz_class numerator =
        model.values[id].get_num() * (denominator / model.values[id].get_den());
    table.integer[id] = numerator.get_ui();  // 0 < p <= 1, so 0 < numerator <= denominator
  }
  return table;
}

}  // namespace oasis::bisim
