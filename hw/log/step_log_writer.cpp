#include "log/step_log_writer.hpp"

#include <cerrno>
#include <cstring>
#include <string>

#include "log/log_error.hpp"
#include "log/step_json.hpp"

namespace oasis::hw::log {
namespace {

std::string system_reason() {
  return errno != 0 ? std::strerror(errno) : "unknown error";
}

}  // namespace

StepLogWriter::StepLogWriter(const std::filesystem::path& path)
    : path_(path), out_(path, std::ios::out | std::ios::trunc | std::ios::binary) {
  if (!out_)
    throw LogError(log_diagnostic(path_.string(), 0, "error", "cannot create: " + system_reason()));
}

void StepLogWriter::write(const StepRecord& record) {
  std::string line;
  try {
    // Invalid UTF-8 in a name becomes U+FFFD rather than costing the step.
    line = step_to_json(record).dump(-1, ' ', false, nlohmann::json::error_handler_t::replace);
  } catch (const LogError& failure) {
    throw LogError(log_diagnostic(path_.string(), 0, "error", failure.what()));
  }
  // One write of the whole line, then flush: the file never holds half a line from us unless
  // the process dies inside this call.
  line += '\n';
  out_.write(line.data(), static_cast<std::streamsize>(line.size()));
  out_.flush();
  if (!out_)
    throw LogError(log_diagnostic(
        path_.string(), 0, "error",
        "cannot write step " + std::to_string(record.step) + ": " + system_reason()));
}

}  // namespace oasis::hw::log
