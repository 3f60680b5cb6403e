// The trial pictures: well-formed SVG with the timeline and the paths, written atomically.
#include "sim/trial_svg.hpp"

#include <filesystem>
#include <fstream>
#include <sstream>

#include <gtest/gtest.h>
#include <unistd.h>

namespace oasis::hw::sim {
namespace {

std::vector<TraceStep> hand_off_trace() {
  std::vector<TraceStep> trace;
  for (int k = 0; k < 50; ++k) {
    TraceStep step;
    step.time_s = 0.2 * k;
    step.true_holder = k < 25 ? 1 : 2;
    step.inferred_holder = k < 27 ? 1 : 2;  // two steps of lag
    step.belief_human1 = k < 27 ? 0.9 : 0.1;
    step.rewarded = k % 10 == 0;
    step.robot = {0.1 * k, 0.0, 0.0};
    step.people = {go1::PlanarPoint{1.0 + 0.1 * k, 0.5}, go1::PlanarPoint{2.0, -0.5 + 0.02 * k}};
    trace.push_back(step);
  }
  return trace;
}

std::size_t count(const std::string& text, const std::string& what) {
  std::size_t n = 0;
  for (std::size_t at = text.find(what); at != std::string::npos; at = text.find(what, at + 1))
    ++n;
  return n;
}

TEST(TrialSvg, HasTheTimelineAndThePaths) {
  const std::string svg = trial_svg(hand_off_trace(), "ours <trial 1>", 3.0);
  EXPECT_EQ(svg.rfind("<svg xmlns=\"http://www.w3.org/2000/svg\"", 0), 0u);
  EXPECT_NE(svg.find("</svg>\n"), std::string::npos);
  EXPECT_EQ(count(svg, "<polyline"), 6u);  // belief, truth, inferred; robot, two people
  EXPECT_NE(svg.find("ours &lt;trial 1&gt;"), std::string::npos);
  EXPECT_EQ(count(svg, "fill=\"#2ca02c\""), 5u);  // the five rewarded steps
}

TEST(TrialSvg, AnEmptyTraceIsStillAPicture) {
  const std::string svg = trial_svg({}, "empty", 3.0);
  EXPECT_NE(svg.find("</svg>"), std::string::npos);
  EXPECT_EQ(count(svg, "<polyline"), 0u);
}

TEST(TrialSvg, IsWrittenThroughATemporaryFile) {
  const std::filesystem::path folder =
      std::filesystem::temp_directory_path() / ("trial_svg_test_" + std::to_string(::getpid()));
  std::filesystem::create_directories(folder);
  const std::filesystem::path path = folder / "trial.svg";
  write_file_atomically(path, "first");
  write_file_atomically(path, "second");
  std::ifstream in(path);
  std::stringstream text;
  text << in.rdbuf();
  EXPECT_EQ(text.str(), "second");
  EXPECT_EQ(std::distance(std::filesystem::directory_iterator(folder),
                          std::filesystem::directory_iterator()),
            1);  // no temporary file left behind
  EXPECT_THROW(write_file_atomically(folder / "missing" / "x.svg", "x"), std::runtime_error);
  std::filesystem::remove_all(folder);
}

}  // namespace
}  // namespace oasis::hw::sim
