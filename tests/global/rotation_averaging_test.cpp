#include "sfm_pruning/global/rotation_averaging.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <iostream>
#include <iterator>
#include <set>
#include <stdexcept>
#include <string>

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
using testing::SceneOptions;

std::vector<IndexT> Keys(const std::map<IndexT, Eigen::Matrix3d>& rotations) {
  std::vector<IndexT> keys;
  for (const auto& [id, R] : rotations) keys.push_back(id);
  return keys;
}

TEST(EstimateGlobalRotations, NoiseFreeGraphRecoversTruthUpToGlobalRotation) {
  const RotationSceneOptions scene_options = SceneOptions(300, 3);
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
  const RotationSceneOptions scene_options = SceneOptions(300, 10, 0.5, 0.2);
  RotationScene scene = MakeRotationScene(scene_options);
  ASSERT_GT(scene.corrupted.size(), 500u);
  std::map<IndexT, Eigen::Matrix3d> rotations;
  const RotationAveragingResult result =
      EstimateGlobalRotations(&scene.graph, RotationAveragingOptions{}, &rotations);

  ASSERT_TRUE(result.success) << result.failure_reason;
  EXPECT_TRUE(result.converged);
  EXPECT_EQ(Keys(rotations), Keys(scene.truth));
  const std::map<IndexT, double> errors = AlignedRotationErrorsDeg(scene.truth, rotations);
  EXPECT_LT(MeanValue(errors), 0.1);
  EXPECT_LT(MaxValue(errors), 0.25);
  // Exactly the corrupted edges are filtered, each recorded with its residual.
  EXPECT_EQ(std::set<ViewPair>(result.filtered_edges.begin(), result.filtered_edges.end()), scene.corrupted);
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

  // The outliers have no influence left: the estimate equals the one computed without them
  // (the corrupted edges invalidated beforehand) far below the noise-limited error above.
  RotationScene clean = MakeRotationScene(scene_options);
  for (const ViewPair& pair : clean.corrupted) {
    clean.graph.InvalidateEdge(pair.first, pair.second, {EdgeInvalidReason::kOther, 0.0, 0.0});
  }
  std::map<IndexT, Eigen::Matrix3d> clean_rotations;
  ASSERT_TRUE(EstimateGlobalRotations(&clean.graph, RotationAveragingOptions{}, &clean_rotations).success);
  EXPECT_LT(MaxValue(AlignedRotationErrorsDeg(clean_rotations, rotations)), 0.01);
}

TEST(EstimateGlobalRotations, IsDeterministic) {
  const RotationSceneOptions scene_options = SceneOptions(150, 4, 1.0, 0.2);
  RotationScene first = MakeRotationScene(scene_options);
  RotationScene second = MakeRotationScene(scene_options);
  std::map<IndexT, Eigen::Matrix3d> first_rotations;
  std::map<IndexT, Eigen::Matrix3d> second_rotations;
  const RotationAveragingResult a =
      EstimateGlobalRotations(&first.graph, RotationAveragingOptions{}, &first_rotations);
  const RotationAveragingResult b =
      EstimateGlobalRotations(&second.graph, RotationAveragingOptions{}, &second_rotations);
  ASSERT_TRUE(a.success);
  EXPECT_EQ(Keys(first_rotations), Keys(second_rotations));
  for (const auto& [id, R] : first_rotations) EXPECT_EQ(R, second_rotations.at(id)) << "view " << id;
  EXPECT_EQ(a.filtered_edges, b.filtered_edges);
  EXPECT_EQ(a.num_l1_iterations, b.num_l1_iterations);
  EXPECT_EQ(a.num_irls_iterations, b.num_irls_iterations);
  EXPECT_EQ(a.num_linear_solver_iterations, b.num_linear_solver_iterations);
  EXPECT_EQ(a.residuals.mean_deg, b.residuals.mean_deg);
}

