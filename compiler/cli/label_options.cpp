#include "cli/label_options.hpp"

#include <stdexcept>
#include <string>

#include "support/error_report.hpp"

namespace oasis::cli {

void add_respect_labels_option(CLI::App& command, std::string& text) {
  command
      .add_option("--respect-labels", text,
                  "Labels (atomic propositions: a PRISM .lab file) that bisimilar states must "
                  "share: all, none, or names separated by commas (as Storm's "
                  "respectedAtomicPropositions)")
      ->capture_default_str()
      ->check(
          [](const std::string& value) -> std::string {
            return model::LabelSelection::parse(value)
                       ? ""
                       : "expected all, none or label names separated by commas, got \"" + value +
                             "\"";
          },
          "all|none|L1,L2");
}

std::optional<std::vector<std::uint32_t>> respected_label_classes(const model::ExplicitModel& model,
                                                                  const std::string& text,
                                                                  const std::string& file) {
  const std::optional<model::LabelSelection> selection = model::LabelSelection::parse(text);
  if (!selection) {
    report_error(file, "--respect-labels: expected all, none or label names, got \"" + text + "\"");
    return std::nullopt;
  }
  try {
    return model::label_classes(model.labels, model.num_states(), *selection);
  } catch (const std::invalid_argument& e) {
    report_error(file, std::string("--respect-labels: ") + e.what());
    return std::nullopt;
  }
}

}  // namespace oasis::cli
