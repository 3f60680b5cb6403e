// UMB, the binary format of PRISM 4.10 and Storm: a file laid out as its specification says
// (built here byte by byte: a plain tar, doubles, an action table with the empty string and an
// unused name, a 256-bit rational, parts we do not read) is read with its labels, rewards and
// choice names; bad input gets an error naming its entry; read -> write -> read gives the same
// model and write -> read -> write the same bytes.

#include <bit>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>
#include <string>
#include <vector>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "../../support/scratch_directory.hpp"
#include "formats/drn_reader.hpp"
#include "formats/model_file.hpp"
#include "formats/umb_reader.hpp"
#include "formats/umb_writer.hpp"
#include "prism/load_program.hpp"

namespace oasis::formats {
namespace {

using model::ExplicitModel;
using Json = nlohmann::ordered_json;

// --- A UMB file by hand ----------------------------------------------------------------

std::string octal(std::uint64_t value, std::size_t digits) {
  std::string text(digits, '0');
  for (std::size_t i = digits; i-- > 0; value /= 8)
    text[i] = static_cast<char>('0' + value % 8);
  return text;
}

// A POSIX (ustar) tar of `entries`, uncompressed, as the format allows.
std::string tar(const std::vector<std::pair<std::string, std::string>>& entries) {
  std::string out;
  for (const auto& [name, bytes] : entries) {
    std::string header(512, '\0');
    header.replace(0, name.size(), name);
    header.replace(100, 7, "0000644");
    header.replace(108, 7, "0000000");
    header.replace(116, 7, "0000000");
    header.replace(124, 11, octal(bytes.size(), 11));
    header.replace(136, 11, octal(0, 11));
    header.replace(148, 8, "        ");
    header[156] = '0';
    header.replace(257, 6, std::string("ustar\0", 6));
    header.replace(263, 2, "00");
    unsigned sum = 0;
    for (const char c : header)
      sum += static_cast<unsigned char>(c);
    header.replace(148, 7, octal(sum, 6) + std::string(1, '\0'));
    out += header;
    out += bytes;
    out.append((512 - bytes.size() % 512) % 512, '\0');
  }
  out.append(1024, '\0');
  return out;
}

std::string u64s(const std::vector<std::uint64_t>& values) {
  std::string out;
  for (const std::uint64_t v : values) {
    for (int b = 0; b < 8; ++b)
      out.push_back(static_cast<char>((v >> (8 * b)) & 0xff));
  }
  return out;
}
std::string u32s(const std::vector<std::uint32_t>& values) {
  std::string out;
  for (const std::uint32_t v : values) {
    for (int b = 0; b < 4; ++b)
      out.push_back(static_cast<char>((v >> (8 * b)) & 0xff));
  }
  return out;
}
std::string doubles(const std::vector<double>& values) {
  std::vector<std::uint64_t> raw;
  for (const double v : values)
    raw.push_back(std::bit_cast<std::uint64_t>(v));
  return u64s(raw);
}
// A 256-bit rational: 128-bit two's-complement numerator, then 128-bit denominator.
std::string rational256(std::int64_t numerator, std::uint64_t denominator) {
  const auto n = static_cast<std::uint64_t>(numerator);
  return u64s({n, numerator < 0 ? ~std::uint64_t{0} : 0, denominator, 0});
}

// An MDP as PRISM or Storm would export it, by the specification's rules:
//   state 0: go -> 1: 0.2, 2: 0.8;  (unlabelled) -> 0: 1
//   state 1: stay -> 1: 1
//   state 2: go -> 0: 0.3, 2: 0.7
// "steps": choice rewards (doubles); "cost": state rewards (256-bit rationals, one negative);
// the label "the goal" on state 1; state 0 initial; valuations and an unknown annotation group
// that the reader reads past.
struct HandMade {
  Json index = Json::parse(R"({
    "format-version": 1, "format-revision": 0,
    "model-data": {"name": "hand"},
    "file-data": {"tool": "by hand", "creation-date": 1770000000},
    "transition-system": {
      "time": "discrete", "#players": 1, "#states": 3, "#initial-states": 1, "#choices": 4,
      "#choice-actions": 4, "#branches": 6, "#branch-actions": 0, "#observations": 0,
      "branch-probability-type": {"type": "double", "size": 64}},
    "annotations": {
      "rewards": {
        "steps": {"alias": "steps", "applies-to": ["choices"], "type": {"type": "double"}},
        "cost": {"applies-to": ["states"], "type": {"type": "rational", "size": 256}}},
      "aps": {"goal": {"alias": "the goal", "applies-to": ["states"],
                       "type": {"type": "bool", "size": 1}}},
      "colours": {"red": {"applies-to": ["states"], "type": {"type": "uint", "size": 8}}}},
    "valuations": {"states": {"unique": true, "classes": [{"variables": [
      {"name": "x", "type": {"type": "uint", "size": 2}}, {"padding": 6}]}]}}
  })");
  std::map<std::string, std::string> files = {
      {"state-to-choices.bin", u64s({0, 2, 3, 4})},
      {"choice-to-branches.bin", u64s({0, 2, 3, 4, 6})},
      {"branch-to-target.bin", u64s({1, 2, 0, 1, 0, 2})},
      {"branch-to-probability.bin", doubles({0.2, 0.8, 1.0, 1.0, 0.3, 0.7})},
      {"state-is-initial.bin", u64s({1})},
      {"actions/choices/values.bin", u32s({1, 0, 2, 1})},
      {"actions/choices/string-mapping.bin", u64s({0, 0, 2, 6, 12})},
      {"actions/choices/strings.bin", "gostayunused"},
      {"annotations/rewards/steps/choices/values.bin", doubles({1.5, 0, 0, 0.25})},
      {"annotations/rewards/cost/states/values.bin",
       rational256(-1, 3) + rational256(0, 1) + rational256(2, 1)},
      {"annotations/aps/goal/states/values.bin", u64s({2})},
      {"annotations/colours/red/states/values.bin", std::string("\1\2\3", 3)},
      {"valuations/states/valuations.bin", std::string("\0\1\2", 3)},
  };

