// The schema reader shared by every YAML file of hw/ (the oasis-go1 settings, the controller
// profiles, the hallway scenario of hw/sim): yaml-cpp builds the node tree, the Reader visitor
// walks a schema's describe() over it, and every problem becomes a Diagnostic at the node's
// line and column. A schema is a function template describe(visitor, values) calling
// section() and value(); a schema with entries of its own kind (the Go1 settings' colour bands
// and action table) reads them with visitors derived from KeyLister and Reader, which it
// passes to parse_with_schema() (hw/settings/settings_visitors.hpp).
#pragma once

#include <algorithm>
#include <filesystem>
#include <map>
#include <optional>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include <yaml-cpp/depthguard.h>  // YAML::DeepRecursion: yaml.h does not include it
#include <yaml-cpp/yaml.h>

#include "yaml_schema/codecs.hpp"
#include "yaml_schema/cross_problem.hpp"
#include "yaml_schema/settings_error.hpp"
#include "yaml_schema/suggest.hpp"

namespace oasis::hw::yaml_schema {

std::vector<std::string> split_lines(std::string_view text);
std::string in_quotes(std::string_view text);
std::string what_node_is(const YAML::Node& node);
std::string join(const std::vector<std::string>& words);
Diagnostic at_mark(const YAML::Mark& mark, const std::vector<std::string>& lines,
                   std::string message);

// The text of a YAML file. Throws SettingsError (no such file, a directory, unreadable).
std::string read_yaml_file(const std::filesystem::path& file);

// Every section and key path of the schema ("robot", "robot.port", ...), for telling a user
// that a key they put in the wrong section belongs in another.
class KeyLister {
 public:
  template <class Body>
  void section(std::string_view key, std::string_view, Body&& body) {
    add(key);
    prefix_.push_back(std::string(key));
    body();
    prefix_.pop_back();
  }
  template <class T, class Codec>
  void value(std::string_view key, const T&, const Codec&, std::string_view) {
    add(key);
  }

  std::vector<std::string> paths;

 protected:
  void add(std::string_view key) {
    std::string path;
    for (const std::string& part : prefix_)
      path += part + ".";
    paths.push_back(path + std::string(key));
  }

 private:
  std::vector<std::string> prefix_;
};

// Every key path of a schema: `describe(lister)` walks it.
template <class Lister = KeyLister, class Describe>
std::vector<std::string> schema_paths(Describe&& describe) {
  Lister lister;
  describe(lister);
  return lister.paths;
}

class Reader {
 public:
  struct Entry {
    std::string key;
    YAML::Mark key_mark;
    YAML::Node value;
  };

  // `moved`: keys that earlier versions had, by dotted path, and where they went; such a key
  // is an error that says so.
  Reader(std::string_view text, std::vector<std::string> schema_paths,
         std::vector<std::pair<std::string, std::string>> moved = {})
      : lines_(split_lines(text)),
        schema_paths_(std::move(schema_paths)),
        moved_(std::move(moved)) {}

  // `describe()` walks the schema with this reader (or the visitor derived from it) as the
  // visitor; `sections` lists the top-level keys for the message when the file is not a
  // mapping ("robot:, limits:, ...").
  template <class Describe>
  void read(const YAML::Node& root, Describe&& describe, std::string_view sections) {
    if (!root.IsMap()) {
      error(root.Mark(), "",
            "expected a mapping of sections (" + std::string(sections) + "), got " +
                what_node_is(root));
      return;
    }
    if (!open("", root)) return;
    describe();
    close();
  }

  // ---- the schema visitor ----

  template <class Body>
  void section(std::string_view key, std::string_view, Body&& body) {
    const std::optional<Entry> entry = take(key);
    if (!entry) return;
    // "robot:" with every key commented out is an empty section, not an error.
    if (!open(path_of(key), entry->value, /*null_is_empty=*/true)) return;
    body();
    close();
  }

  template <class T, class Codec>
  void value(std::string_view key, T& field, const Codec& codec, std::string_view) {
    const std::optional<Entry> entry = take(key);
    if (entry) read_scalar(path_of(key), *entry, field, codec);
  }

  // ---- results ----

  // Reports a cross-key problem at whichever of its two keys the file wrote.
  void report(const CrossProblem& problem) {
    for (const std::string* key : {&problem.key, &problem.other_key}) {
      const auto mark = marks_.find(*key);
      if (mark == marks_.end()) continue;
      error(mark->second, problem.key, problem.message);
      return;
    }
    error(YAML::Mark::null_mark(), problem.key, problem.message);
  }

  const std::vector<Diagnostic>& diagnostics() const { return diagnostics_; }

