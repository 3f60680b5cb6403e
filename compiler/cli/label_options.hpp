#pragma once
// --respect-labels, shared by `quotient` (which labels the bisimulation respects) and the
// record of it that `verify` reads back from a quotient's JSON.

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>

#include "model/explicit_model.hpp"

namespace oasis::cli {

void add_respect_labels_option(CLI::App& command, std::string& text);

// The states' classes of the labels `text` selects ("all", "none", "L1,L2"); empty when none
// are respected. Prints "FILE: error: ..." and returns nullopt for a label the model lacks.
std::optional<std::vector<std::uint32_t>> respected_label_classes(const model::ExplicitModel& model,
                                                                  const std::string& text,
                                                                  const std::string& file);

}  // namespace oasis::cli