  [[nodiscard]] std::string bytes() const {
    std::vector<std::pair<std::string, std::string>> entries = {{"index.json", index.dump(2)}};
    for (const auto& [name, content] : files)
      entries.emplace_back(name, content);
    return tar(entries);
  }
};

struct Read {
  std::optional<ExplicitModel> model;
  std::string messages;
};

Read read_bytes(const std::string& bytes, const ReadOptions& options = {}) {
  SourceManager sources;
  std::ostringstream out;
  DiagnosticEngine diagnostics(sources, out);
  const FileId file = sources.add("x.umb", bytes);
  Read result;
  result.model = read_umb(file, diagnostics, options);
  result.messages = out.str();
  return result;
}

model::ActionIndex action_named(const ExplicitModel& m, const std::string& name) {
  return static_cast<model::ActionIndex>(std::find(m.actions.begin(), m.actions.end(), name) -
                                         m.actions.begin());
}

std::map<model::StateIndex, Rational> distribution(const ExplicitModel& m, model::StateIndex s,
                                                   const std::string& action) {
  std::map<model::StateIndex, Rational> result;
  const model::ActionIndex a = action_named(m, action);
  if (a == m.num_actions()) return result;
  const model::TransitionMatrix& t = *m.contexts.at(0).transitions;
  for (auto e = t.edges_begin(s, a); e < t.edges_end(s, a); ++e)
    result[t.edge_target[e]] = m.values[t.edge_probability[e]];
  return result;
}

std::vector<std::string> labels_of(const ExplicitModel& m, model::StateIndex s) {
  std::vector<std::string> names;
  for (const std::uint32_t l : m.labels.of(s))
    names.push_back(m.labels.names[l]);
  std::sort(names.begin(), names.end());
  return names;
}

TEST(Umb, ReadsAFileLaidOutAsTheSpecificationSays) {
  const Read read = read_bytes(HandMade{}.bytes());
  ASSERT_TRUE(read.model) << read.messages;
  EXPECT_EQ(read.messages, "");
  const ExplicitModel& m = *read.model;
  EXPECT_EQ(m.type, model::ModelType::kMdp);
  EXPECT_EQ(m.num_states(), 3U);
  EXPECT_EQ(m.actions, (std::vector<std::string>{"go", "[1]", "stay"}));
  EXPECT_EQ(m.states.initial, std::vector<model::StateIndex>{0});
  EXPECT_EQ(labels_of(m, 0), std::vector<std::string>{"init"});
  EXPECT_EQ(labels_of(m, 1), std::vector<std::string>{"the goal"});
  // Doubles are read as the decimals they print as: 0.2 is 1/5, and 0.3 + 0.7 is exactly 1.
  EXPECT_EQ(distribution(m, 0, "go"),
            (std::map<model::StateIndex, Rational>{{1, Rational(1, 5)}, {2, Rational(4, 5)}}));
  EXPECT_EQ(distribution(m, 0, "[1]"), (std::map<model::StateIndex, Rational>{{0, 1}}));
  EXPECT_EQ(distribution(m, 2, "go"),
            (std::map<model::StateIndex, Rational>{{0, Rational(3, 10)}, {2, Rational(7, 10)}}));
  ASSERT_EQ(m.contexts.size(), 2U);
  EXPECT_EQ(m.contexts[0].name, "steps");
  EXPECT_EQ(m.contexts[1].name, "cost");  // no alias: the identifier
  const model::ActionIndex go = action_named(m, "go");
  EXPECT_EQ(m.reward(0, 0, go), Rational(3, 2));
  EXPECT_EQ(m.reward(0, 2, go), Rational(1, 4));
  EXPECT_EQ(m.reward(1, 0, go), Rational(-1, 3));
  EXPECT_EQ(m.reward(1, 2, go), 2);
  EXPECT_EQ(m.contexts[0].transitions, m.contexts[1].transitions);
  EXPECT_FALSE(model::find_structural_problem(m));
  // The valuations: x in the 2 low bits, 6 bits of padding.
  EXPECT_EQ(m.states.variables, std::vector<std::string>{"x"});
  EXPECT_EQ(m.states.valuations, (std::vector<std::int64_t>{0, 1, 2}));
}

TEST(Umb, ValuationsOfAnotherFormAreReadPastWithAWarning) {
  HandMade file;
  file.index["valuations"]["states"]["classes"][0]["variables"][0]["type"]["type"] = "string";
  Read read = read_bytes(file.bytes());
  ASSERT_TRUE(read.model) << read.messages;
  EXPECT_TRUE(read.model->states.variables.empty());
  EXPECT_NE(read.messages.find("x.umb: warning: the state valuations are read past: variable "
                               "'x' is of type 'string'"),
            std::string::npos)
      << read.messages;

  // Signed, offset and Boolean fields: y = -1 (int 3 bits) + 10, b (bool).
  file = HandMade{};
  file.index["valuations"]["states"]["classes"][0]["variables"] = Json::parse(
      R"([{"name": "y", "type": {"type": "int", "size": 3}, "offset": 10},
          {"name": "b", "type": {"type": "bool"}}, {"padding": 4}])");
  file.files["valuations/states/valuations.bin"] = std::string("", 3);
  read = read_bytes(file.bytes());
  ASSERT_TRUE(read.model) << read.messages;
  EXPECT_EQ(read.model->states.variables, (std::vector<std::string>{"y", "b"}));
  EXPECT_EQ(read.model->states.valuations, (std::vector<std::int64_t>{9, 0, 13, 1, 11, 0}));
}