 protected:
  // For the visitors derived from this one: the entries of the mapping being read, taken by
  // key, and where to report.
  struct Frame {
    std::string path;
    std::vector<Entry> entries;
    std::vector<std::string> known;  // the keys the schema asked for here
  };

  std::string path_of(std::string_view key) const {
    const std::string& parent = frames_.back().path;
    return parent.empty() ? std::string(key) : parent + "." + std::string(key);
  }

  // Where to point at a value: the value itself, or its key when there is no value.
  static YAML::Mark at(const Entry& entry) {
    if (entry.value.IsNull() || entry.value.Mark().is_null()) return entry.key_mark;
    return entry.value.Mark();
  }

  void error(const YAML::Mark& mark, std::string key, std::string message) {
    Diagnostic diagnostic{0, 0, std::move(key), std::move(message), {}};
    if (!mark.is_null()) {
      diagnostic.line = mark.line + 1;
      diagnostic.column = mark.column + 1;
      if (static_cast<std::size_t>(mark.line) < lines_.size())
        diagnostic.source_line = lines_[static_cast<std::size_t>(mark.line)];
    }
    diagnostics_.push_back(std::move(diagnostic));
  }

  // Enters a mapping; false (and an error) if `node` is not one.
  bool open(std::string path, const YAML::Node& node, bool null_is_empty = false) {
    if (!node.IsMap() && !(null_is_empty && node.IsNull())) {
      error(node.Mark().is_null() ? YAML::Mark() : node.Mark(), path,
            "expected a mapping, got " + what_node_is(node));
      return false;
    }
    Frame frame{std::move(path), {}, {}};
    std::map<std::string, int> first_line;
    if (node.IsMap()) {
      for (const auto& pair : node) {
        const YAML::Node& key = pair.first;
        const std::string key_path = frame.path.empty() ? "" : frame.path + ".";
        if (!key.IsScalar()) {
          error(key.Mark(), frame.path, "expected a key name, got " + what_node_is(key));
          continue;
        }
        const auto [previous, inserted] = first_line.emplace(key.Scalar(), key.Mark().line + 1);
        if (!inserted) {
          error(key.Mark(), key_path + key.Scalar(),
                "listed twice (first at line " + std::to_string(previous->second) + ")");
          continue;
        }
        frame.entries.push_back({key.Scalar(), key.Mark(), pair.second});
      }
    }
    frames_.push_back(std::move(frame));
    return true;
  }

  // Leaves the current mapping, reporting every key the schema did not ask for.
  void close() {
    const Frame& frame = frames_.back();
    for (const Entry& entry : frame.entries) {
      if (std::find(frame.known.begin(), frame.known.end(), entry.key) != frame.known.end())
        continue;
      const std::string path = frame.path.empty() ? entry.key : frame.path + "." + entry.key;
      error(entry.key_mark, path, unknown_key_message(frame, entry.key));
    }
    frames_.pop_back();
  }

  std::string unknown_key_message(const Frame& frame, const std::string& key) const {
    const std::string dotted = frame.path.empty() ? key : frame.path + "." + key;
    for (const auto& [old_path, where_now] : moved_)
      if (old_path == dotted) return "no longer a key here: " + where_now;
    if (const auto close = closest_candidate(key, frame.known))
      return "unknown key; did you mean \"" + *close + "\"?";
    for (const std::string& path : schema_paths_) {
      const std::size_t dot = path.rfind('.');
      const std::string leaf = dot == std::string::npos ? path : path.substr(dot + 1);
      const std::string parent = dot == std::string::npos ? "" : path.substr(0, dot);
      if (leaf == key && parent != frame.path)
        return "unknown key here; it belongs in " + (parent.empty() ? "the top level" : parent) +
               " (" + path + ")";
    }
    const std::string where = frame.path.empty() ? "the file" : frame.path;
    return "unknown key; " + where + " takes " + join(frame.known);
  }

  std::optional<Entry> take(std::string_view key) {
    Frame& frame = frames_.back();
    frame.known.push_back(std::string(key));
    for (const Entry& entry : frame.entries) {
      if (entry.key != key) continue;
      marks_[path_of(key)] = at(entry);
      return entry;
    }
    return std::nullopt;
  }

  // For a mapping whose keys are data (actions:): every key is accepted.
  std::vector<Entry> accept_every_key() {
    Frame& frame = frames_.back();
    for (const Entry& entry : frame.entries) {
      frame.known.push_back(entry.key);
      marks_[path_of(entry.key)] = entry.key_mark;
    }
    return frame.entries;
  }

