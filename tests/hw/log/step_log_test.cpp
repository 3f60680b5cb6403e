// The step log: writer -> reader round trips (with and without ground truth, non-finite
// values), every reader error with its FILE:LINE, and the cut-short last line of a killed run.

#include <cmath>
#include <filesystem>
#include <fstream>
#include <functional>
#include <limits>
#include <sstream>
#include <string>
#include <vector>

#include <gtest/gtest.h>
#include <unistd.h>

#include "log/log_error.hpp"
#include "log/step_json.hpp"
#include "log/step_log_reader.hpp"
#include "log/step_log_writer.hpp"

namespace oasis::hw::log {
namespace {

namespace fs = std::filesystem;

StepRecord sample_record(std::uint64_t step, bool with_truth) {
  StepRecord record;
  record.step = step;
  record.time_s = 0.2 * static_cast<double>(step) + 0.013;
  record.humans[0] = {true, 1.25, -0.4, 0.93};
  record.humans[1] = {false, 0.0, 0.0, 0.0};
  record.state = {1.25, -0.4, 3.0, 0.75};
  record.holder = 1;
  record.reward = 0.1 + 1e-17;  // needs 17 digits to read back exactly
  record.belief = {0.7, 0.3};
  record.abstraction = 0;
  record.abstraction_name = "human1_has_treat";
  record.action = 3;
  record.action_name = "forward";
  record.command = {0.3, 0.0, -0.25};
  record.filter_status = "ok";
  if (with_truth) record.truth = GroundTruth{1, 0.5};
  return record;
}

void expect_same(const StepRecord& a, const StepRecord& b) {
  EXPECT_EQ(a.step, b.step);
  EXPECT_EQ(a.time_s, b.time_s);
  for (std::size_t h = 0; h < 2; ++h) {
    EXPECT_EQ(a.humans[h].seen, b.humans[h].seen) << h;
    EXPECT_EQ(a.humans[h].x_m, b.humans[h].x_m) << h;
    EXPECT_EQ(a.humans[h].y_m, b.humans[h].y_m) << h;
    EXPECT_EQ(a.humans[h].confidence, b.humans[h].confidence) << h;
  }
  EXPECT_EQ(a.state, b.state);
  EXPECT_EQ(a.holder, b.holder);
  EXPECT_EQ(a.reward, b.reward);
  EXPECT_EQ(a.belief, b.belief);
  EXPECT_EQ(a.abstraction, b.abstraction);
  EXPECT_EQ(a.abstraction_name, b.abstraction_name);
  EXPECT_EQ(a.action, b.action);
  EXPECT_EQ(a.action_name, b.action_name);
  EXPECT_EQ(a.command.forward_m_s, b.command.forward_m_s);
  EXPECT_EQ(a.command.lateral_m_s, b.command.lateral_m_s);
  EXPECT_EQ(a.command.yaw_rate_rad_s, b.command.yaw_rate_rad_s);
  EXPECT_EQ(a.filter_status, b.filter_status);
  ASSERT_EQ(a.truth.has_value(), b.truth.has_value());
  if (a.truth) {
    EXPECT_EQ(a.truth->abstraction, b.truth->abstraction);
    EXPECT_EQ(a.truth->reward, b.truth->reward);
  }
}

std::string line_of(const StepRecord& record) {
  return step_to_json(record).dump() + "\n";
}

// A private file under the system's temporary directory, removed at the end of the test.
class StepLogFile : public ::testing::Test {
 protected:
  void SetUp() override {
    const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
    path_ = fs::temp_directory_path() /
            ("oasis_step_log_" + std::to_string(::getpid()) + "_" + info->name() + ".jsonl");
  }
  void TearDown() override { fs::remove(path_); }

  std::string contents() const {
    std::ifstream in(path_, std::ios::binary);
    std::ostringstream text;
    text << in.rdbuf();
    return text.str();
  }

