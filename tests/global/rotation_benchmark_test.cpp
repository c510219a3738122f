// Scaling benchmark of EstimateGlobalRotations at the size of large collections (10,000 views,
// ~50,000 edges), on the two graph shapes that stress different solvers (see
// rotation_increment_solver.hpp). Disabled by default (a few seconds each); run with
//   test_global_rotation --gtest_also_run_disabled_tests --gtest_filter='*Benchmark*'
#include <gtest/gtest.h>

#include <iostream>

#include "global/rotation_test_scene.hpp"

namespace sfm_pruning {
namespace {

void RunBenchmark(const testing::RotationSceneOptions& scene_options) {
  testing::RotationScene scene = testing::MakeRotationScene(scene_options);
  const testing::TimedRotationAveraging run = testing::RunTimedRotationAveraging(&scene);
  ASSERT_TRUE(run.result.success) << run.result.failure_reason;
  EXPECT_TRUE(run.result.converged);
  std::cout << run.Summary(scene) << "\n";
}

// Unordered collection: ring + 4 random chords per view (expander-like, ~50k edges).
TEST(RotationAveragingBenchmark, DISABLED_TenThousandViewsRandomChords) {
  RunBenchmark(testing::SceneOptions(10000, 4, 1.0, 0.1));
}

// Video: each view linked to the next 5 (a band, 50k edges).
TEST(RotationAveragingBenchmark, DISABLED_TenThousandViewsVideoBand) {
  testing::RotationSceneOptions scene_options = testing::SceneOptions(10000, 0, 1.0, 0.1);
  scene_options.ring_neighbors = 5;
  RunBenchmark(scene_options);
}

}  // namespace
}  // namespace sfm_pruning
