#include "table1/report.hpp"

#include <algorithm>
#include <iomanip>
#include <map>
#include <sstream>
#include <tuple>

#include "metrics/table_text.hpp"
#include "support/atomic_file.hpp"

namespace oasis::table1 {
namespace {

std::string cell(const metrics::MeanStd& value) {
  return metrics::mean_std_text(value);
}

std::string pattern_label(Pattern pattern) {
  switch (pattern) {
    case Pattern::kStep:
      return "step (t=100)";
    case Pattern::kNoisyStep:
      return "noisy step";
    case Pattern::kPeriodic:
      return "periodic (10)";
    case Pattern::kNoisyPeriodic:
      return "noisy periodic";
    case Pattern::kUniformRandom:
      return "uniform random";
  }
  return "?";
}

const RowResult* find_row(const std::vector<RowResult>& rows, const std::string& model,
                          Pattern pattern, NoiseReading noise, FilterKind filter,
                          NoiseReading declared = NoiseReading::kNone) {
  for (const RowResult& row : rows)
    if (row.model == model && row.pattern == pattern && row.noise == noise &&
        row.filter == filter && row.declared == declared)
      return &row;
  return nullptr;
}

// "robust", or "robust:perceived" when the table runs more than one declared reading.
std::string column_label(FilterKind filter, NoiseReading declared, const Table1Options& options) {
  std::string label(filter_name(filter));
  if (declared != NoiseReading::kNone && options.declared.size() > 1)
    label += ":" + std::string(noise_name(declared));
  return label;
}

}  // namespace

std::optional<PaperReference> paper_reference(const std::string& model, Pattern pattern) {
  // Table I of the paper, transcribed.
  static const std::map<std::pair<std::string, Pattern>, PaperReference> table{
      {{"i", Pattern::kStep}, {{0.99, 0.00}, {0.10, 0.20}, {0.20, 0.40}}},
      {{"i", Pattern::kNoisyStep}, {{0.99, 0.00}, {0.70, 0.98}, {0.80, 1.17}}},
      {{"i", Pattern::kPeriodic}, {{0.93, 0.001}, {0.70, 0.1}, {6.80, 1.72}}},
      {{"i", Pattern::kNoisyPeriodic}, {{0.95, 0.01}, {0.48, 0.05}, {4.00, 0.63}}},
      {{"i", Pattern::kUniformRandom}, {{0.84, 0.01}, {0.31, 0.03}, {3.80, 1.17}}},
      {{"ii", Pattern::kStep}, {{0.83, 0.01}, {0.00, 0.00}, {0.00, 0.00}}},
      {{"ii", Pattern::kNoisyStep}, {{0.83, 0.01}, {0.50, 0.32}, {1.00, 0.63}}},
      {{"ii", Pattern::kPeriodic}, {{0.84, 0.01}, {0.22, 0.06}, {2.60, 0.49}}},
      {{"ii", Pattern::kNoisyPeriodic}, {{0.83, 0.02}, {0.24, 0.11}, {2.40, 1.02}}},
      {{"ii", Pattern::kUniformRandom}, {{0.84, 0.01}, {0.19, 0.03}, {2.40, 0.49}}},
  };
  const auto found = table.find({model, pattern});
  if (found == table.end()) return std::nullopt;
  return found->second;
}

void print_table(std::ostream& out, const std::vector<RowResult>& rows,
                 const Table1Options& options) {
  out << "Table I, discrete-space tracking: " << options.steps << " steps, " << options.seeds
      << " seeds, sigma = " << options.sigma
      << " for the noisy patterns; ours = mean ± population std over seeds;\n"
      << "'paper' columns are the paper's printed Table I (reference, not computed).\n";
  std::vector<std::pair<Pattern, NoiseReading>> lines;
  for (Pattern pattern : options.patterns) {
    if (!pattern_is_noisy(pattern)) {
      lines.emplace_back(pattern, NoiseReading::kNone);
      continue;
    }
    for (NoiseReading noise : options.noises)
      lines.emplace_back(pattern, noise);
  }
  const bool has_paper = std::find(options.filters.begin(), options.filters.end(),
                                   FilterKind::kPaper) != options.filters.end();
  std::vector<TransitionModel> models = table1_models();
  if (options.fit_runs > 0) models.push_back({"fit", 0.0});
  for (const TransitionModel& model : models) {
    if (model.id == "fit")
      out << "\n== Abstraction transition model (fit): p(stay) fitted per row from "
          << options.fit_runs << " training runs of its pattern and noise ==\n";
    else
      out << "\n== Abstraction transition model (" << model.id << "): p(stay) = " << model.p_stay
          << " ==\n";
    if (has_paper) {
      out << "filter paper (Algorithm 1, random ties)\n";
      out << metrics::pad_columns("pattern", 16) << metrics::pad_columns("noise", 11) << "| "
          << metrics::pad_columns("accuracy", 13) << metrics::pad_columns("avg lag", 13)
          << metrics::pad_columns("max lag", 13) << "| " << metrics::pad_columns("paper: acc", 13)
          << metrics::pad_columns("avg lag", 13) << "max lag\n";
      for (const auto& [pattern, noise] : lines) {
        const RowResult* row = find_row(rows, model.id, pattern, noise, FilterKind::kPaper);
        if (row == nullptr) continue;
        out << metrics::pad_columns(pattern_label(pattern), 16)
            << metrics::pad_columns(std::string(noise_name(noise)), 11) << "| "
            << metrics::pad_columns(cell(row->accuracy), 13)
            << metrics::pad_columns(cell(row->avg_lag), 13)
            << metrics::pad_columns(cell(row->max_lag), 13) << "| ";
        if (const auto reference = paper_reference(model.id, pattern))
          out << metrics::pad_columns(cell(reference->accuracy), 13)
              << metrics::pad_columns(cell(reference->avg_lag), 13) << cell(reference->max_lag);
        if (model.id == "fit") {
          std::ostringstream fitted;
          fitted << std::fixed << std::setprecision(4) << row->p_stay;
          out << "fitted p(stay) = " << fitted.str();
        }
        out << "\n";
      }
    }
    out << "all filters: accuracy / avg lag / max lag (means); zero-likelihood steps per trial "
           "(mean)\n";
    out << metrics::pad_columns("pattern", 16) << metrics::pad_columns("noise", 11);
    const auto columns = filter_columns(options);
    for (const auto& [filter, declared] : columns)
      out << "| " << metrics::pad_columns(column_label(filter, declared, options), 23);
    out << "\n";
    for (const auto& [pattern, noise] : lines) {
      out << metrics::pad_columns(pattern_label(pattern), 16)
          << metrics::pad_columns(std::string(noise_name(noise)), 11);
      for (const auto& [filter, declared] : columns) {
        const RowResult* row = find_row(rows, model.id, pattern, noise, filter, declared);
        std::ostringstream text;
        if (row != nullptr)
          text << std::fixed << std::setprecision(2) << row->accuracy.mean << " / "
               << row->avg_lag.mean << " / " << std::setprecision(1) << row->max_lag.mean << " z"
               << std::setprecision(0) << row->zero_likelihood_steps.mean;
        out << "| " << metrics::pad_columns(text.str(), 23);
      }
      out << "\n";
    }
  }
}

nlohmann::json rows_json(const std::vector<RowResult>& rows) {
  const auto stat = [](const metrics::MeanStd& value) {
    return nlohmann::json{{"mean", value.mean}, {"std", value.std}};
  };
  nlohmann::json list = nlohmann::json::array();
  for (const RowResult& row : rows)
    list.push_back({{"model", row.model},
                    {"pattern", std::string(pattern_name(row.pattern))},
                    {"noise", std::string(noise_name(row.noise))},
                    {"filter", std::string(filter_name(row.filter))},
                    {"declared", row.declared == NoiseReading::kNone
                                     ? nlohmann::json(nullptr)
                                     : nlohmann::json(std::string(noise_name(row.declared)))},
                    {"p_stay", row.p_stay},
                    {"accuracy", stat(row.accuracy)},
                    {"avg_lag", stat(row.avg_lag)},
                    {"max_lag", stat(row.max_lag)},
                    {"zero_likelihood_steps", stat(row.zero_likelihood_steps)}});
  return list;
}

bool write_text(const std::filesystem::path& path, const std::string& text, std::string& error) {
  AtomicFile file;  // whole or not at all: an interrupted run leaves the previous file
  std::string reason;
  if (file.open(path.string(), reason)) {
    file.append(text);
    if (file.commit(reason)) return true;
  }
  error = "cannot write " + path.string() + ": " + reason;
  return false;
}

std::string trace_csv(const Trace& trace, const std::vector<std::string>& context_names,
                      const std::vector<std::string>& state_names) {
  const auto name = [](const std::vector<std::string>& names, std::uint32_t i) {
    return i < names.size() ? names[i] : std::to_string(i);
  };
  std::ostringstream out;
  out << "t,true_context,inferred_ml,true_state,observed_state,reward\n";
  for (std::size_t k = 0; k < trace.truth.size(); ++k)
    out << k << ',' << name(context_names, trace.truth[k]) << ','
        << name(context_names, trace.inferred[k]) << ',' << name(state_names, trace.true_state[k])
        << ',' << name(state_names, trace.observed_state[k]) << ',' << trace.reward[k] << '\n';
  return out.str();
}

std::string trial_stem(const TrialSpec& spec) {
  return "model-" + spec.model.id + "_" + std::string(pattern_name(spec.pattern)) + "_" +
         std::string(noise_name(spec.noise)) + "_" + std::string(filter_name(spec.filter)) +
         (uses_declared_model(spec.filter) ? "-" + std::string(noise_name(spec.declared)) : "") +
         "_seed" + std::to_string(spec.seed);
}

std::string trace_svg(const TrialSpec& spec, const Trace& trace,
                      const std::vector<std::string>& context_names, std::size_t steps) {
  steps = std::min(steps, trace.truth.size());
  const double width = 900, height = 220, left = 120, right = 20, top = 40, bottom = 40;
  const double plot_w = width - left - right, plot_h = height - top - bottom;
  std::size_t levels = context_names.size();
  for (std::size_t k = 0; k < steps; ++k)
    levels = std::max<std::size_t>({levels, trace.truth[k] + 1u, trace.inferred[k] + 1u});
  levels = std::max<std::size_t>(levels, 2);
  const auto x = [&](double k) { return left + plot_w * k / static_cast<double>(steps); };
  const auto y = [&](double level) {
    return top + plot_h * (1.0 - level / static_cast<double>(levels - 1));
  };
  const auto path = [&](const std::vector<std::uint32_t>& values, double offset) {
    std::ostringstream d;
    d << std::fixed << std::setprecision(1);
    for (std::size_t k = 0; k < steps; ++k) {
      const double level = values[k] + offset;
      d << (k == 0 ? "M" : "L") << x(static_cast<double>(k)) << ',' << y(level) << " L"
        << x(static_cast<double>(k + 1)) << ',' << y(level) << ' ';
    }
    return d.str();
  };
  std::ostringstream svg;
  svg << std::fixed << std::setprecision(1);
  svg << "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"" << width << "\" height=\"" << height
      << "\" viewBox=\"0 0 " << width << ' ' << height << "\" font-family=\"sans-serif\" "
      << "font-size=\"12\">\n<rect width=\"100%\" height=\"100%\" fill=\"white\"/>\n";
  svg << "<text x=\"" << left << "\" y=\"20\">" << trial_stem(spec) << " (first " << steps
      << " steps)</text>\n";
  svg << "<line x1=\"" << left << "\" y1=\"" << top + plot_h << "\" x2=\"" << left + plot_w
      << "\" y2=\"" << top + plot_h << "\" stroke=\"black\"/>\n";
  for (std::size_t tick = 0; tick <= steps; tick += 25)
    svg << "<text x=\"" << x(static_cast<double>(tick)) << "\" y=\"" << top + plot_h + 16
        << "\" text-anchor=\"middle\">" << tick << "</text>\n";
  for (std::size_t level = 0; level < levels; ++level) {
    const std::string label =
        level < context_names.size() ? context_names[level] : std::to_string(level);
    svg << "<text x=\"" << left - 8 << "\" y=\"" << y(static_cast<double>(level)) + 4
        << "\" text-anchor=\"end\">" << label << "</text>\n";
  }
  std::vector<std::uint32_t> truth(trace.truth.begin(), trace.truth.begin() + steps);
  std::vector<std::uint32_t> inferred(trace.inferred.begin(), trace.inferred.begin() + steps);
  // The inferred line is drawn a little off the true one so that both stay visible.
  svg << "<path d=\"" << path(truth, 0.0) << "\" fill=\"none\" stroke=\"#1f77b4\" "
      << "stroke-width=\"2\"/>\n";
  svg << "<path d=\"" << path(inferred, 0.03) << "\" fill=\"none\" stroke=\"#ff7f0e\" "
      << "stroke-width=\"2\" stroke-dasharray=\"2,3\"/>\n";
  svg << "<text x=\"" << width - right - 200 << "\" y=\"20\" fill=\"#1f77b4\">true</text>\n";
  svg << "<text x=\"" << width - right - 150
      << "\" y=\"20\" fill=\"#ff7f0e\">inferred (ML)</text>\n";
  svg << "</svg>\n";
  return svg.str();
}

}  // namespace oasis::table1
