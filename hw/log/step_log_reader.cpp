#include "log/step_log_reader.hpp"

#include <filesystem>
#include <limits>
#include <optional>

#include <nlohmann/json.hpp>

#include "files/input_file.hpp"
#include "log/log_error.hpp"
#include "log/step_json.hpp"
#include "text/printable_text.hpp"

namespace oasis::hw::log {
namespace {

struct Line {
  std::string_view text;
  std::size_t number = 0;  // from 1
  bool terminated = true;  // ends with '\n'
};

std::vector<Line> split_lines(std::string_view text) {
  std::vector<Line> lines;
  std::size_t begin = 0;
  while (begin < text.size()) {
    const std::size_t end = text.find('\n', begin);
    const bool terminated = end != std::string_view::npos;
    const std::size_t stop = terminated ? end : text.size();
    lines.push_back({text.substr(begin, stop - begin), lines.size() + 1, terminated});
    begin = stop + 1;
  }
  return lines;
}

std::optional<nlohmann::ordered_json> parse_json(std::string_view text, std::string& error) {
  try {
    return nlohmann::ordered_json::parse(text);
  } catch (const nlohmann::json::exception& failure) {
    // A syntax error (parse_error) or a number too large for a double (out_of_range.406).
    // nlohmann's text is "[json.exception.parse_error.101] parse error at line 1, column 7:
    // syntax error ..."; keep what follows the id, the column being the useful part.
    const std::string what = failure.what();
    const std::size_t after_id = what.find("] ");
    // It may quote the line (a 10 MB number): escaped and cut.
    error = "not valid JSON: " +
            oasis::text::printable_excerpt(
                after_id == std::string::npos ? what : what.substr(after_id + 2), 240);
    return std::nullopt;
  }
}

}  // namespace

StepLog parse_step_log(std::string_view text, const std::string& name) {
  StepLog log;
  for (const Line& line : split_lines(text)) {
    const auto fail = [&](const std::string& message) {
      return LogError(log_diagnostic(name, line.number, "error", message));
    };
    if (line.text.empty()) throw fail("empty line");
    std::string error;
    const std::optional<nlohmann::ordered_json> object = parse_json(line.text, error);
    if (!object) {
      if (line.terminated) throw fail(error);
      log.warnings.push_back(log_diagnostic(name, line.number, "warning",
                                            "last line is cut short (no newline, " + error +
                                                "); ignored, as a run killed while "
                                                "writing leaves it"));
      break;
    }
    std::optional<StepRecord> record = step_from_json(*object, error);
    if (!record) throw fail(error);
    log.records.push_back(std::move(*record));
  }
  return log;
}

StepLog read_step_log(const std::filesystem::path& path) {
  // The readers' one rule (common/files/input_file.hpp): a directory or device is refused, a
  // pipe nobody writes to too, after its grace period.
  std::string reason;
  const std::optional<std::string> text =
      files::read_input(path.string(), std::numeric_limits<std::size_t>::max(), reason);
  if (!text) throw LogError(log_diagnostic(path.string(), 0, "error", reason));
  return parse_step_log(*text, path.string());
}

}  // namespace oasis::hw::log
