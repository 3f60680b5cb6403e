#include <unistd.h>

#include "cli/commands.hpp"
#include "cli/number_options.hpp"

namespace oasis::cli {

void add_common_options(CLI::App& command, CommonOptions& options) {
  command
      .add_option("--max-states", options.load.max_states,
                  "Stop exploring a factored model past this many states")
      ->capture_default_str()
      ->check(whole_in(1, 4'000'000'000U));
  command.add_option("--max-errors", options.max_errors, "Stop after this many errors")
      ->capture_default_str()
      ->check(whole_in(1, 100000));
  command
      .add_option("--max-spec-size", options.load.max_spec_bytes,
                  "Refuse .oasis files larger than this (bytes, or with a unit: 64M)")
      ->capture_default_str()
      ->transform(CLI::AsSizeValue(false));
  command
      .add_option("--max-input-size", options.load.max_input_bytes,
                  "Refuse .aut, .tra, CSV and JSON inputs larger than this (bytes, or 2G; never "
                  "more than 2^32 - 1)")
      ->capture_default_str()
      ->transform(CLI::AsSizeValue(false));
  command
      .add_option("--max-number-bits", options.load.max_number_bits,
                  "Refuse exact numbers whose numerator or denominator has more bits than this")
      ->capture_default_str()
      ->check(whole_in(64, std::uint64_t{1} << 34));
  command
      .add_option("--progress", options.progress,
                  "Show progress on stderr (exploration, the stages of a continuous compile): auto "
                  "(when it is a terminal), "
                  "always or never")
      ->capture_default_str()
      ->check(CLI::IsMember({"auto", "always", "never"}));
}

LoadOptions effective_load_options(const CommonOptions& options) {
  LoadOptions load = options.load;
  load.progress =
      options.progress == "always" || (options.progress == "auto" && ::isatty(STDERR_FILENO) == 1);
  return load;
}

}  // namespace oasis::cli
