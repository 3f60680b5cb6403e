// The schema writer shared by every YAML file of hw/: the Writer visitor prints every key of a
// schema's describe() with its value and comment, sections as nested mappings, top-level items
// separated by blank lines. Files written by it are read back by schema_reader.hpp.
#pragma once

#include <algorithm>
#include <cmath>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "settings/codecs.hpp"

namespace oasis::hw::settings::detail {

// Comments start in this column (0-based) unless the text is longer.
constexpr std::size_t kCommentColumn = 40;

inline std::string channel_text(double value) {
  if (value == std::floor(value) && std::fabs(value) < 1e9)
    return std::to_string(static_cast<long long>(value));
  return format_real(value);
}

inline std::string hsv_text(const cv::Scalar& hsv) {
  return "[" + channel_text(hsv[0]) + ", " + channel_text(hsv[1]) + ", " + channel_text(hsv[2]) +
         "]";
}

class Writer {
 public:
  // `banner`: the comment lines that open the file, each ending in a newline.
  explicit Writer(std::string banner) : banner_(std::move(banner)) {}

  template <class Body>
  void section(std::string_view key, std::string_view comment, Body&& body) {
    begin_item();
    comment_block(comment);
    add(std::string(key) + ":", "");
    ++depth_;
    body();
    --depth_;
  }

  template <class T, class Codec>
  void value(std::string_view key, const T& field, const Codec& codec, std::string_view comment) {
    begin_item();
    add(std::string(key) + ": " + codec.format(field), comment);
  }

  void bands(std::string_view key, const std::vector<HsvBand>& bands, std::string_view comment) {
    add(std::string(key) + ":", comment);
    ++depth_;
    for (const HsvBand& band : bands)
      add("- {low: " + hsv_text(band.low) + ", high: " + hsv_text(band.high) + "}", "");
    --depth_;
  }

  void actions(std::string_view key, const std::vector<ActionVelocity>& actions,
               std::string_view comment) {
    begin_item();
    comment_block(comment);
    add(std::string(key) + ":", "");
    std::size_t width = 0;
    for (const ActionVelocity& entry : actions)
      width = std::max(width, yaml_string(entry.action).size());
    ++depth_;
    for (const ActionVelocity& entry : actions) {
      std::string name = yaml_string(entry.action) + ":";
      name.resize(width + 1, ' ');
      const go1::VelocityCommand& v = entry.velocity;
      add(name + " {forward: " + format_real(v.forward) + ", lateral: " + format_real(v.lateral) +
              ", yaw_rate: " + format_real(v.yaw_rate) + "}",
          "");
    }
    --depth_;
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

 private:
  struct Line {
    std::string text;
    std::string comment;
  };

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

  std::string indent() const { return std::string(2 * depth_, ' '); }

  std::string banner_;
  std::vector<Line> lines_;
  std::size_t depth_ = 0;
};

}  // namespace oasis::hw::settings::detail
