// `oasis-go1 score LOG...`: the paper's Table II metrics for one or more step logs.

#include <iostream>
#include <memory>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include "app/commands.hpp"
#include "app/print_error.hpp"
#include "command_line/number_options.hpp"
#include "log/log_error.hpp"
#include "log/step_log_reader.hpp"
#include "log/table2_metrics.hpp"
#include "log/table2_report.hpp"

namespace oasis::hw::app {
namespace {

struct ScoreRequest {
  std::vector<std::string> logs;
  std::optional<double> period_s;
  bool json = false;
};

int score(const ScoreRequest& request) {
  std::vector<log::TrialScore> trials;
  log::ScoreOptions options;
  options.period_s = request.period_s;
  try {
    for (const std::string& path : request.logs) {
      const log::StepLog step_log = log::read_step_log(path);
      for (const std::string& warning : step_log.warnings)
        std::cerr << warning << '\n';  // already "FILE:LINE: warning: ..."
      if (step_log.records.empty()) {  // nothing to score is an error, not a table of zeros
        print_error("the log has no steps to score", path);
        return 1;
      }
      trials.push_back(log::score_trial(step_log.records, options));
    }
  } catch (const log::LogError& e) {
    std::cerr << e.what() << '\n';
    return 1;
  } catch (const std::invalid_argument& e) {  // a log whose time does not advance
    print_error(e.what());
    return 1;
  }
  const log::Table2Summary summary = log::summarize_trials(trials);
  if (request.json)
    std::cout << log::table2_json(summary).dump(2) << '\n';
  else
    log::print_table2(std::cout, summary);
  return 0;
}

}  // namespace

CommandRunner add_score_command(CLI::App& app) {
  auto request = std::make_shared<ScoreRequest>();
  CLI::App* command = app.add_subcommand(
      "score", "print the paper's Table II metrics (accuracy, lags, normalized reward) for logs");
  command->add_option("logs", request->logs, "step logs written by run --log, one per trial")
      ->required()
      ->check(CLI::ExistingFile);
  command
      ->add_option("--period", request->period_s,
                   "seconds per step for the lags; default: the median step of each log")
      ->check(oasis::cli::real_in(oasis::cli::positive(3600.0)));
  command->add_flag("--json", request->json,
                    "print {accuracy, avg_lag_s, max_lag_s, normalized_reward} as JSON, each "
                    "{mean, std} over the logs");
  command->footer(
      "Accuracy and lags need a log with ground truth (the synthetic source writes it); "
      "without it they are reported as unavailable. See hw/log/README.md.");
  return [request] { return score(*request); };
}

}  // namespace oasis::hw::app
