#include "fit/noise_fit.hpp"

#include <unordered_map>

#include "support/text.hpp"

namespace oasis::fit {

std::uint64_t NoiseCounts::total() const {
  std::uint64_t sum = 0;
  for (std::uint64_t c : counts)
    sum += c;
  return sum;
}

std::uint64_t NoiseCounts::wrong() const {
  std::uint64_t sum = total();
  for (std::uint32_t s = 0; s < num_states; ++s)
    sum -= counts[static_cast<std::size_t>(s) * num_states + s];
  return sum;
}

std::uint64_t NoiseCounts::row_total(std::uint32_t s) const {
  std::uint64_t sum = 0;
  for (std::uint32_t o = 0; o < num_states; ++o)
    sum += counts[static_cast<std::size_t>(s) * num_states + o];
  return sum;
}

bool read_noise_labels(const CsvTable& table, const std::vector<std::string>& states,
                       NoiseCounts& counts, DiagnosticEngine& diagnostics) {
  const auto true_column = table.column("true_state");
  const auto observed_column = table.column("observed_state");
  if (!true_column) return missing_column(table, "true_state", diagnostics);
  if (!observed_column) return missing_column(table, "observed_state", diagnostics);
  if (counts.counts.empty()) {
    counts.num_states = static_cast<std::uint32_t>(states.size());
    counts.counts.assign(states.size() * states.size(), 0);
  }
  std::unordered_map<std::string, std::uint32_t> index;
  for (std::size_t i = 0; i < states.size(); ++i)
    index.emplace(states[i], static_cast<std::uint32_t>(i));
  std::string known;
  for (std::size_t i = 0; i < states.size() && i < 12; ++i)
    known += (i ? ", " : "") + states[i];
  if (states.size() > 12) known += ", ...";
  const auto lookup = [&](const CsvCell& cell) -> std::optional<std::uint32_t> {
    const auto found = index.find(cell.text);
    if (found != index.end()) return found->second;
    diagnostics.error(cell.where,
                      "unknown state " + quoted(cell.text) + " (the spec's states: " + known + ")");
    return std::nullopt;
  };
  const std::size_t errors_before = diagnostics.error_count();
  for (const CsvRow& row : table.rows) {
    if (diagnostics.should_stop()) break;
    const auto s = lookup(row.cells[*true_column]);
    const auto o = lookup(row.cells[*observed_column]);
    if (s && o) ++counts.counts[static_cast<std::size_t>(*s) * counts.num_states + *o];
  }
  return diagnostics.error_count() == errors_before;
}

SymmetricNoiseFit fit_symmetric_noise(const NoiseCounts& counts) {
  SymmetricNoiseFit fit;
  fit.total = counts.total();
  fit.wrong = counts.wrong();
  fit.sigma = static_cast<double>(fit.wrong) / static_cast<double>(fit.total);
  fit.interval = wilson_interval(static_cast<double>(fit.wrong), static_cast<double>(fit.total));
  return fit;
}

ConfusionFit fit_confusion(const NoiseCounts& counts, double pseudo_count) {
  const std::uint32_t n = counts.num_states;
  const SymmetricNoiseFit symmetric = fit_symmetric_noise(counts);
  ConfusionFit fit;
  fit.matrix.assign(static_cast<std::size_t>(n) * n, 0.0);
  fit.intervals.assign(static_cast<std::size_t>(n) * n, Interval{0.0, 1.0});
  for (std::uint32_t s = 0; s < n; ++s) {
    const std::size_t base = static_cast<std::size_t>(s) * n;
    const double row_total = static_cast<double>(counts.row_total(s)) + pseudo_count * n;
    if (counts.row_total(s) == 0) {
      fit.rows_without_pairs.push_back(s);
      for (std::uint32_t o = 0; o < n; ++o)
        fit.matrix[base + o] = o == s ? 1.0 - symmetric.sigma : symmetric.sigma / (n - 1);
      fit.intervals[base + s] = {1.0 - symmetric.interval.high, 1.0 - symmetric.interval.low};
      continue;
    }
    for (std::uint32_t o = 0; o < n; ++o) {
      const double count = static_cast<double>(counts.counts[base + o]) + pseudo_count;
      fit.matrix[base + o] = count / row_total;
      fit.intervals[base + o] = wilson_interval(count, row_total);
    }
  }
  return fit;
}

}  // namespace oasis::fit
