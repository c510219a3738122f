#include "sfm_pruning/global/rotation_averaging.hpp"

#include <algorithm>
#include <chrono>
#include <iterator>

#include <gtest/gtest.h>

#include "global/rotation_test_scene.hpp"
#include "sfm_pruning/view_graph/components.hpp"

namespace sfm_pruning {
namespace {

using testing::AlignedRotationErrorsDeg;
using testing::MakeRotationScene;
using testing::MaxValue;
using testing::MeanValue;
using testing::RotationScene;
using testing::RotationSceneOptions;

std::vector<IndexT> Keys(const std::map<IndexT, Eigen::Matrix3d>& rotations) {
  std::vector<IndexT> keys;
  for (const auto& [id, R] : rotations) keys.push_back(id);
  return keys;
}

TEST(EstimateGlobalRotations, NoiseFreeGraphRecoversTruthUpToGlobalRotation) {
  RotationSceneOptions scene_options;
  scene_options.num_views = 300;
  RotationScene scene = MakeRotationScene(scene_options);
  std::map<IndexT, Eigen::Matrix3d> rotations;
  const RotationAveragingResult result =
      EstimateGlobalRotations(&scene.graph, RotationAveragingOptions{}, &rotations);

  ASSERT_TRUE(result.success) << result.failure_reason;
  EXPECT_TRUE(result.converged);
  EXPECT_FALSE(result.initialized_from_input);
  EXPECT_EQ(Keys(rotations), Keys(scene.truth));
  EXPECT_TRUE(result.dropped_views.empty());
  EXPECT_TRUE(result.filtered_edges.empty());
  EXPECT_LT(MaxValue(AlignedRotationErrorsDeg(scene.truth, rotations)), 1e-6);
  EXPECT_LT(result.residuals.max_deg, 1e-6);
  EXPECT_EQ(result.residuals.num_edges, scene.graph.NumValidEdges());
  // The gauge is the spanning tree's root, which stays at the identity.
  EXPECT_TRUE(rotations.at(result.gauge_view).isApprox(Eigen::Matrix3d::Identity(), 1e-12));
}

TEST(EstimateGlobalRotations, RecoversRotationsWithTwentyPercentCorruptedEdges) {
  RotationSceneOptions scene_options;
  scene_options.num_views = 300;
  scene_options.chords_per_view = 10;
  scene_options.noise_deg = 0.5;
  scene_options.outlier_fraction = 0.2;
  RotationScene scene = MakeRotationScene(scene_options);
  ASSERT_GT(scene.corrupted.size(), 500u);
  std::map<IndexT, Eigen::Matrix3d> rotations;
  const RotationAveragingResult result =
      EstimateGlobalRotations(&scene.graph, RotationAveragingOptions{}, &rotations);

  ASSERT_TRUE(result.success) << result.failure_reason;
  EXPECT_TRUE(result.converged);
  EXPECT_EQ(Keys(rotations), Keys(scene.truth));
  const std::map<IndexT, double> errors = AlignedRotationErrorsDeg(scene.truth, rotations);
  std::cout << "mean " << MeanValue(errors) << " max " << MaxValue(errors) << " l1 "
            << result.num_l1_iterations << " irls " << result.num_irls_iterations << " cg "
            << result.num_linear_solver_iterations << " res " << result.residuals.mean_deg << " "
            << result.residuals.median_deg << " " << result.residuals.max_deg << "\n";
  EXPECT_LT(MeanValue(errors), 0.1);
  EXPECT_LT(MaxValue(errors), 0.25);
  // Exactly the corrupted edges are filtered, each recorded with its residual.
  EXPECT_EQ(std::set<ViewPair>(result.filtered_edges.begin(), result.filtered_edges.end()),
            scene.corrupted);
  for (const ViewPair& pair : result.filtered_edges) {
    const ViewGraphEdge* edge = scene.graph.FindEdge(pair.first, pair.second);
    ASSERT_NE(edge, nullptr);
    EXPECT_FALSE(edge->is_valid);
    EXPECT_EQ(edge->invalidation.reason, EdgeInvalidReason::kRotationResidual);
    EXPECT_GT(edge->invalidation.value, 10.0);
    EXPECT_EQ(edge->invalidation.threshold, 10.0);
  }
  EXPECT_LT(result.residuals.max_deg, 2.0);
  EXPECT_GT(result.residuals_before_filtering.max_deg, 10.0);
}

TEST(EstimateGlobalRotations, TimesTwoThousandViews) {
  RotationSceneOptions scene_options;
  scene_options.num_views = 2000;
  scene_options.chords_per_view = 5;
  scene_options.noise_deg = 1.0;
  scene_options.outlier_fraction = 0.1;
  RotationScene scene = MakeRotationScene(scene_options);
  std::map<IndexT, Eigen::Matrix3d> rotations;
  const auto start = std::chrono::steady_clock::now();
  const RotationAveragingResult result =
      EstimateGlobalRotations(&scene.graph, RotationAveragingOptions{}, &rotations);
  const double seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  ASSERT_TRUE(result.success) << result.failure_reason;
  std::cout << "2000 views, " << scene.graph.NumEdges() << " edges: " << seconds << " s, l1 "
            << result.num_l1_iterations << " irls " << result.num_irls_iterations << " cg "
            << result.num_linear_solver_iterations << " err mean "
            << MeanValue(AlignedRotationErrorsDeg(scene.truth, rotations)) << " max "
            << MaxValue(AlignedRotationErrorsDeg(scene.truth, rotations)) << "\n";
}

}  // namespace
}  // namespace sfm_pruning
