// ProgressBar: draws the final state on destruction when enabled, nothing when disabled; set_done never
// moves backwards.
#include "util/progress_bar.hpp"

#include <gtest/gtest.h>

#include <string>

namespace {

TEST(ProgressBar, FinalStateAndSilence) {
  testing::internal::CaptureStderr();
  {
    exactvis::ProgressBar bar("work", 10, true);
    bar.advance(3);
    bar.set_done(8);
    bar.set_done(5);  // ignored: not backwards
    bar.advance();
  }
  const std::string drawn = testing::internal::GetCapturedStderr();
  EXPECT_NE(drawn.find("work ["), std::string::npos) << drawn;
  EXPECT_NE(drawn.find("(9/10)\n"), std::string::npos) << drawn;

  testing::internal::CaptureStderr();
  {
    exactvis::ProgressBar bar("quiet", 10, false);
    bar.advance(10);
  }
  EXPECT_EQ(testing::internal::GetCapturedStderr(), "");
}

}  // namespace
