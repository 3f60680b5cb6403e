// The limits of support/limits.hpp reported as errors, never as crashes: the memory budget's
// flag (its enforcement is memory_budget_test.cpp, not run under sanitizers), the size of exact
// numbers (constants that square each other, literals of
// millions of digits, model-file values), and the sizes of input files.

#include <atomic>
#include <chrono>
#include <filesystem>
#include <stdexcept>
#include <string>
#include <thread>
#include <vector>

#include <gtest/gtest.h>

#include "../../support/run_oasisc.hpp"
#include "../../support/scratch_files.hpp"
#include "../../support/spec_models.hpp"
#include "command_line/memory_budget.hpp"
#include "support/parallel.hpp"
#include "text/byte_size.hpp"

namespace {

namespace fs = std::filesystem;
using oasis::test::CommandResult;
using oasis::test::output_has;
using oasis::test::run_oasisc;

class Limits : public oasis::test::ScratchFilesTest {
 protected:
  Limits() : ScratchFilesTest("oasis_limits_test") {}
};

// --- The memory budget (its enforcement: memory_budget_test.cpp) ---------------------------

TEST_F(Limits, BadMemoryBudgetsAreUsageErrors) {
  const std::string spec = std::string(OASIS_SOURCE_DIR) + "/specs/discrete_tracking.oasis";
  if (oasis::memory_budget_enforceable()) {
    const CommandResult tiny = run_oasisc("check " + spec + " --memory-budget 1K");
    EXPECT_EQ(tiny.status, 2) << tiny.output;
    EXPECT_TRUE(output_has(tiny,
                           "oasisc: error: --memory-budget: a memory budget must be at least "
                           "16.0 MiB, not 1.0 KiB"))
        << tiny.output;
    const CommandResult word = run_oasisc("check " + spec + " --memory-budget lots");
    EXPECT_EQ(word.status, 2) << word.output;
    EXPECT_TRUE(output_has(word, "expected a size such as 512M, 4G or 75%")) << word.output;
  }
  const CommandResult none = run_oasisc("check " + spec + " --memory-budget none");
  EXPECT_EQ(none.status, 0) << none.output;
}

TEST(MemoryBudget, ParsesSizesPercentagesAndNone) {
  std::string error;
  EXPECT_EQ(oasis::parse_memory_budget("none", error), 0U);
  EXPECT_EQ(oasis::parse_memory_budget("512M", error), std::uint64_t{512} << 20);
  EXPECT_EQ(oasis::parse_memory_budget("4GiB", error), std::uint64_t{4} << 30);
  EXPECT_EQ(oasis::parse_memory_budget("1.5g", error), std::uint64_t{3} << 29);
  EXPECT_EQ(oasis::parse_memory_budget("67108864", error), std::uint64_t{64} << 20);
  EXPECT_FALSE(oasis::parse_memory_budget("0%", error));
  EXPECT_FALSE(oasis::parse_memory_budget("101%", error));
  EXPECT_FALSE(oasis::parse_memory_budget("-1G", error));
  EXPECT_FALSE(oasis::parse_memory_budget("4X", error));
  EXPECT_FALSE(oasis::parse_memory_budget("1M", error));  // below the minimum
  if (const auto available = oasis::available_memory_bytes()) {
    EXPECT_EQ(oasis::parse_memory_budget("50%", error), *available / 100 * 50);
    EXPECT_EQ(oasis::parse_memory_budget("auto", error), *available / 100 * 75);
  }
}

TEST(MemoryBudget, DescribesBytesForMessages) {
  EXPECT_EQ(oasis::text::describe_bytes(900), "900 bytes");
  EXPECT_EQ(oasis::text::describe_bytes(std::uint64_t{3} << 29), "1.5 GiB");
  EXPECT_EQ(oasis::text::describe_bytes(std::uint64_t{16} << 20), "16.0 MiB");
}

// An exception in a worker (std::bad_alloc under a budget) reaches the caller instead of
// terminating the process, and no further item is started.
// Item 3 throws; every other item takes a millisecond, so the 1000 items would take about half
// a second on two threads: the throw stops them long before (no timing is asserted, only that
// far from all items started).
TEST(MemoryBudget, ParallelForRethrowsAWorkersException) {
  std::atomic<int> started{0};
  EXPECT_THROW(oasis::parallel_for(1000, 2,
                                   [&](std::size_t i) {
                                     ++started;
                                     if (i == 3) throw std::bad_alloc();
                                     std::this_thread::sleep_for(std::chrono::milliseconds(1));
                                   }),
               std::bad_alloc);
  EXPECT_LT(started.load(), 500);
}

// --- The size of exact numbers -------------------------------------------------------------

std::string tracking_with(const std::string& constants, const std::string& discount) {
  return "mdp m {\n" + constants +
         "  states a, b;\n  actions go;\n  a, go -> 1/2: a + 1/2: b;\n  b, go -> b;\n"
         "  reward a : 1;\n  discount " +
         discount + ";\n}\n";
}

TEST(NumberSize, SquaringConstantsStopsAtTheLimitWithOneError) {
  std::string constants = "  const c0 = 1e-99999;\n";
  for (int i = 0; i < 40; ++i)
    constants += "  const c" + std::to_string(i + 1) + " = c" + std::to_string(i) + " * c" +
                 std::to_string(i) + ";\n";
  const auto errors = oasis::test::spec_errors(tracking_with(constants, "0.9"));
  ASSERT_EQ(errors.size(), 1U) << ::testing::PrintToString(errors);
  EXPECT_NE(errors[0].find("4:14: number about 1e-399996"), std::string::npos) << errors[0];
  EXPECT_NE(errors[0].find("is too long to compute with exactly: its numerator or denominator "
                           "has 1328758 bits, more than the limit of 1048576 (--max-number-bits)"),
            std::string::npos)
      << errors[0];
}

TEST(NumberSize, AFiveThousandDigitLiteralIsExact) {
  // 0.5 followed by 4998 zeros and a 1: far from any double, carried as 0.5, kept exact.
  const std::string discount = "0.5" + std::string(4998, '0') + "1";
  oasis::test::check_spec_text_ir(tracking_with("", discount));
  // 1/10^1000 is exact too, and refused only where a catalog would have to carry it.
  const auto errors =
      oasis::test::spec_errors(tracking_with("", "1 - 1/1" + std::string(1000, '0')));
  ASSERT_EQ(errors.size(), 1U);
  EXPECT_NE(errors[0].find("rounds to 1 in double precision"), std::string::npos) << errors[0];
}

TEST(NumberSize, ALiteralOfMillionsOfDigitsIsRefusedWhereItIsWritten) {
  const auto errors =
      oasis::test::spec_errors(tracking_with("", "0." + std::string(2'000'000, '9')));
  ASSERT_EQ(errors.size(), 1U);
  EXPECT_NE(errors[0].find("7:12: number of 2000002 characters is too long to compute "
                           "with exactly"),
            std::string::npos)
      << errors[0].substr(0, 200);
}

TEST_F(Limits, MaxNumberBitsIsConfigurable) {
  const fs::path spec = write("m.oasis", tracking_with("  const tiny = 1e-30;\n", "0.9"));
  EXPECT_EQ(run_oasisc("check " + spec.string()).status, 0);
  const CommandResult result = run_oasisc("check " + spec.string() + " --max-number-bits 64");
  EXPECT_EQ(result.status, 1) << result.output;
  EXPECT_TRUE(output_has(result,
                         "m.oasis:2:16: error: number of 5 characters is too long to "
                         "compute with exactly: its numerator or denominator has 100 bits, "
                         "more than the limit of 64 (--max-number-bits)"))
      << result.output;
  EXPECT_TRUE(output_has(result, "  const tiny = 1e-30;\n               ^~~~~")) << result.output;
}

TEST_F(Limits, ModelFileNumbersAreBoundToo) {
  const fs::path aut =
      write("m.aut", "des (0,2,2)\n(0,\"a\",1 1/12345678901234567890123 0)\n(1,\"a\",1)\n");
  EXPECT_EQ(run_oasisc("check " + aut.string()).status, 0);
  const CommandResult result = run_oasisc("check " + aut.string() + " --max-number-bits 64");
  EXPECT_EQ(result.status, 1) << result.output;
  EXPECT_TRUE(output_has(result, "m.aut:2:10: error: probability about 8.1e-23 is too long"))
      << result.output;
  EXPECT_TRUE(output_has(result, "more than the limit of 64 (--max-number-bits)")) << result.output;
}

// --- Input sizes -----------------------------------------------------------------------------

TEST_F(Limits, InputFilesLargerThanTheirLimitAreRefused) {
  const fs::path spec =
      write("big.oasis", tracking_with("// " + std::string(3000, 'x') + "\n", "0.9"));
  const CommandResult spec_result = run_oasisc("check " + spec.string() + " --max-spec-size 2K");
  EXPECT_EQ(spec_result.status, 1) << spec_result.output;
  EXPECT_TRUE(output_has(spec_result,
                         "big.oasis: error: cannot read spec: file is larger than the "
                         "limit of 2048 bytes"))
      << spec_result.output;

  const fs::path aut = write("m.aut", "des (0,2,2)\n(0,\"a\",1)\n(1,\"a\",1)\n");
  const CommandResult aut_result = run_oasisc("check " + aut.string() + " --max-input-size 16");
  EXPECT_EQ(aut_result.status, 1) << aut_result.output;
  EXPECT_TRUE(output_has(aut_result, "m.aut: error: file is larger than the limit of 16 bytes"))
      << aut_result.output;

  const fs::path labels = write("labels.csv", "true_state,observed_state\ns1,s1\ns2,s3\n");
  const CommandResult csv_result =
      run_oasisc("fit noise " + std::string(OASIS_SOURCE_DIR) + "/specs/discrete_tracking.oasis " +
                 labels.string() + " --max-input-size 20");
  EXPECT_EQ(csv_result.status, 1) << csv_result.output;
  EXPECT_TRUE(output_has(csv_result,
                         "labels.csv: error: cannot read: file is larger than the limit "
                         "of 20 bytes"))
      << csv_result.output;

  const fs::path json = write("result.json", "{\"contexts\": []}\n");
  const CommandResult json_result =
      run_oasisc("verify " + std::string(OASIS_SOURCE_DIR) + "/specs/discrete_tracking.oasis " +
                 json.string() + " --max-input-size 8");
  EXPECT_EQ(json_result.status, 1) << json_result.output;
  EXPECT_TRUE(output_has(json_result,
                         "result.json: error: cannot read: file is larger than the "
                         "limit of 8 bytes"))
      << json_result.output;
}

// --- Model sizes (issue 41): the memory budget, not a fixed state count ---------------------

// An .aut file of `transitions` lines over `states` states (a ring, each state's lines to its
// neighbours), small enough to write in a test and large enough that its reading needs more
// than a tiny budget: 32 bytes per line at least.
std::string ring_aut(std::uint32_t states, std::uint32_t transitions) {
  std::string text = "des (0," + std::to_string(transitions) + "," + std::to_string(states) + ")\n";
  for (std::uint32_t t = 0; t < transitions; ++t) {
    const std::uint32_t s = t % states;
    text += "(" + std::to_string(s) + ",\"a" + std::to_string(t / states) + "\"," +
            std::to_string((s + 1) % states) + ")\n";
  }
  return text;
}

// A header declaring 4*10^9 states and 10^15 transitions, with one line of body: the default
// budget (75% of the machine) refuses it at the header, naming the option, and no output is
// written. Before issue 41 the message named no option, and oasisc read the whole file first.
TEST_F(Limits, AHeaderBeyondTheDefaultMemoryBudgetIsRefusedNamingTheOption) {
  const fs::path aut = write("huge.aut", "des (0,1000000000000000,4000000000)\n(0,\"a\",1)\n");
  const fs::path out = scratch_.path() / "q.json";
  const CommandResult result =
      run_oasisc("quotient " + aut.string() + " --format json -o " + out.string());
  EXPECT_EQ(result.status, 1) << result.output;
  EXPECT_TRUE(output_has(result,
                         "huge.aut:1:8: error: the header declares 1000000000000000 transitions "
                         "and 4000000000 states: reading it takes at least "))
      << result.output;
  EXPECT_TRUE(output_has(result, "(raise it with --memory-budget)")) << result.output;
  EXPECT_FALSE(fs::exists(out));
}

TEST_F(Limits, ASmallMemoryBudgetRefusesAModelThatOtherwiseLoads) {
  // 10^6 lines, 2.5*10^5 states: at least 32 MB to read; about 17 MB of file.
  const fs::path aut = write("ring.aut", ring_aut(250000, 1000000));
  const CommandResult loads = run_oasisc("check " + aut.string());
  EXPECT_EQ(loads.status, 0) << loads.output;
  const CommandResult refused = run_oasisc("check " + aut.string() + " --memory-budget 24M");
  EXPECT_EQ(refused.status, 1) << refused.output;
  EXPECT_TRUE(output_has(refused,
                         "ring.aut:1:8: error: the header declares 1000000 transitions and "
                         "250000 states: reading it takes at least 31.5 MiB, more than the "
                         "memory budget of 24.0 MiB (raise it with --memory-budget)"))
      << refused.output;
}

TEST_F(Limits, MaxStatesStillCapsWhenGiven) {
  const fs::path aut = write("ring.aut", ring_aut(2000, 4000));
  EXPECT_EQ(run_oasisc("check " + aut.string()).status, 0);
  EXPECT_EQ(run_oasisc("check " + aut.string() + " --max-states 2000").status, 0);
  const CommandResult capped = run_oasisc("check " + aut.string() + " --max-states 1999");
  EXPECT_EQ(capped.status, 1) << capped.output;
  EXPECT_TRUE(output_has(capped,
                         "ring.aut:1:13: error: the header declares 2000 states, more than the "
                         "limit of 1999 (raise it with --max-states)"))
      << capped.output;
  // Past 32-bit state numbers the option itself is refused: no cap can be set there.
  EXPECT_EQ(run_oasisc("check " + aut.string() + " --max-states 4294967295").status, 2);
}

}  // namespace
