// The schema writer shared by every YAML file of hw/: the Writer visitor prints every key of a
// schema's describe() with its value and comment, sections as nested mappings, top-level items
// separated by blank lines. Files written by it are read back by schema_reader.hpp. A schema
// with entries of its own kind writes them with a visitor derived from this one.
#pragma once

#include <algorithm>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "yaml_schema/codecs.hpp"

namespace oasis::hw::yaml_schema {

// Comments start in this column (0-based) unless the text is longer.
constexpr std::size_t kCommentColumn = 40;

class Writer {
 public:
  // `banner`: the comment lines that open the file, each ending in a newline.
  explicit Writer(std::string banner) : banner_(std::move(banner)) {}

  template <class Body>
  void section(std::string_view key, std::string_view comment, Body&& body) {
    begin_item();
    comment_block(comment);
    add(std::string(key) + ":", "");
    nested(body);
  }

  template <class T, class Codec>
  void value(std::string_view key, const T& field, const Codec& codec, std::string_view comment) {
    begin_item();
    add(std::string(key) + ": " + codec.format(field), comment);
  }

  std::string text() const {
    std::string out(banner_);
    for (const Line& line : lines_) {
      std::string row = line.text;
      if (!line.comment.empty()) {
        row.resize(std::max(row.size() + 2, kCommentColumn), ' ');
        row += "# " + line.comment;
      }
      out += row + "\n";
    }
    return out;
  }

 protected:
  // Top-level items are separated by a blank line.
  void begin_item() {
    if (depth_ == 0) lines_.push_back({"", ""});
  }

  void comment_block(std::string_view comment) {
    while (!comment.empty()) {
      const std::size_t end = std::min(comment.find('\n'), comment.size());
      lines_.push_back({indent() + "# " + std::string(comment.substr(0, end)), ""});
      comment.remove_prefix(std::min(end + 1, comment.size()));
    }
  }

  void add(std::string text, std::string_view comment) {
    lines_.push_back({indent() + std::move(text), std::string(comment)});
  }

  // Writes what `body()` adds one level deeper.
  template <class Body>
  void nested(Body&& body) {
    ++depth_;
    body();
    --depth_;
  }

 private:
  struct Line {
    std::string text;
    std::string comment;
  };

  std::string indent() const { return std::string(2 * depth_, ' '); }

  std::string banner_;
  std::vector<Line> lines_;
  std::size_t depth_ = 0;
};

}  // namespace oasis::hw::yaml_schema
