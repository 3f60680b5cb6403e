// The helpers of schema_reader.hpp that need no template.

#include "yaml_schema/schema_reader.hpp"

#include <cstddef>
#include <filesystem>
#include <optional>
#include <utility>

#include "files/input_file.hpp"

namespace oasis::hw::yaml_schema {

std::vector<std::string> split_lines(std::string_view text) {
  std::vector<std::string> lines;
  std::size_t start = 0;
  while (start <= text.size()) {
    std::size_t end = text.find('\n', start);
    if (end == std::string_view::npos) end = text.size();
    std::string line(text.substr(start, end - start));
    if (!line.empty() && line.back() == '\r') line.pop_back();
    lines.push_back(std::move(line));
    start = end + 1;
  }
  return lines;
}

std::string in_quotes(std::string_view text) {
  constexpr std::size_t kShown = 60;
  std::string shown(text.substr(0, kShown));
  if (text.size() > kShown) shown += "...";
  return "\"" + shown + "\"";
}

std::string what_node_is(const YAML::Node& node) {
  switch (node.Type()) {
    // "got a list" after "expected a list of ..." would read as a contradiction: say what is off.
    case YAML::NodeType::Sequence:
      return node.size() == 0 ? "an empty list" : "a list";
    case YAML::NodeType::Map:
      return node.size() == 0 ? "an empty mapping" : "a mapping";
    case YAML::NodeType::Scalar:
      return in_quotes(node.Scalar());
    default:
      return "nothing";
  }
}

std::string join(const std::vector<std::string>& words) {
  std::string text;
  for (const std::string& word : words)
    text += (text.empty() ? "" : ", ") + word;
  return text;
}

Diagnostic at_mark(const YAML::Mark& mark, const std::vector<std::string>& lines,
                   std::string message) {
  Diagnostic diagnostic{0, 0, "", std::move(message), {}};
  if (mark.is_null()) return diagnostic;
  diagnostic.line = mark.line + 1;
  diagnostic.column = mark.column + 1;
  if (static_cast<std::size_t>(mark.line) < lines.size())
    diagnostic.source_line = lines[static_cast<std::size_t>(mark.line)];
  return diagnostic;
}

namespace {
// Settings, scenarios and profiles are written by hand: past this it is the wrong file.
constexpr std::size_t kMaxSettingsBytes = std::size_t{16} << 20;
}  // namespace

std::string read_yaml_file(const std::filesystem::path& file) {
  const std::string name = file.string();
  std::error_code ignored;
  if (!std::filesystem::exists(file, ignored))
    throw SettingsError(name, {{0, 0, "", "no such settings file", {}}});
  // The readers' one rule (common/files/input_file.hpp): a directory or device is refused, and
  // a pipe nobody writes to too, after its grace period (`--config <(...)` works).
  std::string reason;
  std::optional<std::string> text = files::read_input(name, kMaxSettingsBytes, reason);
  if (!text) throw SettingsError(name, {{0, 0, "", reason + ", not a settings file", {}}});
  return std::move(*text);
}

}  // namespace oasis::hw::yaml_schema
