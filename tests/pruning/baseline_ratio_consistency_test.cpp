// The baseline-ratio test (baseline_ratio_consistency.hpp, consistency_tests.hpp's (c)) on exact
// data: four cameras on an arc, every pair an exact edge.
#include <gtest/gtest.h>

#include <cmath>

#include "pruning/pruning_test_scene.hpp"
#include "sfm_pruning/pruning/consistency_tests.hpp"

namespace sfm_pruning {
namespace {

using testing::MakePruningTestScene;
using testing::PruningTestScene;
using testing::RandomSimilarity;

PruningTestScene FullyConnectedScene() {
  PruningTestScene scene = MakePruningTestScene(4, 40, 5);
  for (IndexT a = 0; a < 4; ++a) {
    for (IndexT b = a + 1; b < 4; ++b) scene.AddExactEdge(a, b);
  }
  return scene;
}

double TrueRatio(const PruningTestScene& scene, IndexT i, IndexT j, IndexT k) {
  return (scene.poses[k].center - scene.poses[i].center).norm() / (scene.poses[j].center - scene.poses[i].center).norm();
}

TEST(BaselineRatios, ExactEdgesMeasureTheTrueRatioInAnyFrame) {
  const PruningTestScene scene = FullyConnectedScene();
  const SubgraphSolution solution = scene.Solution({0, 1, 2, 3}, RandomSimilarity(3, 4.0));
  const std::vector<BaselineRatioCheck> checks =
      MeasureBaselineRatios(scene.graph, solution, scene.views_and_intrinsics, scene.features);
  ASSERT_EQ(checks.size(), 12u);  // 4 views, 3 edges each: 3 pairs of edges per view
  for (const BaselineRatioCheck& check : checks) {
    EXPECT_EQ(check.num_common_points, 40u);
    EXPECT_NEAR(check.measured_ratio, TrueRatio(scene, check.view_i, check.view_j, check.view_k), 1e-6);
    EXPECT_NEAR(check.implied_ratio, check.measured_ratio, 1e-6);
    EXPECT_NEAR(check.Factor(), 1.0, 1e-6);
  }
}

TEST(BaselineRatios, ACameraMovedAlongItsBaselineFailsEveryTripletThroughIt) {
  const PruningTestScene scene = FullyConnectedScene();
  SubgraphSolution solution = scene.Solution({0, 1, 2, 3}, Similarity3());
  // View 3 slides towards view 0 to 60 % of its distance: every edge direction from 0 is kept,
  // so the paper's e_t at view 0 cannot see it, but the distance |c_0 - c_3| shrinks by 1 / 0.6.
  Pose& moved = solution.poses.at(3);
  moved.center = scene.poses[0].center + 0.6 * (scene.poses[3].center - scene.poses[0].center);
  ConsistencyTestOptions options;
  options.test_loops = options.test_relative_rotation = options.test_relative_translation = false;
  options.max_baseline_ratio_factor = 1.25;
  ConsistencyReport report;
  TestBaselineRatios(scene.graph, solution, scene.views_and_intrinsics, scene.features, options, &report);
  EXPECT_FALSE(report.consistent);
  bool found_at_view_0 = false;
  for (const ConsistencyViolation& violation : report.violations) {
    EXPECT_EQ(violation.test, ConsistencyTest::kBaselineRatio);
    ASSERT_EQ(violation.loop.size(), 3u);
    const bool through_3 = violation.loop[0] == 3 || violation.loop[1] == 3 || violation.loop[2] == 3;
    EXPECT_TRUE(through_3);
    EXPECT_GT(violation.value, 1.25);
    EXPECT_DOUBLE_EQ(violation.threshold, 1.25);
    if (violation.loop[0] == 0) {
      found_at_view_0 = true;
      EXPECT_NEAR(violation.value, 1.0 / 0.6, 1e-6);  // 0: (1, 3) and (2, 3)
    }
  }
  EXPECT_TRUE(found_at_view_0);
}

TEST(BaselineRatios, OffAtZeroAndSilentOnARightSolution) {
  const PruningTestScene scene = FullyConnectedScene();
  SubgraphSolution solution = scene.Solution({0, 1, 2, 3}, RandomSimilarity(8, 0.3));
  ConsistencyReport report;
  ConsistencyTestOptions options;
  EXPECT_DOUBLE_EQ(options.max_baseline_ratio_factor, 1.25);  // on by default
  options.max_baseline_ratio_factor = 0.0;
  solution.poses.at(3).center *= 2.0;  // wrong, but the test is off
  TestBaselineRatios(scene.graph, solution, scene.views_and_intrinsics, scene.features, options, &report);
  EXPECT_TRUE(report.consistent);
  EXPECT_TRUE(report.violations.empty());

  options.max_baseline_ratio_factor = 1.01;
  const SubgraphSolution right = scene.Solution({0, 1, 2, 3}, RandomSimilarity(8, 0.3));
  TestBaselineRatios(scene.graph, right, scene.views_and_intrinsics, scene.features, options, &report);
  EXPECT_TRUE(report.consistent);
  EXPECT_TRUE(report.violations.empty());
}

}  // namespace
}  // namespace sfm_pruning
