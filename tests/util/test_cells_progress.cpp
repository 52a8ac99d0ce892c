// The two-level progress display of `exactvis pvs` (util/cells_progress.hpp): its final line names the cells
// done, the current cell's steps, elapsed and remaining time; disabled, it writes nothing; thread-safe.
#include "util/cells_progress.hpp"

#include <gtest/gtest.h>

#include <thread>
#include <vector>

using namespace exactvis;

TEST(CellsProgress, FinalLineAndSilenceWhenDisabled) {
  testing::internal::CaptureStderr();
  {
    CellsProgress bar("pvs", 3, "triangles", true);
    bar.finish_item();
    bar.start_item(100);
    std::vector<std::thread> workers;
    for (int t = 0; t < 4; ++t)
      workers.emplace_back([&bar, t] {
        for (int i = 1; i <= 10; ++i) bar.item_steps(static_cast<std::uint64_t>(10 * t + i));
      });
    for (auto& w : workers) w.join();
  }
  const std::string out = testing::internal::GetCapturedStderr();
  const std::string last = out.substr(out.rfind('\r') + 1);
  EXPECT_NE(last.find("pvs: cells 1/3"), std::string::npos) << last;
  EXPECT_NE(last.find("cell 40/100 triangles"), std::string::npos) << last;
  EXPECT_NE(last.find("elapsed"), std::string::npos) << last;
  EXPECT_NE(last.find("left"), std::string::npos) << last;
  testing::internal::CaptureStderr();
  {
    CellsProgress quiet("pvs", 3, "triangles", false);
    quiet.start_item(5);
    quiet.item_steps(3);
    quiet.finish_item();
  }
  EXPECT_EQ(testing::internal::GetCapturedStderr(), "");
}