TEST(EstimateGlobalRotations, GraphWithoutEdgesReportsFailure) {
  const std::map<IndexT, Eigen::Matrix3d> untouched = {{3, Eigen::Matrix3d::Identity()}};
  for (size_t num_nodes : {0, 1, 4}) {
    ViewGraph graph;
    for (IndexT id = 0; id < num_nodes; ++id) graph.AddNode(id);
    std::map<IndexT, Eigen::Matrix3d> rotations = untouched;
    const RotationAveragingResult result =
        EstimateGlobalRotations(&graph, RotationAveragingOptions{}, &rotations);
    EXPECT_FALSE(result.success);
    EXPECT_EQ(result.failure_reason, "no valid edge");
    EXPECT_EQ(rotations.size(), 1u);  // unchanged
    EXPECT_EQ(result.dropped_views.size(), num_nodes);
  }
  // Only invalid edges: the same.
  const RotationSceneOptions scene_options = SceneOptions(5, 3);
  RotationScene scene = MakeRotationScene(scene_options);
  for (const ViewPair& pair : scene.graph.ValidEdgePairs()) {
    scene.graph.InvalidateEdge(pair.first, pair.second, {EdgeInvalidReason::kTooFewInliers, 3, 30});
  }
  std::map<IndexT, Eigen::Matrix3d> rotations;
  const RotationAveragingResult result =
      EstimateGlobalRotations(&scene.graph, RotationAveragingOptions{}, &rotations);
  EXPECT_FALSE(result.success);
  EXPECT_TRUE(rotations.empty());
}

TEST(EstimateGlobalRotations, NullArgumentsThrow) {
  ViewGraph graph;
  std::map<IndexT, Eigen::Matrix3d> rotations;
  EXPECT_THROW(EstimateGlobalRotations(nullptr, {}, &rotations), std::invalid_argument);
  EXPECT_THROW(EstimateGlobalRotations(&graph, {}, nullptr), std::invalid_argument);
}

// Two components (40 and 10 views) and an isolated view: only the largest is estimated.
TEST(EstimateGlobalRotations, DisconnectedGraphEstimatesLargestComponentOnly) {
  RotationSceneOptions large_options;
  large_options.num_views = 40;
  large_options.noise_deg = 0.5;
  RotationScene scene = MakeRotationScene(large_options);
  RotationSceneOptions small_options;
  small_options.num_views = 10;
  small_options.first_id = 1000;
  small_options.seed = 2;
  const RotationScene small = MakeRotationScene(small_options);
  for (const auto& [pair, edge] : small.graph.Edges()) scene.graph.AddEdge(pair, edge);
  scene.graph.AddNode(5000);
  const size_t num_edges = scene.graph.NumValidEdges();

  for (bool remove : {false, true}) {
    ViewGraph graph = scene.graph;
    RotationAveragingOptions options;
    options.remove_dropped_views_from_graph = remove;
    std::map<IndexT, Eigen::Matrix3d> rotations;
    const RotationAveragingResult result = EstimateGlobalRotations(&graph, options, &rotations);
    ASSERT_TRUE(result.success) << result.failure_reason;
    EXPECT_EQ(Keys(rotations), Keys(scene.truth));
    EXPECT_EQ(result.estimated_views, Keys(scene.truth));
    std::vector<IndexT> expected_dropped = Keys(small.truth);
    expected_dropped.push_back(5000);
    EXPECT_EQ(result.dropped_views, expected_dropped);
    EXPECT_LT(MaxValue(AlignedRotationErrorsDeg(scene.truth, rotations)), 0.5);
    if (remove) {
      EXPECT_EQ(std::vector<IndexT>(graph.Nodes().begin(), graph.Nodes().end()), Keys(scene.truth));
    } else {
      EXPECT_EQ(graph.NumNodes(), 51u);
      EXPECT_EQ(graph.NumValidEdges(), num_edges);  // nothing to filter, nothing erased
    }
  }
}