// Issue 41: the index's counts beyond the memory budget are refused before any array of the
// model is built, naming the option.
TEST(Umb, AnIndexBeyondTheMemoryBudgetIsRefused) {
  HandMade file;
  file.index["transition-system"]["#states"] = 1000000000;
  file.index["transition-system"]["#choices"] = 4000000000U;
  file.index["transition-system"]["#branches"] = 4000000000U;
  ReadOptions options;
  options.memory_budget = std::uint64_t{1} << 30;
  const Read read = read_bytes(file.bytes(), options);
  EXPECT_FALSE(read.model);
  EXPECT_NE(read.messages.find("x.umb: error: index.json: transition-system: the index declares "
                               "1000000000 states, 4000000000 choices and 4000000000 branches: "
                               "reading it takes at least 122.9 GiB, more than the memory "
                               "budget of 1.0 GiB (raise it with --memory-budget)"),
            std::string::npos)
      << read.messages;
}

TEST(Umb, AMarkovChainHasTheOneActionOfTheOtherReaders) {
  HandMade file;
  file.index["transition-system"]["#players"] = 0;
  file.index["transition-system"]["#choices"] = 3;
  file.index["transition-system"]["#choice-actions"] = 0;
  file.index["transition-system"]["#branches"] = 4;
  file.index.erase("annotations");
  file.files = {{"choice-to-branches.bin", u64s({0, 2, 3, 4})},
                {"branch-to-target.bin", u64s({1, 2, 1, 2})},
                {"branch-to-probability.bin", doubles({0.5, 0.5, 1, 1})},
                {"state-is-initial.bin", u64s({1})}};
  const Read read = read_bytes(file.bytes());
  ASSERT_TRUE(read.model) << read.messages;
  EXPECT_EQ(read.model->type, model::ModelType::kDtmc);
  EXPECT_EQ(read.model->actions, std::vector<std::string>{"[0]"});
  ASSERT_EQ(read.model->contexts.size(), 1U);
  EXPECT_EQ(read.model->contexts[0].name, "default");
}

