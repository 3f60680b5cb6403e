// The helpers of schema_reader.hpp that need no template.

#include "settings/schema_reader.hpp"

#include <cerrno>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <sstream>

namespace oasis::hw::settings::detail {

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
    case YAML::NodeType::Sequence:
      return "a list";
    case YAML::NodeType::Map:
      return "a mapping";
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

std::string read_yaml_file(const std::filesystem::path& file) {
  const std::string name = file.string();
  std::error_code ignored;
  if (!std::filesystem::exists(file, ignored))
    throw SettingsError(name, {{0, 0, "", "no such settings file", {}}});
  if (std::filesystem::is_directory(file, ignored))
    throw SettingsError(name, {{0, 0, "", "is a directory, not a settings file", {}}});
  // A FIFO nobody writes to would block the open below forever.
  if (!std::filesystem::is_regular_file(file, ignored))
    throw SettingsError(
        name,
        {{0, 0, "", "is not a regular file (a FIFO, socket or device), not a settings file", {}}});
  std::ifstream in(file, std::ios::binary);
  std::ostringstream text;
  if (in) text << in.rdbuf();
  if (!in || in.bad())
    throw SettingsError(
        name,
        {{0, 0, "", std::string("cannot read the settings file: ") + std::strerror(errno), {}}});
  return text.str();
}

}  // namespace oasis::hw::settings::detail