TEST(EstimateGlobalRotations, UsesGivenRotationsAsInitialisation) {
  const RotationSceneOptions scene_options = SceneOptions(80, 5, 0.5, 0.2);
  RotationScene scene = MakeRotationScene(scene_options);
  // The truth in another world frame, each rotation off by 5 degrees.
  std::mt19937 rng(11);
  const Eigen::Matrix3d world = testing::UniformRandomRotation(&rng);
  std::map<IndexT, Eigen::Matrix3d> initial;
  for (const auto& [id, R] : scene.truth) {
    initial[id] = R * world * testing::RandomRotationOfAngle(&rng, DegToRad(5.0));
  }

  std::map<IndexT, Eigen::Matrix3d> rotations = initial;
  const RotationAveragingResult result =
      EstimateGlobalRotations(&scene.graph, RotationAveragingOptions{}, &rotations);
  ASSERT_TRUE(result.success) << result.failure_reason;
  EXPECT_TRUE(result.initialized_from_input);
  EXPECT_EQ(result.gauge_view, scene.truth.begin()->first);  // the smallest id stays fixed
  EXPECT_EQ(rotations.at(result.gauge_view), initial.at(result.gauge_view));
  EXPECT_LT(MeanValue(AlignedRotationErrorsDeg(scene.truth, rotations)), 0.15);
  EXPECT_EQ(std::set<ViewPair>(result.filtered_edges.begin(), result.filtered_edges.end()), scene.corrupted);

  // A partial initialisation is ignored: the spanning tree is used.
  RotationScene again = MakeRotationScene(scene_options);
  std::map<IndexT, Eigen::Matrix3d> partial = initial;
  partial.erase(partial.begin());
  const RotationAveragingResult from_tree =
      EstimateGlobalRotations(&again.graph, RotationAveragingOptions{}, &partial);
  ASSERT_TRUE(from_tree.success);
  EXPECT_FALSE(from_tree.initialized_from_input);
  EXPECT_EQ(Keys(partial), Keys(scene.truth));
}

// A threshold far below the noise cuts most edges, and with them views: whatever is cut, the
// result must stay consistent with the graph.
TEST(EstimateGlobalRotations, FilteringKeepsLargestRemainingComponent) {
  const RotationSceneOptions scene_options = SceneOptions(60, 2, 2.0);
  RotationScene scene = MakeRotationScene(scene_options);
  RotationAveragingOptions options;
  options.max_relative_rotation_error_deg = 0.5;
  std::map<IndexT, Eigen::Matrix3d> rotations;
  const RotationAveragingResult result = EstimateGlobalRotations(&scene.graph, options, &rotations);
  ASSERT_TRUE(result.success) << result.failure_reason;
  ASSERT_FALSE(result.dropped_views.empty());
  ASSERT_GT(result.estimated_views.size(), 1u);

  EXPECT_EQ(Keys(rotations), result.estimated_views);
  std::vector<IndexT> all;
  std::set_union(result.estimated_views.begin(), result.estimated_views.end(), result.dropped_views.begin(),
                 result.dropped_views.end(), std::back_inserter(all));
  EXPECT_EQ(all, Keys(scene.truth));
  EXPECT_EQ(all.size(), result.estimated_views.size() + result.dropped_views.size());
  // The estimated views form one component of the filtered graph.
  const ViewGraph kept = scene.graph.InducedSubgraph(
      std::set<IndexT>(result.estimated_views.begin(), result.estimated_views.end()));
  EXPECT_EQ(ConnectedComponents(kept).size(), 1u);
  EXPECT_EQ(result.residuals.num_edges, kept.NumValidEdges());
  EXPECT_LE(result.residuals.max_deg, 0.5);
  size_t num_invalid = 0;
  for (const auto& [pair, edge] : scene.graph.Edges()) {
    if (edge.is_valid) continue;
    ++num_invalid;
    EXPECT_EQ(edge.invalidation.reason, EdgeInvalidReason::kRotationResidual);
    EXPECT_GT(edge.invalidation.value, 0.5);
  }
  EXPECT_EQ(num_invalid, result.filtered_edges.size());
  EXPECT_EQ(result.residuals_before_filtering.num_edges, scene.graph.NumEdges());
}

