#include <unistd.h>

#include "cli/commands.hpp"
#include "command_line/memory_option.hpp"
#include "command_line/number_options.hpp"
#include "support/limits.hpp"

namespace oasis::cli {

void add_common_options(CLI::App& command, CommonOptions& options) {
  command
      .add_option("--max-states", options.load.max_states,
                  "Refuse a model past this many states, explored or declared by a model "
                  "file's header (by default only what 32-bit state numbers cannot hold: "
                  "--memory-budget bounds the model)")
      ->capture_default_str()
      ->check(whole_in(1, limits::kMaxStates));
  command.add_option("--max-errors", options.max_errors, "Stop after this many errors")
      ->capture_default_str()
      ->check(whole_in(1, 100000));
  as_size(command
              .add_option("--max-spec-size", options.load.max_spec_bytes,
                          "Refuse .oasis and PRISM programs larger than this (bytes, or with a "
                          "unit: 64M)")
              ->capture_default_str());
  as_size(command
              .add_option("--max-input-size", options.load.max_input_bytes,
                          "Refuse .aut, .tra, CSV and JSON inputs larger than this (bytes, or "
                          "with a unit: 8G)")
              ->capture_default_str());
  command
      .add_option("--max-number-bits", options.load.max_number_bits,
                  "Refuse exact numbers whose numerator or denominator has more bits than this")
      ->capture_default_str()
      ->check(whole_in(64, std::uint64_t{1} << 34));
  command.add_option("--const", options.load.constants,
                     "PRISM programs: values of the constants the program leaves undefined, "
                     "as NAME=VALUE separated by commas (N=4,p=0.1,fair=true)");
  command
      .add_option("--rewards", options.load.rewards,
                  "PRISM programs: the reward structures that become contexts: none (as Storm, "
                  "which builds a reward model only when a property needs it), all, or names "
                  "separated by commas. With none, the program has one context, 'default'")
      ->capture_default_str()
      ->check(
          [](const std::string& value) -> std::string {
            return model::LabelSelection::parse(value) ? ""
                                                       : "expected none, all or reward structure "
                                                         "names separated by commas, got \"" +
                                                             value + "\"";
          },
          "none|all|R1,R2");
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
  // A model file whose header declares more than reading it could fit is refused at once.
  load.memory_budget = command_memory_budget();
  load.progress =
      options.progress == "always" || (options.progress == "auto" && ::isatty(STDERR_FILENO) == 1);
  return load;
}

}  // namespace oasis::cli
