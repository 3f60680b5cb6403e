// Size options (--max-input-size, --max-spec-size) pass one rule
// (common/command_line/number_options.hpp, size_text): CLI11 alone took "-1" as 2^64 - 1 bytes,
// which turned the limit off (issue 37).

#include <string>

#include <gtest/gtest.h>

#include "../../support/run_oasisc.hpp"

namespace {

using oasis::test::CommandResult;
using oasis::test::run_oasisc;

const std::string kSpec = std::string(OASIS_SOURCE_DIR) + "/specs/discrete_tracking.oasis";

TEST(SizeOptions, ASignOrANonNumberIsAUsageError) {
  for (const std::string option : {"--max-input-size", "--max-spec-size"}) {
    for (const std::string value : {"-1", "+5", "nan", "inf", "1e999", "G", ".", "8G!"}) {
      const CommandResult result = run_oasisc("check " + kSpec + " " + option + " '" + value + "'");
      EXPECT_EQ(result.status, 2) << option << ' ' << value << '\n' << result.output;
      EXPECT_NE(result.output.find(option), std::string::npos) << result.output;
    }
  }
}

TEST(SizeOptions, SizesWithUnitsAreTaken) {
  for (const std::string value : {"65536", "8G", "64M", "512kb"}) {
    const CommandResult result = run_oasisc("check " + kSpec + " --max-spec-size " + value);
    EXPECT_EQ(result.status, 0) << value << '\n' << result.output;
  }
}

// Too small a limit still refuses the file: the limit is in force, not turned off.
TEST(SizeOptions, ASmallLimitRefusesTheSpec) {
  const CommandResult result = run_oasisc("check " + kSpec + " --max-spec-size 10");
  EXPECT_EQ(result.status, 1) << result.output;
}

}  // namespace
