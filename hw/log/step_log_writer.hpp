#pragma once
// Appends the loop's steps to a JSON-lines file (one step_json.hpp object per line) as they
// happen. Each line is flushed to the operating system before write() returns, so a run that is
// killed (SIGKILL, a crash, the watchdog pulling the plug) leaves every step it finished on
// disk; at worst the last line is cut short, which the reader reports and skips. There is no
// fsync per step: a power cut may lose what the kernel had not yet written.

#include <filesystem>
#include <fstream>

#include "log/step_record.hpp"

namespace oasis::hw::log {

class StepLogWriter {
 public:
  // Creates `path`, or empties it if it exists. Throws LogError if it cannot be opened.
  explicit StepLogWriter(const std::filesystem::path& path);

  // One line, flushed. Throws LogError when the record cannot be written (time_s not finite,
  // disk full); the lines before it stay intact.
  void write(const StepRecord& record);

  const std::filesystem::path& path() const { return path_; }

 private:
  std::filesystem::path path_;
  std::ofstream out_;
};

}  // namespace oasis::hw::log
