// Lost output is an error: every oasisc command that prints its result fails when standard
// output cannot take it (/dev/full), and still succeeds when it can.

#include <string>

#include <gtest/gtest.h>

#include "../../support/run_oasisc.hpp"

namespace {

using oasis::test::run_oasisc;

const std::string kSpec = std::string(OASIS_SOURCE_DIR) + "/specs/discrete_tracking.oasis";

class FullStandardOutput : public ::testing::TestWithParam<std::string> {};

TEST_P(FullStandardOutput, ExitsNonZeroWithAMessage) {
  const auto result = run_oasisc(GetParam() + " > /dev/full");
  EXPECT_EQ(result.status, 1) << result.output;
  EXPECT_NE(result.output.find("oasisc: error: cannot write standard output"), std::string::npos)
      << result.output;
}

TEST_P(FullStandardOutput, SucceedsWhenTheOutputArrives) {
  const auto result = run_oasisc(GetParam() + " > /dev/null");
  EXPECT_EQ(result.status, 0) << result.output;
}

INSTANTIATE_TEST_SUITE_P(Commands, FullStandardOutput,
                         ::testing::Values("info " + kSpec, "info --json " + kSpec,
                                           "check " + kSpec, "quotient " + kSpec,
                                           "quotient --format json --partition " + kSpec, "--help",
                                           "--version", "compile --help"));

}  // namespace
