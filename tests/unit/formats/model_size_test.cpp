// formats/model_size.hpp: the bytes a header's counts need at least, per reader and per rank,
// and the refusals that name the option raising each limit (issue 41). The readers' own
// refusals, located in their files, are in their tests.

#include "formats/model_size.hpp"

#include <cstdint>
#include <limits>

#include <gtest/gtest.h>

namespace oasis::formats {
namespace {

TEST(ModelSize, CountsEachChoiceWithOneEdgeAtLeast) {
  // 24 + 8 bytes per choice, 4 per state: the sequential reader.
  EXPECT_EQ(least_reading_bytes({.states = 10, .choices = 100}, std::nullopt), 100U * 32 + 40);
  // Declared edges beyond the choices count at 8 bytes each.
  EXPECT_EQ(least_reading_bytes({.states = 10, .choices = 100, .edges = 300}, std::nullopt),
            100U * 24 + 300 * 8 + 40);
  // A Markov chain's header gives rows (edges) only.
  EXPECT_EQ(least_reading_bytes({.states = 10, .edges = 300}, std::nullopt), 300U * 8 + 40);
}

TEST(ModelSize, ARankHoldsItsShareRoundedUp) {
  // 16 + 8 bytes per choice and 4 per state, over ceil(n / P).
  EXPECT_EQ(least_reading_bytes({.states = 10, .choices = 101}, 4), 26U * 24 + 3 * 4);
  EXPECT_EQ(least_reading_bytes({.states = 10, .choices = 101}, 1), 101U * 24 + 10 * 4);
}

TEST(ModelSize, SaturatesInsteadOfWrapping) {
  const std::uint64_t huge = std::numeric_limits<std::uint64_t>::max();
  EXPECT_EQ(least_reading_bytes({.states = huge, .choices = huge}, std::nullopt), huge);
  ReadOptions options;
  options.memory_budget = std::uint64_t{1} << 40;
  EXPECT_TRUE(memory_refusal({.states = 1, .choices = huge}, options));
}

TEST(ModelSize, NoBudgetRefusesNothingAndAFittingModelPasses) {
  ReadOptions options;
  EXPECT_FALSE(memory_refusal({.states = 4'000'000'000U, .choices = 1'000'000'000'000U}, options));
  options.memory_budget = 3200 + 40;
  EXPECT_FALSE(memory_refusal({.states = 10, .choices = 100}, options));
  options.memory_budget = 3200 + 39;
  const auto refusal = memory_refusal({.states = 10, .choices = 100}, options);
  ASSERT_TRUE(refusal);
  EXPECT_EQ(*refusal,
            "reading it takes at least 3240 bytes, more than the memory budget of 3239 bytes "
            "(raise it with --memory-budget)");
}

TEST(ModelSize, StateCountsNameTheLimitThatRefusedThem) {
  ReadOptions options;
  EXPECT_FALSE(state_count_refusal("4294967294", limits::kMaxStates, options));
  EXPECT_EQ(state_count_refusal("4294967295", 4294967295U, options),
            "4294967295 states, more than the 4294967294 that oasis can number (states are "
            "numbered with 32 bits; no option raises this)");
  options.max_states = 100;
  EXPECT_FALSE(state_count_refusal("100", 100, options));
  EXPECT_EQ(state_count_refusal("101", 101, options),
            "101 states, more than the limit of 100 (raise it with --max-states)");
}

}  // namespace
}  // namespace oasis::formats
