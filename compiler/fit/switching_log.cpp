#include "fit/switching_log.hpp"

#include <map>
#include <optional>
#include <unordered_map>

#include "support/text.hpp"

namespace oasis::fit {
namespace {

class NameIndex {
 public:
  NameIndex(const std::vector<std::string>& names, std::string kind)
      : names_(names), kind_(std::move(kind)) {
    for (std::size_t i = 0; i < names.size(); ++i)
      index_.emplace(names[i], static_cast<std::uint32_t>(i));
  }

  std::optional<std::uint32_t> find(const CsvCell& cell, DiagnosticEngine& diagnostics) const {
    const auto found = index_.find(cell.text);
    if (found != index_.end()) return found->second;
    std::string known;
    const std::size_t shown = std::min<std::size_t>(names_.size(), 12);
    for (std::size_t i = 0; i < shown; ++i)
      known += (i ? ", " : "") + names_[i];
    if (shown < names_.size()) known += ", ...";
    diagnostics.error(cell.where, "unknown " + kind_ + " " + quoted(cell.text) + " (the spec's " +
                                      kind_ + "s: " + known + ")");
    return std::nullopt;
  }

 private:
  const std::vector<std::string>& names_;
  std::string kind_;
  std::unordered_map<std::string, std::uint32_t> index_;
};

bool unknown_action_text(const std::string& text) {
  return text.empty() || text == "-" || text == "?";
}

}  // namespace

bool read_switching_log(const CsvTable& table, const LogNames& names, std::vector<LoggedRun>& runs,
                        DiagnosticEngine& diagnostics) {
  const std::optional<std::size_t> state_column = table.column("observed_state");
  const std::optional<std::size_t> reward_column = table.column("reward");
  if (!state_column) return missing_column(table, "observed_state", diagnostics);
  if (!reward_column) return missing_column(table, "reward", diagnostics);
  const std::optional<std::size_t> run_column = table.column("run");
  std::optional<std::size_t> step_column = table.column("step");
  if (!step_column) step_column = table.column("t");
  const std::optional<std::size_t> action_column = table.column("action");

  const NameIndex states(names.states, "state");
  const NameIndex actions(names.actions, "action");
  struct Open {
    std::size_t run;  // index into runs
    std::optional<std::uint64_t> last_step;
  };
  std::map<std::string, Open> open;  // run id -> its run
  const std::size_t errors_before = diagnostics.error_count();
  for (const CsvRow& row : table.rows) {
    if (diagnostics.should_stop()) break;
    const std::string id = run_column ? row.cells[*run_column].text : std::string();
    auto [it, inserted] = open.try_emplace(id, Open{runs.size(), std::nullopt});
    if (inserted) runs.push_back({run_column ? table.path + ":" + id : table.path, {}});
    Open& run = it->second;

    LoggedStep step;
    const std::optional<std::uint32_t> state = states.find(row.cells[*state_column], diagnostics);
    const std::optional<double> reward =
        parse_number(row.cells[*reward_column], "the reward", diagnostics);
    bool ok = state && reward;
    if (action_column && !unknown_action_text(row.cells[*action_column].text)) {
      const std::optional<std::uint32_t> action =
          actions.find(row.cells[*action_column], diagnostics);
      if (action) step.action = *action;
      ok = ok && action;
    }
    if (step_column) {
      const CsvCell& cell = row.cells[*step_column];
      const std::optional<std::uint64_t> number = parse_count(cell, "the step", diagnostics);
      if (!number) {
        ok = false;
      } else if (run.last_step && *number <= *run.last_step) {
        diagnostics.error(cell.where, "step " + cell.text + " does not follow step " +
                                          std::to_string(*run.last_step) +
                                          (run_column ? " of run " + quoted(id) : "") +
                                          ": steps must increase within a run");
        ok = false;
      } else if (run.last_step && *number - *run.last_step - 1 > kMaxMissingSteps) {
        diagnostics.error(cell.where, "step " + cell.text + " leaves more than " +
                                          std::to_string(kMaxMissingSteps) +
                                          " steps without an observation");
        ok = false;
      } else {
        if (run.last_step)
          step.missing_before = static_cast<std::uint32_t>(*number - *run.last_step - 1);
        run.last_step = *number;
      }
    }
    if (!ok) continue;
    step.observed_state = *state;
    step.reward = *reward;
    runs[run.run].steps.push_back(step);
  }
  return diagnostics.error_count() == errors_before;
}

}  // namespace oasis::fit
