// The one shape of the messages programs print outside the diagnostic engine.

#include "support/error_report.hpp"

#include <gtest/gtest.h>

namespace oasis {
namespace {

TEST(ErrorReport, LineIsWhereSeverityAndMessage) {
  EXPECT_EQ(report_line("oasisc", "error", "--format aut writes files"),
            "oasisc: error: --format aut writes files\n");
  EXPECT_EQ(report_line("out/dir", "warning", "x"), "out/dir: warning: x\n");
  EXPECT_EQ(report_line("oasisc: fit noise", "note", "no pairs"),
            "oasisc: fit noise: note: no pairs\n");
}

TEST(ErrorReport, MessagesGoToStandardErrorUnchanged) {
  testing::internal::CaptureStderr();
  report_error("spec.oasis", "bad \"name\"\twith a tab");
  report_warning("oasisc", "context \"a\": above the target");
  report_note("catalog.bin", "checked exactly");
  EXPECT_EQ(testing::internal::GetCapturedStderr(),
            "spec.oasis: error: bad \"name\"\twith a tab\n"
            "oasisc: warning: context \"a\": above the target\n"
            "catalog.bin: note: checked exactly\n");
}

}  // namespace
}  // namespace oasis
