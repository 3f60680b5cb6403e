#pragma once
// Logged runs for the switching fit (docs/fitting.md): one CSV row per filter step with the
// observed state and reward, optionally the run, the step number and the action taken.
//
//   run,step,action,observed_state,reward
//   0,0,R,s2,0
//   0,1,L,s1,1
//
// Columns:
//   observed_state  required; a state name of the spec
//   reward          required; a number
//   run             optional; rows of one run need not be adjacent. Without it the file is
//                   one run. Runs of different files are different runs.
//   step (or t)     optional; integers increasing within a run. A gap (step 7 after step 4)
//                   means steps whose observation is missing: the filter predicts through
//                   them without a measurement.
//   action          optional; an action name of the spec, the action taken before the state
//                   was observed (a_t). Empty, '-' or '?' (or no column) is an unknown action:
//                   the joint filter then moves the true state with every action enabled in
//                   it, equally likely (the random actions of oasis-sim). The paper's filter
//                   does not use actions.
// Other columns are ignored, so `oasis-sim table1 --csv-dir` traces
// (t,true_context,inferred_ml,true_state,observed_state,reward) are read as they are.

#include <cstdint>
#include <string>
#include <vector>

#include "fit/csv_table.hpp"

namespace oasis::fit {

inline constexpr std::uint32_t kUnknownAction = 0xFFFFFFFFu;

struct LoggedStep {
  std::uint32_t observed_state = 0;
  double reward = 0.0;
  std::uint32_t action = kUnknownAction;
  std::uint32_t missing_before = 0;  // steps without an observation just before this one
};

struct LoggedRun {
  std::string name;  // "file" or "file:run"
  std::vector<LoggedStep> steps;
};

// The names a log refers to: the spec's states and actions, in index order.
struct LogNames {
  std::vector<std::string> states;
  std::vector<std::string> actions;
};

// The longest gap between two logged steps of a run (in steps) accepted.
inline constexpr std::uint64_t kMaxMissingSteps = 1'000'000;

// Appends the runs of `table` to `runs`. false after reporting errors (missing columns,
// unknown names, bad numbers, steps that do not increase).
bool read_switching_log(const CsvTable& table, const LogNames& names, std::vector<LoggedRun>& runs,
                        DiagnosticEngine& diagnostics);

}  // namespace oasis::fit