  template <class T, class Codec>
  bool read_scalar(const std::string& path, const Entry& entry, T& field, const Codec& codec) {
    const YAML::Node& node = entry.value;
    if (node.IsScalar()) {
      T parsed = field;
      if (codec.parse(node.Scalar(), parsed)) {
        field = std::move(parsed);
        return true;
      }
    }
    std::string message = "expected " + codec.expected() + ", got " + what_node_is(node);
    if constexpr (requires { codec.spellings(); }) {
      if (node.IsScalar())
        if (const auto close = closest_candidate(node.Scalar(), codec.spellings()))
          message += "; did you mean \"" + *close + "\"?";
    }
    error(at(entry), path, std::move(message));
    return false;
  }

 private:
  std::vector<std::string> lines_;
  std::vector<std::string> schema_paths_;
  std::vector<std::pair<std::string, std::string>> moved_;
  std::vector<Frame> frames_;
  std::map<std::string, YAML::Mark> marks_;  // path -> where the file wrote it
  std::vector<Diagnostic> diagnostics_;
};

// The 0-based line of a document marker ("---" at the start of a line) that follows content,
// i.e. starts a second document; nothing if there is none. Comments and blank lines are not
// content, so a file may open with "---".
inline std::optional<std::size_t> second_document_line(std::string_view yaml_text) {
  const std::vector<std::string> lines = split_lines(yaml_text);
  bool content = false;
  for (std::size_t k = 0; k < lines.size(); ++k) {
    const std::string& line = lines[k];
    const bool marker = line.rfind("---", 0) == 0 &&
                        (line.size() == 3 || line[3] == ' ' || line[3] == '\t' || line[3] == '\r');
    if (marker && content) return k;
    const std::size_t first = line.find_first_not_of(" \t\r");
    if (!marker && first != std::string::npos && line[first] != '#') content = true;
  }
  return std::nullopt;
}

// The visitors a plain schema is read with; a schema with entries of its own kind passes a
// struct naming visitors derived from these.
struct PlainVisitors {
  using Lister = KeyLister;
  using Reader = yaml_schema::Reader;
};

// Parses `yaml_text` into `values` (which start as the defaults) through the schema.
// `cross_check(values)` returns the CrossProblems between keys; it runs only when every key is
// valid on its own, since a failed key's default would only add confusing follow-up errors.
// Throws SettingsError with every problem found.
// `moved` lists keys of earlier versions and where they went (see Reader).
template <class Visitors = PlainVisitors, class Values, class Describe, class CrossCheck>
void parse_with_schema(std::string_view yaml_text, std::string_view file_name, Values& values,
                       Describe&& describe, CrossCheck&& cross_check, std::string_view sections,
                       std::vector<std::pair<std::string, std::string>> moved = {}) {
  const std::string file(file_name);
  // Not YAML::LoadAll: Debian 12's yaml-cpp 0.7.0 loops forever, allocating, on a stray comma
  // (upstream jbeder/yaml-cpp#1040; found by tests/fuzz/settings_fuzz.cpp). YAML::Load reads the
  // first document, and a second one is found by its "---" line.
  if (const auto second = second_document_line(yaml_text))
    throw SettingsError(file, {{static_cast<int>(*second) + 1, 1, "",
                                "a second YAML document; the settings are one mapping",
                                split_lines(yaml_text)[*second]}});
  YAML::Node document;
  try {
    document = YAML::Load(std::string(yaml_text));
  } catch (const YAML::DeepRecursion& e) {
    // yaml-cpp's own text for this is "bad file", and its mark points past the nesting (at the
    // end of what it scanned ahead), so the error names the file only.
    throw SettingsError(file, {{0,
                                0,
                                "",
                                "invalid YAML: nested " + std::to_string(e.depth()) +
                                    " levels deep, past what the YAML reader allows; settings "
                                    "are a few levels deep",
                                {}}});
  } catch (const YAML::Exception& e) {
    throw SettingsError(file, {at_mark(e.mark, split_lines(yaml_text), "invalid YAML: " + e.msg)});
  }
  if (!document.IsDefined() || document.IsNull())
    throw SettingsError(file, {{0,
                                0,
                                "",
                                "the file holds no settings; expected a mapping of sections (" +
                                    std::string(sections) + "); write {} to keep every default",
                                {}}});

  const Values defaults = values;
  typename Visitors::Reader reader(
      yaml_text,
      schema_paths<typename Visitors::Lister>([&](auto& lister) { describe(lister, defaults); }),
      std::move(moved));
  reader.read(
      document, [&] { describe(reader, values); }, sections);
  if (reader.diagnostics().empty())
    for (const CrossProblem& problem : cross_check(values))
      reader.report(problem);
  if (!reader.diagnostics().empty()) throw SettingsError(file, reader.diagnostics());
}

}  // namespace oasis::hw::yaml_schema