// Noise-free inliers and 20% outliers. Filtering + the re-solve on the kept edges is exact;
// without filtering the outliers keep a small pull (Geman-McClure weights never reach 0).
TEST(EstimateGlobalRotations, FilteringCanBeDisabled) {
  const RotationSceneOptions scene_options = SceneOptions(60, 4, 0.0, 0.2);
  RotationScene filtered = MakeRotationScene(scene_options);
  std::map<IndexT, Eigen::Matrix3d> filtered_rotations;
  const RotationAveragingResult with_filter =
      EstimateGlobalRotations(&filtered.graph, RotationAveragingOptions{}, &filtered_rotations);
  ASSERT_TRUE(with_filter.success);
  EXPECT_EQ(with_filter.filtered_edges.size(), filtered.corrupted.size());
  EXPECT_LT(MaxValue(AlignedRotationErrorsDeg(filtered.truth, filtered_rotations)), 1e-6);
  EXPECT_LT(with_filter.residuals.max_deg, 1e-6);

  RotationScene scene = MakeRotationScene(scene_options);
  RotationAveragingOptions options;
  options.filter_edges = false;
  std::map<IndexT, Eigen::Matrix3d> rotations;
  const RotationAveragingResult result = EstimateGlobalRotations(&scene.graph, options, &rotations);
  ASSERT_TRUE(result.success);
  EXPECT_TRUE(result.filtered_edges.empty());
  EXPECT_EQ(scene.graph.NumValidEdges(), scene.graph.NumEdges());
  EXPECT_EQ(result.residuals.max_deg, result.residuals_before_filtering.max_deg);
  EXPECT_GT(result.residuals.max_deg, 10.0);  // the outliers are still there
  const double unfiltered_error = MaxValue(AlignedRotationErrorsDeg(scene.truth, rotations));
  EXPECT_GT(unfiltered_error, 1e-6);
  EXPECT_LT(unfiltered_error, 0.05);
}

TEST(EstimateGlobalRotations, ReportsProgressPerIteration) {
  const RotationSceneOptions scene_options = SceneOptions(50, 3, 1.0);
  RotationScene scene = MakeRotationScene(scene_options);
  std::map<std::string, int> calls;
  bool within_total = true;
  const ProgressCallback progress = [&](const std::string& stage, size_t done, size_t total) {
    ++calls[stage];
    within_total = within_total && done <= total;
  };
  std::map<IndexT, Eigen::Matrix3d> rotations;
  const RotationAveragingResult result =
      EstimateGlobalRotations(&scene.graph, RotationAveragingOptions{}, &rotations, progress);
  ASSERT_TRUE(result.success);
  EXPECT_TRUE(within_total);
  EXPECT_EQ(calls["rotation averaging (L1)"], result.num_l1_iterations);
  EXPECT_EQ(calls["rotation averaging (IRLS)"], result.num_irls_iterations);
}

// Scale check at 2,000 views / ~12,000 edges (a dense 6000 x 6000 system would take far
// longer than this whole test). The 10,000-view timings are bench/cpp/rotation_averaging_bench.cpp.
TEST(EstimateGlobalRotations, TimesTwoThousandViews) {
  RotationScene scene = MakeRotationScene(SceneOptions(2000, 5, 1.0, 0.1));
  const testing::TimedRotationAveraging run = testing::RunTimedRotationAveraging(&scene);
  ASSERT_TRUE(run.result.success) << run.result.failure_reason;
  EXPECT_TRUE(run.result.converged);
  EXPECT_LT(MeanValue(run.errors_deg), 0.25);
  EXPECT_EQ(std::set<ViewPair>(run.result.filtered_edges.begin(), run.result.filtered_edges.end()),
            scene.corrupted);
  RecordProperty("seconds", std::to_string(run.seconds));
  std::cout << run.Summary(scene) << "\n";
}

}  // namespace
}  // namespace sfm_pruning
