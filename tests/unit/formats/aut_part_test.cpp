// formats::read_aut_part, which the distributed engine's ranks read their share of a file
// with: whatever the cut, the parts together hand over exactly the lines read_aut reads, each
// once, with the same values, and the actions' first offsets give read_aut's numbering.

#include <algorithm>
#include <map>
#include <random>
#include <sstream>
#include <string>
#include <tuple>
#include <vector>

#include <gtest/gtest.h>

#include "formats/aut_reader.hpp"

namespace oasis::formats {
namespace {

// One distribution as text, comparable across parts: source, action, reward, targets.
using Line = std::tuple<model::StateIndex, std::string, std::string, std::string>;

std::string row_text(const std::vector<std::pair<model::StateIndex, Rational>>& row) {
  std::string text;
  for (const auto& [target, probability] : row)
    text += std::to_string(target) + ":" + to_string(probability) + " ";
  return text;
}

// Every distribution of read_aut's model.
std::vector<Line> whole_file_lines(const model::ExplicitModel& model) {
  std::vector<Line> lines;
  const model::TransitionMatrix& matrix = *model.contexts[0].transitions;
  for (model::StateIndex s = 0; s < model.num_states(); ++s) {
    for (model::ActionIndex a = 0; a < model.num_actions(); ++a) {
      if (!matrix.enabled(s, a)) continue;
      std::vector<std::pair<model::StateIndex, Rational>> row;
      for (auto e = matrix.edges_begin(s, a); e < matrix.edges_end(s, a); ++e)
        row.emplace_back(matrix.edge_target[e], model.values[matrix.edge_probability[e]]);
      lines.emplace_back(s, model.actions[a], to_string(model.reward(0, s, a)), row_text(row));
    }
  }
  std::sort(lines.begin(), lines.end());
  return lines;
}

struct PartsRead {
  std::vector<Line> lines;
  std::uint64_t counted = 0;  // the parts' own counts of lines
  std::vector<std::string> actions_in_file_order;
  std::string diagnostics;
  bool ok = true;
};

PartsRead read_in_parts(const std::string& text, std::uint32_t count) {
  PartsRead result;
  std::map<SourceOffset, std::string> first_appearance;
  for (std::uint32_t index = 0; index < count; ++index) {
    SourceManager sources;
    std::ostringstream out;
    DiagnosticEngine diagnostics(sources, out);
    const FileId file = sources.add("x.aut", text);
    std::vector<Line> lines;
    std::vector<std::pair<model::StateIndex, ValueId>> rows;
    std::vector<std::tuple<model::StateIndex, model::ActionIndex, ValueId, std::size_t,
                           std::size_t>>
        seen;  // values are the part's: resolved once its pool is complete
    bool header_read = false;
    const auto part = read_aut_part(
        file, diagnostics, ReadOptions{}, index, count,
        [&](const AutLine& line) {
          seen.emplace_back(line.source, line.action, line.reward, rows.size(), line.row.size());
          rows.insert(rows.end(), line.row.begin(), line.row.end());
        },
        header_read);
    result.diagnostics += out.str();
    if (!part) {
      result.ok = false;
      continue;
    }
    result.counted += part->lines;
    for (std::size_t a = 0; a < part->actions.size(); ++a) {
      const auto [it, inserted] =
          first_appearance.try_emplace(part->action_offsets[a], part->actions[a]);
      EXPECT_TRUE(inserted || it->second == part->actions[a]);
    }
    for (const auto& [source, action, reward, first, size] : seen) {
      std::vector<std::pair<model::StateIndex, Rational>> row;
      for (std::size_t i = first; i < first + size; ++i)
        row.emplace_back(rows[i].first, part->values[rows[i].second]);
      result.lines.emplace_back(source, part->actions[action], to_string(part->values[reward]),
                                row_text(row));
    }
  }
  for (const auto& [offset, name] : first_appearance) {
    if (std::find(result.actions_in_file_order.begin(), result.actions_in_file_order.end(), name) ==
        result.actions_in_file_order.end())
      result.actions_in_file_order.push_back(name);
  }
  std::sort(result.lines.begin(), result.lines.end());
  return result;
}

// A valid .aut text with blank lines, CRLF endings, spaces, quoted and bare labels, rewards,
// repeated targets within a line and, sometimes, an end-of-text character at the end.
std::string random_aut(std::mt19937& random) {
  const auto pick = [&](int below) {
    return static_cast<int>(std::uniform_int_distribution<int>(0, below - 1)(random));
  };
  const int states = 1 + pick(12);
  // Per state at most one label of each action: go, stay and wait, with or without a reward.
  const std::vector<std::vector<std::string>> labels = {
      {"go", "\"go|reward(3/2)\""}, {"\"stay\""}, {"wait", "\"reward(-1)|wait\""}};
  std::vector<std::string> lines;
  for (int s = 0; s < states; ++s) {
    for (const std::vector<std::string>& choices : labels) {
      if (pick(3) == 0) continue;
      const std::string& label =
          choices[static_cast<std::size_t>(pick(static_cast<int>(choices.size())))];
      std::string line =
          "(" + std::string(pick(3) == 0 ? " " : "") + std::to_string(s) + "," + label + ",";
      const int targets = 1 + pick(3);
      for (int t = 0; t < targets; ++t) {
        line += std::to_string(pick(states));
        if (t + 1 < targets) line += " 1/" + std::to_string(targets + 1) + " ";
      }
      lines.push_back(line + ")");
    }
  }
  std::shuffle(lines.begin(), lines.end(), random);
  std::string text =
      "des (0," + std::to_string(lines.size()) + "," + std::to_string(states) + ")\n";
  for (const std::string& line : lines) {
    if (pick(6) == 0) text += pick(2) ? "\n" : "  \r\n";
    text += line + (pick(4) == 0 ? "\r\n" : "\n");
  }
  if (pick(5) == 0) {  // no line break at the end
    text.pop_back();
    if (text.back() == '\r') text.pop_back();
  }
  if (pick(5) == 0) text += text.back() == '\n' ? "\x04" : "\n\x04";  // EOT on a line of its own
  return text;
}

TEST(AutPart, PartsTogetherReadEveryLineOnceWhateverTheCut) {
  std::mt19937 random(20261127);
  for (int trial = 0; trial < 300; ++trial) {
    const std::string text = random_aut(random);
    SourceManager sources;
    std::ostringstream out;
    DiagnosticEngine diagnostics(sources, out);
    const auto whole = read_aut(sources.add("x.aut", text), diagnostics, ReadOptions{});
    ASSERT_TRUE(whole) << out.str() << "\n" << text;
    const std::vector<Line> expected = whole_file_lines(*whole);
    for (std::uint32_t count : {1U, 2U, 3U, 5U, 8U, 64U}) {
      const PartsRead parts = read_in_parts(text, count);
      ASSERT_TRUE(parts.ok) << parts.diagnostics;
      EXPECT_EQ(parts.diagnostics, "");
      EXPECT_EQ(parts.lines, expected) << count << " parts of\n" << text;
      EXPECT_EQ(parts.counted, expected.size());
      EXPECT_EQ(parts.actions_in_file_order, whole->actions) << count << " parts of\n" << text;
    }
  }
}

TEST(AutPart, AnErrorIsReportedByThePartThatHoldsItsLineOnly) {
  std::string text = "des (0,6,3)\n";
  for (int s = 0; s < 5; ++s)
    text += "(" + std::to_string(s % 3) + ",\"a" + std::to_string(s) + "\",1)\n";
  text += "(2,\"b\",1 3/2 0)\n";  // the last line: in the last part whatever the count
  for (std::uint32_t count : {1U, 2U, 4U}) {
    std::size_t reports = 0;
    for (std::uint32_t index = 0; index < count; ++index) {
      SourceManager sources;
      std::ostringstream out;
      DiagnosticEngine diagnostics(sources, out);
      bool header_read = false;
      const auto part = read_aut_part(
          sources.add("x.aut", text), diagnostics, ReadOptions{}, index, count,
          [](const AutLine&) {}, header_read);
      EXPECT_TRUE(header_read);
      EXPECT_EQ(part.has_value(), index + 1 < count);
      if (out.str().find("x.aut:7:") != std::string::npos) ++reports;
    }
    EXPECT_EQ(reports, 1U) << count << " parts";
  }
}

TEST(AutPart, AHeaderErrorSaysTheHeaderWasNotRead) {
  SourceManager sources;
  std::ostringstream out;
  DiagnosticEngine diagnostics(sources, out);
  bool header_read = true;
  const auto part = read_aut_part(
      sources.add("x.aut", "des (0,1)\n(0,a,0)\n"), diagnostics, ReadOptions{}, 1, 2,
      [](const AutLine&) {}, header_read);
  EXPECT_FALSE(part);
  EXPECT_FALSE(header_read);
}

// Issue 41: the memory budget is each rank's, and a rank holds about 1/P of the model: a
// header that 4 ranks cannot hold within 1 GiB each is refused, naming the option and the way
// out; 64 ranks hold it.
TEST(AutPart, TheMemoryBudgetIsPerRank) {
  const std::string text = "des (0,1000000000,100000000)\n(0,\"a\",1)\n";
  ReadOptions options;
  options.memory_budget = std::uint64_t{1} << 30;
  const auto read_first_part = [&](std::uint32_t count, std::string& messages) {
    SourceManager sources;
    std::ostringstream out;
    DiagnosticEngine diagnostics(sources, out);
    bool header_read = false;
    const auto part = read_aut_part(
        sources.add("x.aut", text), diagnostics, options, 0, count, [](const AutLine&) {},
        header_read);
    messages = out.str();
    return part.has_value();
  };
  std::string messages;
  EXPECT_FALSE(read_first_part(4, messages));
  // A rank's share: 2.5e8 lines of 16 + 8 bytes and 2.5e7 states of 4.
  EXPECT_NE(messages.find("x.aut:1:8: error: the header declares 1000000000 transitions and "
                          "100000000 states: reading it takes at least 5.7 GiB on the largest "
                          "of 4 ranks, more than the memory budget of 1.0 GiB per rank (raise "
                          "it with --memory-budget, or run on more ranks)"),
            std::string::npos)
      << messages;
  EXPECT_TRUE(read_first_part(64, messages)) << messages;
}

}  // namespace
}  // namespace oasis::formats
