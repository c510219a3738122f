// Scaling benchmark of EstimateGlobalRotations at the size of large collections (10,000 views,
// ~50,000 edges). Disabled by default (it takes a few seconds); run it with
//   test_global_rotation --gtest_also_run_disabled_tests --gtest_filter='*Benchmark*'
#include <chrono>
#include <iostream>

#include <gtest/gtest.h>

#include "global/rotation_test_scene.hpp"
#include "sfm_pruning/global/rotation_averaging.hpp"

namespace sfm_pruning {
namespace {

TEST(RotationAveragingBenchmark, DISABLED_TenThousandViewsFiftyThousandEdges) {
  testing::RotationSceneOptions scene_options;
  scene_options.num_views = 10000;
  scene_options.chords_per_view = 4;  // ring + 4 chords per view: ~50k edges
  scene_options.noise_deg = 1.0;
  scene_options.outlier_fraction = 0.1;
  testing::RotationScene scene = testing::MakeRotationScene(scene_options);
  std::map<IndexT, Eigen::Matrix3d> rotations;
  const auto start = std::chrono::steady_clock::now();
  const RotationAveragingResult result =
      EstimateGlobalRotations(&scene.graph, RotationAveragingOptions{}, &rotations);
  const double seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  ASSERT_TRUE(result.success) << result.failure_reason;
  const std::map<IndexT, double> errors = testing::AlignedRotationErrorsDeg(scene.truth, rotations);
  std::cout << scene.truth.size() << " views, " << scene.graph.NumEdges() << " edges: " << seconds
            << " s; L1 " << result.num_l1_iterations << " + IRLS " << result.num_irls_iterations
            << " iterations, " << result.num_linear_solver_iterations << " CG iterations; error mean "
            << testing::MeanValue(errors) << " deg, max " << testing::MaxValue(errors) << " deg; "
            << result.filtered_edges.size() << " of " << scene.corrupted.size()
            << " corrupted edges filtered\n";
  EXPECT_TRUE(result.converged);
}


TEST(RotationAveragingBenchmark, DISABLED_TenThousandViewsVideoBand) {
  testing::RotationSceneOptions scene_options;
  scene_options.num_views = 10000;
  scene_options.ring_neighbors = 5;
  scene_options.chords_per_view = 0;
  scene_options.noise_deg = 1.0;
  scene_options.outlier_fraction = 0.1;
  testing::RotationScene scene = testing::MakeRotationScene(scene_options);
  std::map<IndexT, Eigen::Matrix3d> rotations;
  const auto start = std::chrono::steady_clock::now();
  const RotationAveragingResult result =
      EstimateGlobalRotations(&scene.graph, RotationAveragingOptions{}, &rotations);
  const double seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  ASSERT_TRUE(result.success) << result.failure_reason;
  const std::map<IndexT, double> errors = testing::AlignedRotationErrorsDeg(scene.truth, rotations);
  std::cout << scene.truth.size() << " views, " << scene.graph.NumEdges() << " edges: " << seconds
            << " s; L1 " << result.num_l1_iterations << " + IRLS " << result.num_irls_iterations
            << " iterations, " << result.num_linear_solver_iterations << " CG iterations; error mean "
            << testing::MeanValue(errors) << " deg, max " << testing::MaxValue(errors) << " deg; "
            << result.filtered_edges.size() << " of " << scene.corrupted.size()
            << " corrupted edges filtered\n";
}

}  // namespace
}  // namespace sfm_pruning