TEST(Umb, BranchRewardsThatAgreeWithinTheirChoiceAreTheChoicesReward) {
  HandMade file;
  file.index["annotations"]["rewards"]["steps"]["applies-to"] = Json::array({"branches"});
  file.files["annotations/rewards/steps/branches/values.bin"] = doubles({2, 2, 0, 0, 0.5, 0.5});
  file.files.erase("annotations/rewards/steps/choices/values.bin");
  Read read = read_bytes(file.bytes());
  ASSERT_TRUE(read.model) << read.messages;
  EXPECT_EQ(read.model->reward(0, 0, action_named(*read.model, "go")), 2);
  EXPECT_EQ(read.model->reward(0, 2, action_named(*read.model, "go")), Rational(1, 2));

  file.files["annotations/rewards/steps/branches/values.bin"] = doubles({2, 3, 0, 0, 0, 0});
  read = read_bytes(file.bytes());
  EXPECT_FALSE(read.model);
  EXPECT_NE(read.messages.find("x.umb: error: annotations/rewards/steps/branches/values.bin: "
                               "the branches of state 0, choice 0 have different rewards"),
            std::string::npos)
      << read.messages;
}

TEST(Umb, WithoutInitialStatesStateZeroIsInitialWithAWarning) {
  HandMade file;
  file.index["transition-system"]["#initial-states"] = 0;
  file.files.erase("state-is-initial.bin");
  const Read read = read_bytes(file.bytes());
  ASSERT_TRUE(read.model) << read.messages;
  EXPECT_EQ(read.model->states.initial, std::vector<model::StateIndex>{0});
  EXPECT_NE(read.messages.find("x.umb: warning: no state is initial; state 0 is the initial state"),
            std::string::npos)
      << read.messages;
}

// --- Bad input ---------------------------------------------------------------------------

struct ErrorCase {
  const char* name;
  void (*change)(HandMade&);
  const char* expected;
};

class UmbError : public ::testing::TestWithParam<ErrorCase> {};

