// The direction check against the capture path's model on a generated street whose facades repeat
// along the walk: the far pairs that matched a facade a period away keep a true rotation (the
// rotation check cannot see them) and point to the wrong place; the model solved from the pairs of
// capture neighbours places every view without them.
#include <gtest/gtest.h>

#include <cmath>
#include <set>

#include "../global/engine_test_scene.hpp"
#include "sfm_pruning/global/view_graph_builder.hpp"
#include "sfm_pruning/pruning/capture_path_directions.hpp"
#include "sfm_pruning/sfm/pose.hpp"

namespace sfm_pruning::testing {
namespace {

// A development scene of the family benchmark (seed 1 of family_street: 38 views walking
// obliquely past a row of three facade designs repeated with gaps, 18 % unique texture).
const SyntheticScene& RepeatedFacades() {
  static const SyntheticScene scene = []() {
    SyntheticSceneOptions options;
    options.scene = "family_street";
    options.seed = 1;
    return GenerateSyntheticScene(options);
  }();
  return scene;
}

const ViewGraph& VerifiedGraph() {
  static const ViewGraph graph = BuildViewGraphFromMatches({}, Listing(RepeatedFacades()), RepeatedFacades().features,
                                                           RepeatedFacades().putative_matches);
  return graph;
}

// Degrees between an edge's verified direction and the true one, R_j (c_i - c_j).
double TrueDirectionErrorDeg(const SyntheticScene& scene, const ViewPair& pair, const ViewGraphEdge& edge) {
  const SfmData& truth = scene.ground_truth;
  const Pose& pose_i = truth.PoseOf(truth.views.at(pair.first));
  const Pose& pose_j = truth.PoseOf(truth.views.at(pair.second));
  return RadToDeg(
      AngleBetweenVectors(edge.relative_pose.translation, pose_j.rotation * (pose_i.center - pose_j.center)));
}

CaptureOrderOptions Sequential() {
  CaptureOrderOptions options;
  options.use = CaptureOrderOptions::Use::kSequential;
  return options;
}

TEST(CapturePathDirections, FarPairsMatchedAPeriodAwayAreRemovedAndTrueOnesKept) {
  const SyntheticScene& scene = RepeatedFacades();
  const ViewGraph& graph = VerifiedGraph();
  const CaptureOrderOptions options = Sequential();
  const CaptureOrder order(options, graph);
  const CapturePathDirectionCheck check =
      CheckDirectionsAgainstCapturePath(options, order, graph, GlobalEngineOptions(), Listing(scene), scene.features);
  ASSERT_TRUE(check.solved);
  ASSERT_TRUE(check.applied);
  EXPECT_EQ(check.num_path_pieces, 1u);
  EXPECT_EQ(check.num_path_views, scene.ground_truth.views.size());
  EXPECT_LT(check.path_residual_deg, 5.0);  // measured: 2.8

  std::set<ViewPair> removed;
  for (const CapturePathDeviation& deviation : check.removed) {
    removed.insert(deviation.pair);
    EXPECT_GT(deviation.places_apart, options.path_window_views);
    EXPECT_GT(deviation.deviation_deg, deviation.bound_deg);
    EXPECT_GE(deviation.bound_deg, options.path_max_direction_deviation_deg);
  }
  // Every far pair whose direction is right is kept, and nearly every far pair that points more
  // than 30 degrees off is removed (measured: 0 right ones removed, every wrong one removed).
  size_t wrong = 0;
  size_t wrong_removed = 0;
  graph.ForEachValidEdge([&](const ViewPair& pair, const ViewGraphEdge& edge) {
    if (order.PlacesApart(pair.first, pair.second) <= options.path_window_views) return;
    const double error_deg = TrueDirectionErrorDeg(scene, pair, edge);
    if (error_deg < 5.0) {
      EXPECT_EQ(removed.count(pair), 0u) << pair.first << "-" << pair.second;
    }
    if (error_deg > 30.0) {
      ++wrong;
      wrong_removed += removed.count(pair);
    }
  });
  ASSERT_GT(wrong, 50u);
  EXPECT_GE(static_cast<double>(wrong_removed), 0.95 * static_cast<double>(wrong));
}

TEST(CapturePathDirections, APathModelThatDisagreesWithItsOwnEdgesJudgesNothing) {
  const SyntheticScene& scene = RepeatedFacades();
  const ViewGraph& graph = VerifiedGraph();
  CaptureOrderOptions options = Sequential();
  // A bound below the path edges' own median residual: the model cannot tell a twin from its error.
  options.path_max_direction_deviation_deg = 0.5;
  const CapturePathDirectionCheck check = CheckDirectionsAgainstCapturePath(
      options, CaptureOrder(options, graph), graph, GlobalEngineOptions(), Listing(scene), scene.features);
  EXPECT_TRUE(check.solved);
  EXPECT_FALSE(check.applied);
  EXPECT_GT(check.path_residual_deg, options.path_max_direction_deviation_deg);
  EXPECT_TRUE(check.removed.empty());
}

TEST(CapturePathDirections, NothingIsSolvedWithoutTheOrderOrWhenOff) {
  const SyntheticScene& scene = RepeatedFacades();
  const ViewGraph& graph = VerifiedGraph();
  CaptureOrderOptions unordered;
  unordered.use = CaptureOrderOptions::Use::kUnordered;
  const CapturePathDirectionCheck without_order = CheckDirectionsAgainstCapturePath(
      unordered, CaptureOrder(unordered, graph), graph, GlobalEngineOptions(), Listing(scene), scene.features);
  EXPECT_FALSE(without_order.solved);
  EXPECT_TRUE(without_order.removed.empty());

  CaptureOrderOptions off = Sequential();
  off.path_max_direction_deviation_deg = 0.0;
  const CapturePathDirectionCheck when_off = CheckDirectionsAgainstCapturePath(
      off, CaptureOrder(off, graph), graph, GlobalEngineOptions(), Listing(scene), scene.features);
  EXPECT_FALSE(when_off.solved);
  EXPECT_TRUE(when_off.removed.empty());
}

}  // namespace
}  // namespace sfm_pruning::testing