  fs::path path_;
};

TEST_F(StepLogFile, RoundTripsRecordsWithAndWithoutTruth) {
  const std::vector<StepRecord> written{sample_record(0, false), sample_record(1, true),
                                        sample_record(2, false)};
  {
    StepLogWriter writer(path_);
    for (const StepRecord& record : written)
      writer.write(record);
  }
  const StepLog log = read_step_log(path_);
  EXPECT_TRUE(log.warnings.empty());
  ASSERT_EQ(log.records.size(), written.size());
  for (std::size_t k = 0; k < written.size(); ++k) {
    SCOPED_TRACE(k);
    expect_same(log.records[k], written[k]);
  }
}

TEST_F(StepLogFile, EveryLineIsOnDiskAsSoonAsItIsWritten) {
  StepLogWriter writer(path_);
  writer.write(sample_record(0, true));
  writer.write(sample_record(1, true));
  // The writer is still open: what a killed run would leave.
  const std::string text = contents();
  EXPECT_EQ(text, line_of(sample_record(0, true)) + line_of(sample_record(1, true)));
  EXPECT_EQ(read_step_log(path_).records.size(), 2u);
}

TEST_F(StepLogFile, KeysAreInTheDocumentedOrderAndTruthOnlyWhenPresent) {
  const std::string without = step_to_json(sample_record(0, false)).dump();
  EXPECT_EQ(without.rfind("{\"step\":0,\"time_s\":0.013,\"humans\":[{\"seen\":true,", 0), 0u)
      << without;
  EXPECT_EQ(without.find("truth"), std::string::npos);
  const std::string with = step_to_json(sample_record(0, true)).dump();
  EXPECT_NE(with.find(",\"filter_status\":\"ok\",\"truth\":{\"abstraction\":1,\"reward\":0.5}}"),
            std::string::npos)
      << with;
}

TEST(StepJson, NanIsNullAndInfinitiesAreStringsBothWays) {
  constexpr double kNan = std::numeric_limits<double>::quiet_NaN();
  constexpr double kInf = std::numeric_limits<double>::infinity();
  StepRecord record = sample_record(4, true);
  record.state = {kNan, 1.0, kInf, -kInf};
  record.humans[1].x_m = kNan;
  record.truth->reward = kNan;
  const std::string line = step_to_json(record).dump();
  EXPECT_NE(line.find("\"state\":[null,1.0,\"inf\",\"-inf\"]"), std::string::npos) << line;

  const StepLog log = parse_step_log(line + "\n", "mem");
  ASSERT_EQ(log.records.size(), 1u);
  const StepRecord& back = log.records[0];
  ASSERT_EQ(back.state.size(), 4u);
  EXPECT_TRUE(std::isnan(back.state[0]));
  EXPECT_EQ(back.state[1], 1.0);
  EXPECT_EQ(back.state[2], kInf);
  EXPECT_EQ(back.state[3], -kInf);
  EXPECT_TRUE(std::isnan(back.humans[1].x_m));
  EXPECT_TRUE(std::isnan(back.truth->reward));
}

TEST(StepJson, TimeMustBeFinite) {
  StepRecord record = sample_record(7, false);
  record.time_s = std::numeric_limits<double>::quiet_NaN();
  try {
    (void)step_to_json(record);
    FAIL() << "expected LogError";
  } catch (const LogError& error) {
    EXPECT_STREQ(error.what(), "step 7: time_s must be finite");
  }
}

TEST_F(StepLogFile, WriterRefusesANonFiniteTimeNamingTheFileAndKeepsEarlierLines) {
  StepLogWriter writer(path_);
  writer.write(sample_record(0, false));
  StepRecord bad = sample_record(1, false);
  bad.time_s = std::numeric_limits<double>::infinity();
  try {
    writer.write(bad);
    FAIL() << "expected LogError";
  } catch (const LogError& error) {
    EXPECT_EQ(std::string(error.what()), path_.string() + ": error: step 1: time_s must be finite");
  }
  EXPECT_EQ(contents(), line_of(sample_record(0, false)));
}

TEST(StepLogWriter, UnopenablePathIsALogError) {
  try {
    StepLogWriter writer("/nonexistent-oasis-dir/run.jsonl");
    FAIL() << "expected LogError";
  } catch (const LogError& error) {
    EXPECT_EQ(std::string(error.what())
                  .rfind("/nonexistent-oasis-dir/run.jsonl: error: cannot create: ", 0),
              0u)
        << error.what();
  }
}

TEST(StepLogReader, MissingFileIsALogError) {
  try {
    (void)read_step_log("/nonexistent-oasis-dir/run.jsonl");
    FAIL() << "expected LogError";
  } catch (const LogError& error) {
    EXPECT_EQ(std::string(error.what()),
              "/nonexistent-oasis-dir/run.jsonl: error: no such file or directory");
  }
}

// The message of the LogError parse_step_log throws on `text`, or "" if none.
std::string read_error(const std::string& text) {
  try {
    (void)parse_step_log(text, "run.jsonl");
  } catch (const LogError& error) {
    return error.what();
  }
  return "";
}

// Two good lines, then line 3 = the good record's JSON with `edit` applied.
std::string third_line_edited(const std::function<void(nlohmann::ordered_json&)>& edit) {
  nlohmann::ordered_json object = step_to_json(sample_record(2, true));
  edit(object);
  return line_of(sample_record(0, true)) + line_of(sample_record(1, true)) + object.dump() + "\n";
}

TEST(StepLogReader, EachErrorNamesFileLineAndKey) {
  using Json = nlohmann::ordered_json;
  const std::string good = line_of(sample_record(0, false));
  EXPECT_EQ(read_error(good + "{\"step\": 1,\n" + good),
            "run.jsonl:2: error: not valid JSON: parse error at line 1, column 12: syntax error "
            "while parsing object key - unexpected end of input; expected string literal");
  EXPECT_EQ(read_error(good + "\n" + good), "run.jsonl:2: error: empty line");
  // Found by the step_log fuzz target: a number beyond a double escaped as nlohmann's own error.
  EXPECT_EQ(read_error(good + "{\"step\": 1, \"time_s\": 1e999}\n" + good),
            "run.jsonl:2: error: not valid JSON: number overflow parsing '1e999'");
  EXPECT_EQ(read_error(good + good + "[1, 2]\n"),
            "run.jsonl:3: error: a line must be one JSON object, not array");

  struct Case {
    std::function<void(Json&)> edit;
    std::string message;
  };
  const std::vector<Case> cases{
      {[](Json& o) { o.erase("step"); }, "missing key 'step'"},
      {[](Json& o) { o["step"] = -1; },
       "key 'step' must be an integer in 0..18446744073709551615, not number"},
      {[](Json& o) { o["time_s"] = "0.4"; }, "key 'time_s' must be a finite number, not string"},
      {[](Json& o) { o["time_s"] = nullptr; }, "key 'time_s' must be a finite number, not null"},
      {[](Json& o) { o["humans"] = Json::array({o["humans"][0]}); },
       "key 'humans' must be an array of 2 objects (human 1, human 2), not array"},
      {[](Json& o) { o["humans"][1].erase("confidence"); }, "missing key 'humans[1].confidence'"},
      {[](Json& o) { o["humans"][0]["seen"] = 1; },
       "key 'humans[0].seen' must be true or false, not number"},
      {[](Json& o) { o["state"][2] = "far"; },
       "key 'state[2]' must be a number, null (NaN), \"inf\" or \"-inf\", not string"},
      {[](Json& o) { o["state"] = 1.0; }, "key 'state' must be an array, not number"},
      {[](Json& o) { o["holder"] = 1.5; }, "key 'holder' must be an integer, not number"},
      {[](Json& o) { o["holder"] = 4294967296LL; }, "key 'holder' is out of range for an int"},
      {[](Json& o) { o.erase("belief"); }, "missing key 'belief'"},
      {[](Json& o) { o["abstraction"] = 4294967296ULL; },
       "key 'abstraction' must be an integer in 0..4294967295, not number"},
      {[](Json& o) { o["abstraction_name"] = 0; },
       "key 'abstraction_name' must be a string, not number"},
      {[](Json& o) { o["action"] = "forward"; },
       "key 'action' must be an integer in 0..4294967295, not string"},
      {[](Json& o) { o.erase("action_name"); }, "missing key 'action_name'"},
      {[](Json& o) { o["command"] = Json::array(); }, "key 'command' must be an object, not array"},
      {[](Json& o) { o["command"].erase("yaw_rate_rad_s"); },
       "missing key 'command.yaw_rate_rad_s'"},
      {[](Json& o) { o["filter_status"] = nullptr; },
       "key 'filter_status' must be a string, not null"},
      {[](Json& o) { o["truth"] = nullptr; }, "key 'truth' must be an object, not null"},
      {[](Json& o) { o["truth"].erase("reward"); }, "missing key 'truth.reward'"},
      {[](Json& o) { o["truth"]["abstraction"] = -2; },
       "key 'truth.abstraction' must be an integer in 0..4294967295, not number"},
  };
  for (const Case& c : cases)
    EXPECT_EQ(read_error(third_line_edited(c.edit)), "run.jsonl:3: error: " + c.message);
}

TEST(StepLogReader, UnknownKeysAreIgnored) {
  const std::string text = third_line_edited([](nlohmann::ordered_json& o) {
    o["added_later"] = {1, 2};
  });
  EXPECT_EQ(parse_step_log(text, "run.jsonl").records.size(), 3u);
}

TEST(StepLogReader, CutShortLastLineIsAWarningAndDropped) {
  const std::string full = line_of(sample_record(0, true)) + line_of(sample_record(1, true));
  const std::string third = line_of(sample_record(2, true));
  const std::string cut = third.substr(0, third.size() / 2);
  const StepLog log = parse_step_log(full + cut, "run.jsonl");
  ASSERT_EQ(log.records.size(), 2u);
  EXPECT_EQ(log.records[1].step, 1u);
  ASSERT_EQ(log.warnings.size(), 1u);
  EXPECT_EQ(log.warnings[0].rfind("run.jsonl:3: warning: last line is cut short (no newline, "
                                  "not valid JSON: parse error at line 1, column ",
                                  0),
            0u)
      << log.warnings[0];
}

TEST(StepLogReader, CompleteLastLineWithoutNewlineIsKept) {
  std::string text = line_of(sample_record(0, false)) + line_of(sample_record(1, false));
  text.pop_back();
  const StepLog log = parse_step_log(text, "run.jsonl");
  EXPECT_EQ(log.records.size(), 2u);
  EXPECT_TRUE(log.warnings.empty());
}

TEST(StepLogReader, CutShortLineFollowedByANewlineIsAnError) {
  const std::string third = line_of(sample_record(2, true));
  const std::string text = line_of(sample_record(0, true)) + third.substr(0, 20) + "\n";
  EXPECT_EQ(read_error(text).rfind("run.jsonl:2: error: not valid JSON: ", 0), 0u)
      << read_error(text);
}

// The example line of hw/log/README.md, kept here so that the documentation stays readable.
TEST(StepLogReader, ReadmeExampleLineIsARecord) {
  const std::string line =
      R"({"step":42,"time_s":8.4,"humans":[{"seen":true,"x_m":0.62,"y_m":0.08,"confidence":0.91},)"
      R"({"seen":false,"x_m":0.0,"y_m":0.0,"confidence":0.0}],"state":[0.62,0.08,null,null],)"
      R"("holder":1,"reward":1.0,"belief":[0.96,0.04],"abstraction":0,)"
      R"("abstraction_name":"human1_holds_treat","action":2,"action_name":"straight",)"
      R"("command":{"forward_m_s":0.5,"lateral_m_s":0.0,"yaw_rate_rad_s":0.0},)"
      R"("filter_status":"ok","truth":{"abstraction":0,"reward":1.0}})";
  const StepLog log = parse_step_log(line + "\n", "README.md");
  ASSERT_EQ(log.records.size(), 1u);
  EXPECT_EQ(log.records[0].action_name, "straight");
  EXPECT_TRUE(std::isnan(log.records[0].state[3]));
  EXPECT_EQ(step_to_json(log.records[0]).dump(), line);  // and it is what the writer writes
}

TEST(StepLogReader, EmptyLogHasNoRecords) {
  const StepLog log = parse_step_log("", "run.jsonl");
  EXPECT_TRUE(log.records.empty());
  EXPECT_TRUE(log.warnings.empty());
}

}  // namespace
}  // namespace oasis::hw::log