TEST_P(UmbError, NamesTheEntryThatIsWrong) {
  HandMade file;
  GetParam().change(file);
  const Read read = read_bytes(file.bytes());
  EXPECT_FALSE(read.model);
  EXPECT_NE(read.messages.find(std::string("x.umb: error: ") + GetParam().expected),
            std::string::npos)
      << read.messages;
}

Json& ts(HandMade& f) {
  return f.index["transition-system"];
}

INSTANTIATE_TEST_SUITE_P(
    Errors, UmbError,
    ::testing::Values(
        ErrorCase{"not_an_object", [](HandMade& f) { f.index = nullptr; },
                  "index.json: is not a JSON object"},
        ErrorCase{"version", [](HandMade& f) { f.index["format-version"] = 2; },
                  "index.json: format version 2 is not supported: oasis reads version 1"},
        ErrorCase{"time", [](HandMade& f) { ts(f)["time"] = "stochastic"; },
                  "index.json: transition-system: time 'stochastic' is not supported"},
        ErrorCase{"players", [](HandMade& f) { ts(f)["#players"] = 2; },
                  "index.json: transition-system: a game of 2 players is not supported"},
        ErrorCase{"no_states", [](HandMade& f) { ts(f)["#states"] = 0; },
                  "index.json: transition-system: \"#states\" is 0: the model has no states"},
        ErrorCase{"many_states", [](HandMade& f) { ts(f)["#states"] = 1e12; },
                  "index.json: transition-system: \"#states\" is not a whole number"},
        ErrorCase{"observations", [](HandMade& f) { ts(f)["#observations"] = 3; },
                  "index.json: transition-system: observations are not supported"},
        ErrorCase{"lts", [](HandMade& f) { ts(f).erase("branch-probability-type"); },
                  "index.json: transition-system: there is no \"branch-probability-type\": a model "
                  "without probabilities"},
        ErrorCase{"interval",
                  [](HandMade& f) {
                    ts(f)["branch-probability-type"] = Json{{"type", "double-interval"}};
                  },
                  "index.json: transition-system: \"branch-probability-type\": values of type "
                  "'double-interval' are not supported"},
        ErrorCase{"rational_size",
                  [](HandMade& f) {
                    ts(f)["branch-probability-type"] = Json{{"type", "rational"}, {"size", 96}};
                  },
                  "index.json: transition-system: \"branch-probability-type\": a rational's size "
                  "must be a multiple of 128 bits, not 96"},
        ErrorCase{"ap_type",
                  [](HandMade& f) {
                    f.index["annotations"]["aps"]["goal"]["type"] = Json{{"type", "uint"}};
                  },
                  "index.json: annotations: \"aps\": \"goal\": an atomic proposition has the "
                  "type bool"},
        ErrorCase{"ap_quote",
                  [](HandMade& f) { f.index["annotations"]["aps"]["goal"]["alias"] = "a\"b"; },
                  "index.json: atomic proposition 'a\"b' holds a '\"'"},
        ErrorCase{"bad_id",
                  [](HandMade& f) {
                    f.index["annotations"]["rewards"]["Steps"] =
                        f.index["annotations"]["rewards"]["steps"];
                  },
                  "index.json: annotations: \"rewards\": \"Steps\": an identifier holds only "
                  "lower-case letters"},
        ErrorCase{"no_probabilities",
                  [](HandMade& f) { f.files.erase("branch-to-probability.bin"); },
                  "branch-to-probability.bin: absent, but the model needs its probabilities"},
        ErrorCase{"reward_absent",
                  [](HandMade& f) { f.files.erase("annotations/rewards/cost/states/values.bin"); },
                  "annotations/rewards/cost/states/values.bin: absent, though the index says it "
                  "is there"},
        ErrorCase{"short_targets",
                  [](HandMade& f) {
                    f.files["branch-to-target.bin"] = u64s({1, 2, 0});
                  },
                  "branch-to-target.bin: holds 24 bytes, but \"#branches\" needs 6 values of 8 "
                  "bytes"},
        ErrorCase{"target_range",
                  [](HandMade& f) {
                    f.files["branch-to-target.bin"] = u64s({1, 2, 0, 1, 0, 9});
                  },
                  "branch-to-target.bin: branch 5 (state 2, choice 0) goes to state 9, but the "
                  "model has 3 states"},
        ErrorCase{"csr_falls",
                  [](HandMade& f) {
                    f.files["state-to-choices.bin"] = u64s({0, 3, 2, 4});
                  },
                  "state-to-choices.bin: offset 2 is 2; the offsets must rise from 0 to 4"},
        ErrorCase{"csr_end",
                  [](HandMade& f) {
                    f.files["choice-to-branches.bin"] = u64s({0, 2, 3, 4, 5});
                  },
                  "choice-to-branches.bin: offset 4 is 5; the offsets must rise from 0 to 6"},
        ErrorCase{"sum",
                  [](HandMade& f) {
                    f.files["branch-to-probability.bin"] = doubles({0.2, 0.7, 1, 1, 0.3, 0.7});
                  },
                  "branch-to-probability.bin: the probabilities of state 0, choice 0 sum to "
                  "9/10 (0.9), not 1"},
        ErrorCase{"zero",
                  [](HandMade& f) {
                    f.files["branch-to-probability.bin"] = doubles({0, 1, 1, 1, 0.3, 0.7});
                  },
                  "branch-to-probability.bin: branch 0 (state 0, choice 0) has the probability 0; "
                  "it must be positive"},
        ErrorCase{"nan",
                  [](HandMade& f) {
                    f.files["branch-to-probability.bin"] = doubles({0.2, 0.8, NAN, 1, 0.3, 0.7});
                  },
                  "branch-to-probability.bin: value 2 is not a finite number"},
        ErrorCase{"denominator",
                  [](HandMade& f) {
                    f.files["annotations/rewards/cost/states/values.bin"] =
                        rational256(1, 3) + rational256(1, 0) + rational256(1, 1);
                  },
                  "annotations/rewards/cost/states/values.bin: value 1 has the denominator 0"},
        ErrorCase{"action_range",
                  [](HandMade& f) {
                    f.files["actions/choices/values.bin"] = u32s({1, 0, 7, 1});
                  },
                  "actions/choices/values.bin: state 1, choice 0 has action 7, but "
                  "\"#choice-actions\" is 4"},
        ErrorCase{"same_action",
                  [](HandMade& f) {
                    f.files["actions/choices/values.bin"] = u32s({1, 1, 2, 1});
                  },
                  "state 0 has two choices named 'go' (choices 0 and 1); an MDP allows one per "
                  "action"},
        ErrorCase{"control_name",
                  [](HandMade& f) { f.files["actions/choices/strings.bin"] = "g\x01stayunused"; },
                  "actions/choices/strings.bin: the name of action 1 is not UTF-8 text"},
        ErrorCase{"initial_count", [](HandMade& f) { ts(f)["#initial-states"] = 2; },
                  "state-is-initial.bin: 1 states are initial, but \"#initial-states\" is 2"},
        ErrorCase{"bitset_size",
                  [](HandMade& f) { f.files["annotations/aps/goal/states/values.bin"] = "\2"; },
                  "annotations/aps/goal/states/values.bin: holds 1 bytes, but a bitset of 3 "
                  "states has 8"},
        ErrorCase{"dtmc_choices", [](HandMade& f) { ts(f)["#players"] = 0; },
                  "state-to-choices.bin: state 0 has 2 choices, but a DTMC (\"#players\": 0) "
                  "has one per state"}),
    [](const ::testing::TestParamInfo<ErrorCase>& case_info) {
      return std::string(case_info.param.name);
    });

