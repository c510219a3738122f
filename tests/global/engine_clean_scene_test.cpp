// The GLOBAL engine end to end on a clean synthetic scene: verification, view graph, rotation
// averaging, tracks, positioning, bundle adjustment; scored with the evaluation module.
#include <gtest/gtest.h>

#include "engine_test_scene.hpp"

namespace sfm_pruning::testing {
namespace {

TEST(EngineCleanScene, RegistersEveryViewAccurately) {
  const SyntheticScene& scene = CleanScene();
  const EngineRun run = RunEngineOn(scene, scene.putative_matches);
  ASSERT_TRUE(run.engine.success) << run.engine.message;
  EXPECT_TRUE(run.build.dropped_views.empty());
  EXPECT_EQ(run.engine.num_registered_views, scene.ground_truth.views.size());
  EXPECT_TRUE(run.engine.dropped_views.empty());
  EXPECT_GT(run.engine.num_landmarks, 500u);
  EXPECT_LT(run.engine.final_rms_px, 1.5);
  // Every point carries its mean reprojection error (COLMAP's ERROR), below the RMS bound too.
  for (const auto& [id, landmark] : run.model.structure) {
    EXPECT_GE(landmark.error, 0.0) << id;
    EXPECT_LT(landmark.error, 4.0) << id;
  }
  const EvaluationReport report = EvaluateModel(run.model, scene.ground_truth);
  EXPECT_EQ(report.num_registered_images, scene.ground_truth.views.size());
  EXPECT_GE(AucAt(report, 3.0), 97.0);
  EXPECT_GE(AucAt(report, 10.0), 99.0);
  // Every stage was timed, in order.
  ASSERT_EQ(run.engine.timings.size(), 4u);
  EXPECT_EQ(run.engine.timings.front().stage, "rotation averaging");
  EXPECT_EQ(run.engine.timings.back().stage, "bundle adjustment");
}

// A non-default positioning still registers every view of the clean scene accurately.
void ExpectEveryViewRegisteredAccurately(const GlobalEngineOptions& options) {
  const SyntheticScene& scene = CleanScene();
  const EngineRun run = RunEngineOn(scene, scene.putative_matches, {}, options);
  ASSERT_TRUE(run.engine.success) << run.engine.message;
  EXPECT_EQ(run.engine.num_registered_views, scene.ground_truth.views.size());
  // The structure comes from the union-find tracks whatever the positioning solved with.
  EXPECT_GT(run.engine.num_landmarks, 500u);
  EXPECT_GE(AucAt(EvaluateModel(run.model, scene.ground_truth), 3.0), 97.0);
}

TEST(EngineCleanScene, TranslationAveragingAlsoRegistersEveryView) {
  GlobalEngineOptions options;
  options.positioning = PositioningMethod::kTranslationAveraging;
  ExpectEveryViewRegisteredAccurately(options);
}

TEST(EngineCleanScene, MatchStarPositioningAlsoRegistersEveryView) {
  GlobalEngineOptions options;
  options.positioning_tracks = PositioningTracks::kMatchStars;
  ExpectEveryViewRegisteredAccurately(options);
}

TEST(EngineCleanScene, IterationCapBindsOnlyTheAdjustmentsBeforeTheLast) {
  const SyntheticScene& scene = CleanScene();
  GlobalEngineOptions options;
  options.intermediate_max_num_iterations = 1;
  const EngineRun run = RunEngineOn(scene, scene.putative_matches, {}, options);
  ASSERT_TRUE(run.engine.success) << run.engine.message;
  const std::vector<BundleAdjustmentResult>& adjustments = run.engine.bundle_adjustments;
  ASSERT_EQ(adjustments.size(), static_cast<size_t>(options.num_bundle_rounds) + 1);
  // num_iterations counts Ceres' steps, and Ceres counts its initial evaluation as one.
  for (size_t k = 0; k + 1 < adjustments.size(); ++k) {
    EXPECT_LE(adjustments[k].num_iterations, 2) << "adjustment " << k;
    EXPECT_EQ(adjustments[k].termination, "NO_CONVERGENCE") << "adjustment " << k;
  }
  // The last adjustment is not capped, so it still converges to the clean scene's accuracy.
  EXPECT_GT(adjustments.back().num_iterations, 2);
  EXPECT_EQ(adjustments.back().termination, "CONVERGENCE");
  EXPECT_GE(AucAt(EvaluateModel(run.model, scene.ground_truth), 3.0), 97.0);
}

TEST(EngineCleanScene, SameSeedGivesBitwiseIdenticalPoses) {
  const SyntheticScene& scene = CleanScene();
  ViewGraphBuildOptions build;
  build.num_threads = 2;  // verification results do not depend on the thread count
  const EngineRun first = RunEngineOn(scene, scene.putative_matches, build);
  const EngineRun second = RunEngineOn(scene, scene.putative_matches);
  ASSERT_TRUE(first.engine.success) << first.engine.message;
  ASSERT_EQ(first.model.poses.size(), second.model.poses.size());
  for (const auto& [pose_id, pose] : first.model.poses) {
    const Pose& other = second.model.poses.at(pose_id);
    EXPECT_TRUE(pose.rotation == other.rotation && pose.center == other.center) << "pose " << pose_id;
  }
  EXPECT_EQ(first.model.structure, second.model.structure);
}

TEST(EngineCleanScene, DisconnectedGraphKeepsTheLargestComponentAndReportsTheRest) {
  const SyntheticScene& scene = CleanScene();
  // Cut views 0 and 1 off from everything but each other.
  PairwiseMatches matches;
  for (const auto& [pair, pair_matches] : scene.putative_matches) {
    if ((pair.first < 2) == (pair.second < 2)) matches.emplace(pair, pair_matches);
  }
  const EngineRun run = RunEngineOn(scene, matches);
  ASSERT_TRUE(run.engine.success) << run.engine.message;
  ASSERT_EQ(run.build.dropped_views.size(), 2u);
  EXPECT_EQ(run.build.dropped_views[0].view_id, 0u);
  EXPECT_EQ(run.build.dropped_views[1].reason, "outside the largest component");
  EXPECT_EQ(run.engine.num_registered_views, scene.ground_truth.views.size() - 2);
}

TEST(EngineCleanScene, VerifiedPairsWithoutPosesAreReestimated) {
  const SyntheticScene& scene = CleanScene();
  const SfmData listing = Listing(scene);
  const ViewGraph reference = BuildViewGraphFromMatches({}, listing, scene.features, scene.putative_matches);
  VerifiedPairs verified;
  for (const auto& [pair, edge] : reference.Edges()) verified[pair].inliers = edge.matches;
  ViewGraphBuildReport build;
  const ViewGraph graph = BuildViewGraphFromVerifiedPairs({}, listing, scene.features, verified, &build);
  EXPECT_EQ(graph.NumValidEdges(), reference.NumValidEdges());
  for (const auto& [pair, edge] : graph.Edges()) {
    const RelativePose& expected = reference.Edges().at(pair).relative_pose;
    EXPECT_LT(RadToDeg(RotationAngleBetween(edge.relative_pose.rotation, expected.rotation)), 0.5);
  }
}

TEST(EngineCleanScene, RefiningThePositionedModelReachesTheFullSolvesAccuracy) {
  const SyntheticScene& scene = CleanScene();
  GlobalEngineOptions positioning_only;
  positioning_only.bundle_adjust = false;
  const EngineRun positioned = RunEngineOn(scene, scene.putative_matches, {}, positioning_only);
  ASSERT_TRUE(positioned.engine.success) << positioned.engine.message;
  EXPECT_TRUE(positioned.engine.bundle_adjustments.empty());
  ASSERT_EQ(positioned.engine.timings.size(), 3u);
  EXPECT_EQ(positioned.engine.timings.back().stage, "positioning");

  const SfmData listing = Listing(scene);
  const ViewGraph graph = BuildViewGraphFromMatches({}, listing, scene.features, scene.putative_matches);
  SfmData refined;
  GlobalEngineReport report;
  RefineGlobalModel({}, graph, positioned.model, scene.features, &refined, &report);
  ASSERT_TRUE(report.success) << report.message;
  EXPECT_EQ(report.num_registered_views, scene.ground_truth.views.size());
  EXPECT_GT(report.num_landmarks, 500u);
  EXPECT_LT(report.final_rms_px, 1.5);
  EXPECT_GE(AucAt(EvaluateModel(refined, scene.ground_truth), 3.0), 97.0);
  // No rotation averaging and no positioning: the poses came from the model.
  ASSERT_EQ(report.timings.size(), 3u);
  EXPECT_EQ(report.timings[0].stage, "tracks");
  EXPECT_EQ(report.timings[1].stage, "triangulation from the poses");
  EXPECT_EQ(report.timings[2].stage, "bundle adjustment");
}

TEST(EngineCleanScene, RefiningAModelDropsTheViewsItDidNotPose) {
  const SyntheticScene& scene = CleanScene();
  const EngineRun run = RunEngineOn(scene, scene.putative_matches);
  ASSERT_TRUE(run.engine.success) << run.engine.message;
  SfmData initial = run.model;
  const IndexT unposed = initial.views.begin()->first;
  initial.poses.erase(initial.views.at(unposed).id_pose);

  const SfmData listing = Listing(scene);
  const ViewGraph graph = BuildViewGraphFromMatches({}, listing, scene.features, scene.putative_matches);
  SfmData refined;
  GlobalEngineReport report;
  RefineGlobalModel({}, graph, initial, scene.features, &refined, &report);
  ASSERT_TRUE(report.success) << report.message;
  EXPECT_EQ(report.num_registered_views, scene.ground_truth.views.size() - 1);
  EXPECT_FALSE(refined.IsPosed(unposed));
  ASSERT_EQ(report.dropped_views.size(), 1u);
  EXPECT_EQ(report.dropped_views[0].view_id, unposed);
  EXPECT_EQ(report.dropped_views[0].reason, "not posed by the model refined");
  // The AUC counts the pairs with the unposed view as failures: 19 of the 20 views' 190 pairs.
  const double n = static_cast<double>(scene.ground_truth.views.size());
  EXPECT_GE(AucAt(EvaluateModel(refined, scene.ground_truth), 3.0), 97.0 * (n - 2.0) / n);
}

TEST(EngineCleanScene, EmptyGraphFailsWithNoEdges) {
  const SyntheticScene& scene = CleanScene();
  const SfmData listing = Listing(scene);
  ViewGraphBuildReport build;
  const ViewGraph graph = BuildViewGraphFromMatches({}, listing, scene.features, {}, &build);
  SfmData model;
  GlobalEngineReport report;
  RunGlobalEngine({}, graph, listing, scene.features, &model, &report);
  EXPECT_FALSE(report.success);
  EXPECT_EQ(report.message, "the view graph has no edges");
  EXPECT_TRUE(model.poses.empty());
}

}  // namespace
}  // namespace sfm_pruning::testing
