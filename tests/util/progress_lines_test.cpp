#include "sfm_pruning/util/progress_lines.hpp"

#include <gtest/gtest.h>

#include <string>
#include <vector>

namespace sfm_pruning::testing {
namespace {

struct Recorder {
  double now = 0.0;
  std::vector<std::string> lines;
  ProgressCallback Callback(double interval) {
    return ProgressLines([this](const std::string& line) { lines.push_back(line); }, interval,
                         [this]() { return now; });
  }
};

TEST(ProgressLines, LongStagesSayWhereTheyAreAndShortOnesStayQuiet) {
  Recorder recorder;
  const ProgressCallback progress = recorder.Callback(10.0);
  // A stage of 3 s: nothing.
  for (size_t k = 0; k <= 3; ++k) {
    recorder.now = static_cast<double>(k);
    progress("tracks", k, 3);
  }
  EXPECT_TRUE(recorder.lines.empty());
  // A stage of 50 items at one per second, starting at t = 10: a line every 10 s, then the end.
  for (size_t k = 0; k <= 50; ++k) {
    recorder.now = 10.0 + static_cast<double>(k);
    progress("features", k, 50);
  }
  ASSERT_EQ(recorder.lines.size(), 5u);
  EXPECT_EQ(recorder.lines[0], "features: 20% (10/50), 10 s elapsed, about 40 s left");
  EXPECT_EQ(recorder.lines[3], "features: 80% (40/50), 40 s elapsed, about 10 s left");
  EXPECT_EQ(recorder.lines[4], "features: done (50/50) in 50 s");
}

TEST(ProgressLines, NothingDoneYetGivesNoEstimate) {
  Recorder recorder;
  const ProgressCallback progress = recorder.Callback(5.0);
  progress("bundle adjustment", 0, 2);
  recorder.now = 6.0;
  progress("bundle adjustment", 0, 2);
  ASSERT_EQ(recorder.lines.size(), 1u);
  EXPECT_EQ(recorder.lines[0], "bundle adjustment: 0% (0/2), 6 s elapsed");
}

}  // namespace
}  // namespace sfm_pruning::testing