TEST(Umb, WhatIsNotAUmbFileSaysSo) {
  for (const std::string& bytes : {std::string(), std::string("hello\n"), std::string(600, 'x')}) {
    const Read read = read_bytes(bytes);
    EXPECT_FALSE(read.model);
    EXPECT_NE(read.messages.find("x.umb: error: not a UMB file (a tar archive, plain or "
                                 "compressed with gzip or xz)"),
              std::string::npos)
        << read.messages;
  }
  const Read json = read_bytes(tar({{"index.json", "{\"format-version\": "}}));
  EXPECT_NE(json.messages.find("x.umb: error: index.json is not valid JSON (at byte 20)"),
            std::string::npos)
      << json.messages;
  const Read huge = read_bytes(tar({{"index.json", "{\"format-version\": 1e400}"}}));
  EXPECT_NE(huge.messages.find("x.umb: error: index.json holds a number out of range"),
            std::string::npos)
      << huge.messages;
  const Read none = read_bytes(tar({{"model.json", "{}"}}));
  EXPECT_NE(none.messages.find("x.umb: error: the archive has no index.json"), std::string::npos)
      << none.messages;
  const Read twice = read_bytes(tar({{"index.json", "{}"}, {"./index.json", "{}"}}));
  EXPECT_NE(twice.messages.find("x.umb: error: entry 'index.json' appears twice in the archive"),
            std::string::npos)
      << twice.messages;
  ReadOptions small;
  small.max_bytes = 100;
  const Read big = read_bytes(HandMade{}.bytes(), small);
  EXPECT_NE(big.messages.find("larger than the input limit (--max-input-size) when decompressed"),
            std::string::npos)
      << big.messages;
}

