#include "formats/prism_reader.hpp"

namespace oasis::formats {

std::string unlabelled_action_name(std::uint32_t choice) {
  return "[" + std::to_string(choice) + "]";
}

std::optional<model::ExplicitModel> read_prism(const PrismFiles&, DiagnosticEngine&,
                                               const ReadOptions&) {
  return std::nullopt;
}

}  // namespace oasis::formats
