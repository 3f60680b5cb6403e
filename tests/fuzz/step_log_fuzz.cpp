// The step log reader of oasis-go1 replay and score (hw/log/step_log_reader.hpp, one JSON
// object per line): any text is refused with a LogError naming the file, or gives records that
// survive a round trip through step_to_json() and step_from_json(). The score of the records
// is then computed as `oasis-go1 score` does: it may refuse a log whose time does not advance
// (std::invalid_argument, reported by the program), and nothing else.

#include <stdexcept>
#include <string>

#include "fuzz_target.hpp"
#include "log/log_error.hpp"
#include "log/step_json.hpp"
#include "log/step_log_reader.hpp"
#include "log/table2_metrics.hpp"
#include "log/table2_report.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace oasis::hw::log;
  StepLog log;
  try {
    log = parse_step_log(oasis::fuzz::text_of(data, size), "fuzz.jsonl");
  } catch (const LogError& error) {
    FUZZ_REQUIRE(std::string(error.what()).find("fuzz.jsonl") != std::string::npos);
    return 0;
  }
  for (const StepRecord& record : log.records) {
    const nlohmann::ordered_json written = step_to_json(record);
    std::string error;
    const auto back = step_from_json(written, error);
    FUZZ_REQUIRE(back.has_value());
    FUZZ_REQUIRE(step_to_json(*back).dump() == written.dump());
  }
  try {
    const TrialScore score = score_trial(log.records);
    (void)table2_json(summarize_trials({score})).dump();
  } catch (const std::invalid_argument&) {
    // a log whose time does not advance: `oasis-go1 score` reports it and exits 1
  }
  return 0;
}