// --- Round trips ---------------------------------------------------------------------------

class UmbFile : public ::testing::Test {
 protected:
  [[nodiscard]] std::string path(const std::string& name) const {
    return (scratch_.path() / name).string();
  }

  std::string write(const ExplicitModel& m, const std::string& name) {
    std::vector<std::size_t> contexts;
    for (std::size_t c = 0; c < m.contexts.size(); ++c)
      contexts.push_back(c);
    std::string error;
    EXPECT_TRUE(write_umb_file(m, contexts, path(name), error)) << error;
    std::ifstream in(path(name), std::ios::binary);
    return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
  }

  ExplicitModel read(const std::string& name) {
    SourceManager sources;
    std::ostringstream messages;
    DiagnosticEngine diagnostics(sources, messages);
    std::optional<ExplicitModel> m = read_model_file(path(name), sources, diagnostics, {});
    EXPECT_TRUE(m) << messages.str();
    return m ? std::move(*m) : ExplicitModel{};
  }

  oasis::test::ScratchDirectory scratch_{"oasis_umb_test"};
};

// Same type, states, initial states, actions by name, exact distributions, labels by name and
// R(s, a) of every context, in order.
void expect_same_model(const ExplicitModel& x, const ExplicitModel& y) {
  ASSERT_EQ(x.num_states(), y.num_states());
  EXPECT_EQ(x.type, y.type);
  EXPECT_EQ(x.states.initial, y.states.initial);
  ASSERT_EQ(x.contexts.size(), y.contexts.size());
  for (std::size_t c = 0; c < x.contexts.size(); ++c)
    EXPECT_EQ(x.contexts[c].name, y.contexts[c].name);
  for (model::StateIndex s = 0; s < x.num_states(); ++s) {
    EXPECT_EQ(labels_of(x, s), labels_of(y, s)) << "state " << s;
    for (model::ActionIndex a = 0; a < x.num_actions(); ++a) {
      const model::ActionIndex b = action_named(y, x.actions[a]);
      const bool enabled = x.contexts[0].transitions->enabled(s, a);
      if (b == y.num_actions()) {
        EXPECT_FALSE(enabled) << x.actions[a];
        continue;
      }
      EXPECT_EQ(distribution(x, s, x.actions[a]), distribution(y, s, x.actions[a]));
      if (!enabled) continue;
      for (std::size_t c = 0; c < x.contexts.size(); ++c)
        EXPECT_EQ(x.reward(c, s, a), y.reward(c, s, b)) << "state " << s << " " << x.actions[a];
    }
  }
}

