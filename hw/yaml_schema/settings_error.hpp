// What is wrong with a settings file (any YAML file read through a schema: the Go1 settings,
// a controller profile, a hallway scenario): every problem found, each in the compiler format
//   FILE:LINE:COL: error: KEY: MESSAGE
// followed by the offending source line and a caret under the column.
#pragma once

#include <stdexcept>
#include <string>
#include <vector>

namespace oasis::hw::yaml_schema {

struct Diagnostic {
  int line = 0;     // 1-based; 0: the problem has no place in the file (a missing file, a default)
  int column = 0;   // 1-based
  std::string key;  // dotted path, "robot.port"; empty for the file as a whole
  std::string message;      // lower-case fragment: "expected an integer in 1..65535, got \"80x2\""
  std::string source_line;  // the file's line `line`, for the caret; empty if none

  // Written out, not defaulted: this header is kept C++17-clean for the C++17 files that reach
  // it (hw/ros's ROS-facing files include the hallway world of hw/sim).
  bool operator==(const Diagnostic& other) const {
    return line == other.line && column == other.column && key == other.key &&
           message == other.message && source_line == other.source_line;
  }
  bool operator!=(const Diagnostic& other) const { return !(*this == other); }
};

// FILE:LINE:COL: error: KEY: MESSAGE, then the source line and a caret (if known).
std::string format_diagnostic(const std::string& file, const Diagnostic& diagnostic);

class SettingsError : public std::runtime_error {
 public:
  // what() is every diagnostic formatted, in order of position in the file.
  SettingsError(std::string file, std::vector<Diagnostic> diagnostics);

  const std::string& file() const { return file_; }
  const std::vector<Diagnostic>& diagnostics() const { return diagnostics_; }

 private:
  std::string file_;
  std::vector<Diagnostic> diagnostics_;
};

}  // namespace oasis::hw::yaml_schema