TEST_F(UmbFile, ReadWriteReadKeepsTheModelAndWriteReadWriteTheBytes) {
  const Read first = read_bytes(HandMade{}.bytes());
  ASSERT_TRUE(first.model) << first.messages;
  const std::string bytes = write(*first.model, "a.umb");
  EXPECT_EQ(bytes.substr(0, 3), std::string("\x1f\x8b\x08", 3));  // gzip, as the format says
  const ExplicitModel second = read("a.umb");
  expect_same_model(*first.model, second);
  EXPECT_EQ(write(second, "b.umb"), bytes);
}

TEST_F(UmbFile, ExactRationalsStayExactAtAnySize) {
  // 1/3 and a probability whose parts need 160 bits: both written as rationals, the second
  // making the whole array 384 bits wide.
  const Rational tiny(mpz_class(1), mpz_class("1461501637330902918203684832716283019655932542976"));
  std::ostringstream text;
  text << "@type: DTMC\n@reward_models\nr\n@nr_states\n2\n@model\nstate 0 [1/3] init\n\taction 0\n"
       << "\t\t0 : 1/3\n\t\t1 : 2/3\nstate 1 [-7/2]\n\taction 0\n\t\t0 : " << tiny << "\n"
       << "\t\t1 : " << Rational(1 - tiny) << "\n";
  SourceManager sources;
  std::ostringstream messages;
  DiagnosticEngine diagnostics(sources, messages);
  const std::optional<ExplicitModel> model =
      read_drn(sources.add("exact.drn", text.str()), diagnostics, {});
  ASSERT_TRUE(model) << messages.str();
  const std::string bytes = write(*model, "exact.umb");
  const ExplicitModel back = read("exact.umb");
  expect_same_model(*model, back);
  EXPECT_EQ(distribution(back, 1, "[0]").at(0), tiny);
  EXPECT_EQ(back.reward(0, 0, 0), Rational(1, 3));
  EXPECT_EQ(back.reward(0, 1, 0), Rational(-7, 2));
  EXPECT_EQ(write(back, "exact2.umb"), bytes);
}

TEST_F(UmbFile, PrismProgramsRoundTripWithTheirRewardStructures) {
  for (const char* name : {"knuth_die.pm", "two_dice.nm", "crowds5.pm"}) {
    SourceManager sources;
    std::ostringstream messages;
    DiagnosticEngine diagnostics(sources, messages);
    prism::LoadOptions options;
    options.rewards = model::LabelSelection{};  // every reward structure a context
    if (std::string(name) == "crowds5.pm") options.constants = "TotalRuns=5";
    const std::optional<ExplicitModel> program = prism::load_program(
        std::string(OASIS_SOURCE_DIR) + "/tests/data/prism/" + name, sources, diagnostics, options);
    ASSERT_TRUE(program) << messages.str();
    const std::string bytes = write(*program, "p.umb");
    const ExplicitModel back = read("p.umb");
    expect_same_model(*program, back);
    EXPECT_EQ(back.states.variables, program->states.variables) << name;
    EXPECT_EQ(back.states.valuations, program->states.valuations) << name;
    EXPECT_EQ(write(back, "q.umb"), bytes) << name;
  }
}

TEST_F(UmbFile, WhatUmbCannotCarryIsRefusedBeforeWriting) {
  Read read = read_bytes(HandMade{}.bytes());
  ASSERT_TRUE(read.model);
  read.model->labels.names[0] = "bad\x01name";
  std::string error;
  const std::vector<std::size_t> all = {0, 1};
  EXPECT_FALSE(write_umb_file(*read.model, all, path("bad.umb"), error));
  EXPECT_NE(error.find("cannot write a UMB file: label name"), std::string::npos) << error;
  EXPECT_FALSE(std::filesystem::exists(path("bad.umb")));
}

}  // namespace
}  // namespace oasis::formats
