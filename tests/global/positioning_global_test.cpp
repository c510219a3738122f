#include <algorithm>

#include <gtest/gtest.h>

#include "positioning_synthetic_scene.hpp"
#include "sfm_pruning/global/global_positioning.hpp"
#include "sfm_pruning/util/error.hpp"

namespace sfm_pruning {
namespace {

std::vector<Track> TracksOf(const testing::PositioningScene& scene) { return BuildTracks(scene.graph).tracks; }

TEST(GlobalPositioning, RecoversExactSceneUpToSimilarity) {
  testing::PositioningScene scene = testing::MakePositioningScene({});
  const std::vector<Track> tracks = TracksOf(scene);
  const PositioningResult result =
      PositionCamerasAndPoints({}, scene.rotations, tracks, scene.features, &scene.sfm_data);
  ASSERT_TRUE(result.success) << result.message;
  EXPECT_EQ(result.num_positioned_views, scene.true_poses.size());
  EXPECT_EQ(scene.sfm_data.poses.size(), scene.true_poses.size());
  EXPECT_LT(testing::MaxRelativeCenterError(scene.true_poses, scene.sfm_data), 1e-4);
  EXPECT_EQ(result.num_filtered_observations, 0u);
  EXPECT_EQ(result.num_landmarks, tracks.size());
  // Rotations are passed through; observations carry the feature id and its pixel.
  for (const auto& [view_id, pose] : scene.true_poses) {
    EXPECT_TRUE(scene.sfm_data.poses.at(scene.sfm_data.views.at(view_id).id_pose).rotation.isApprox(pose.rotation));
  }
  for (const auto& [landmark_id, landmark] : scene.sfm_data.structure) {
    ASSERT_LT(landmark_id, tracks.size());
    EXPECT_EQ(landmark.observations.size(), tracks[landmark_id].size());
    for (const auto& [view_id, observation] : landmark.observations) {
      EXPECT_EQ(observation.id_feat, tracks[landmark_id].at(view_id));
      EXPECT_EQ(observation.x, scene.features.at(view_id).Position(observation.id_feat));
    }
  }
}

TEST(GlobalPositioning, NoiseAndOutliersStayWithinOnePercent) {
  testing::PositioningSceneOptions options;
  options.pixel_noise_std = 1.0;
  options.outlier_ratio = 0.05;
  testing::PositioningScene scene = testing::MakePositioningScene(options);
  const PositioningResult result =
      PositionCamerasAndPoints({}, scene.rotations, TracksOf(scene), scene.features, &scene.sfm_data);
  ASSERT_TRUE(result.success) << result.message;
  EXPECT_LT(testing::MaxRelativeCenterError(scene.true_poses, scene.sfm_data), 0.01);

  // The angular filter removes most outliers and keeps almost every inlier.
  const testing::KeptObservations kept = testing::CountKeptObservations(scene, scene.sfm_data);
  EXPECT_GT(result.num_filtered_observations, kept.num_outliers / 2);
  EXPECT_LT(kept.num_outliers_kept, kept.num_outliers / 5);
  EXPECT_GT(kept.num_inliers_kept, kept.num_inliers * 9 / 10);
}

TEST(GlobalPositioning, SubsampledSolveTriangulatesTheOtherTracks) {
  testing::PositioningScene scene = testing::MakePositioningScene({});
  const std::vector<Track> tracks = TracksOf(scene);
  GlobalPositioningOptions options;
  options.subsampling = {60, 4};  // each view sees about 480 tracks
  const PositioningResult result =
      PositionCamerasAndPoints(options, scene.rotations, tracks, scene.features, &scene.sfm_data);
  ASSERT_TRUE(result.success) << result.message;
  EXPECT_LT(result.num_solved_tracks, tracks.size() / 2);
  EXPECT_GE(result.num_solved_tracks, 60u);
  EXPECT_EQ(result.num_positioned_views, scene.true_poses.size());
  EXPECT_LT(testing::MaxRelativeCenterError(scene.true_poses, scene.sfm_data), 1e-4);
  // Every track has its point: solved or triangulated from the solved cameras (exact data).
  EXPECT_EQ(result.num_landmarks, tracks.size());
  EXPECT_EQ(result.num_filtered_observations, 0u);
}

TEST(GlobalPositioning, DeterministicForASeed) {
  testing::PositioningSceneOptions options = testing::SmallSceneOptions();
  options.pixel_noise_std = 0.5;
  testing::PositioningScene scene = testing::MakePositioningScene(options);
  SfmData first = scene.sfm_data, second = scene.sfm_data;
  const std::vector<Track> tracks = TracksOf(scene);
  PositionCamerasAndPoints({}, scene.rotations, tracks, scene.features, &first);
  PositionCamerasAndPoints({}, scene.rotations, tracks, scene.features, &second);
  EXPECT_TRUE(first == second);
}

// The small scene with 0.5 px noise and 10 % wrong observations.
testing::PositioningScene NoisySceneWithOutliers() {
  testing::PositioningSceneOptions scene_options = testing::SmallSceneOptions();
  scene_options.pixel_noise_std = 0.5;
  scene_options.outlier_ratio = 0.1;
  return testing::MakePositioningScene(scene_options);
}

TEST(GlobalPositioning, RandomStartsKeepTheStartAgreeingWithMostRays) {
  testing::PositioningScene scene = NoisySceneWithOutliers();
  const std::vector<Track> tracks = TracksOf(scene);
  SfmData single = scene.sfm_data, restarted = scene.sfm_data, again = scene.sfm_data;
  const PositioningResult one = PositionCamerasAndPoints({}, scene.rotations, tracks, scene.features, &single);
  GlobalPositioningOptions options;
  options.solver.num_random_starts = 4;
  const PositioningResult four = PositionCamerasAndPoints(options, scene.rotations, tracks, scene.features, &restarted);
  ASSERT_TRUE(one.success && four.success) << one.message << four.message;

  // One start is the plain solve from the seed, and it is the first of the four.
  EXPECT_EQ(one.num_random_starts, 1);
  ASSERT_EQ(one.consistent_constraints_per_start.size(), 1u);
  ASSERT_EQ(four.consistent_constraints_per_start.size(), 4u);
  EXPECT_EQ(four.consistent_constraints_per_start[0], one.consistent_constraints_per_start[0]);
  // The kept start is one that agrees with the most rays, and every start lands on the scene here
  // (10 % outliers leave one basin), so the choice only moves the result within the noise.
  const auto& counts = four.consistent_constraints_per_start;
  EXPECT_EQ(counts[four.selected_start], *std::max_element(counts.begin(), counts.end()));
  for (const size_t count : counts) EXPECT_GT(count, counts[four.selected_start] * 95 / 100);
  EXPECT_LT(testing::MaxRelativeCenterError(scene.true_poses, restarted), 0.01);
  if (four.selected_start == 0) {
    EXPECT_TRUE(single == restarted);
  }

  // Deterministic for a seed, starts included.
  PositionCamerasAndPoints(options, scene.rotations, tracks, scene.features, &again);
  EXPECT_TRUE(again == restarted);
}

TEST(GlobalPositioning, ScreenedStartsSolveOnlyTheBestOneToTheEnd) {
  testing::PositioningScene scene = NoisySceneWithOutliers();
  const std::vector<Track> tracks = TracksOf(scene);
  SfmData full = scene.sfm_data, screened = scene.sfm_data;
  GlobalPositioningOptions options;
  options.solver.num_random_starts = 4;
  const PositioningResult every = PositionCamerasAndPoints(options, scene.rotations, tracks, scene.features, &full);
  options.solver.start_screening_iterations = 5;
  const PositioningResult best = PositionCamerasAndPoints(options, scene.rotations, tracks, scene.features, &screened);
  ASSERT_TRUE(every.success && best.success) << every.message << best.message;

  // Each start was scored after 5 iterations, the kept one agrees with the most rays then, and
  // finishing it alone reaches the scene as solving every start to the end does.
  ASSERT_EQ(best.consistent_constraints_per_start.size(), 4u);
  const auto& counts = best.consistent_constraints_per_start;
  EXPECT_EQ(counts[best.selected_start], *std::max_element(counts.begin(), counts.end()));
  EXPECT_GT(best.num_solver_iterations, 5);
  EXPECT_LE(best.num_solver_iterations, 5 + options.solver.max_num_iterations + options.solver.max_num_resolve_iterations);
  EXPECT_LT(testing::MaxRelativeCenterError(scene.true_poses, screened), 0.01);
  EXPECT_LT(testing::MaxRelativeCenterError(scene.true_poses, full), 0.01);
}

TEST(GlobalPositioning, FailsWithoutTracksAndLeavesTheSceneUntouched) {
  testing::PositioningScene scene = testing::MakePositioningScene({});
  const SfmData before = scene.sfm_data;
  const PositioningResult result =
      PositionCamerasAndPoints({}, scene.rotations, {}, scene.features, &scene.sfm_data);
  EXPECT_FALSE(result.success);
  EXPECT_FALSE(result.message.empty());
  EXPECT_TRUE(scene.sfm_data == before);
}

TEST(GlobalPositioning, RejectsRigs) {
  testing::PositioningScene scene = testing::MakePositioningScene({});
  scene.sfm_data.views.at(12).id_pose = scene.sfm_data.views.at(10).id_pose;
  const PositioningResult result =
      PositionCamerasAndPoints({}, scene.rotations, TracksOf(scene), scene.features, &scene.sfm_data);
  EXPECT_FALSE(result.success);
  EXPECT_NE(result.message.find("rig"), std::string::npos);
}

TEST(GlobalPositioning, ViewsWithoutRotationAreLeftOut) {
  testing::PositioningScene scene = testing::MakePositioningScene({});
  scene.rotations.erase(10);
  // A first track seen by view 10 and one other view keeps a single positionable observation.
  // Without a subsampling cap it is among the candidates the selection returns, and the k-th solved
  // point must still be the k-th kept track's.
  std::vector<Track> tracks = TracksOf(scene);
  for (const Track& track : tracks) {
    if (track.count(10) == 0) continue;
    const auto other = std::find_if(track.begin(), track.end(), [](const auto& entry) { return entry.first != 10; });
    tracks.insert(tracks.begin(), Track{{10, track.at(10)}, *other});
    break;
  }
  size_t num_kept = 0;
  for (const Track& track : tracks) num_kept += track.size() - track.count(10) >= 2;
  ASSERT_LT(num_kept, tracks.size());
  GlobalPositioningOptions options;
  options.subsampling.max_tracks_per_view = 0;
  const PositioningResult result =
      PositionCamerasAndPoints(options, scene.rotations, tracks, scene.features, &scene.sfm_data);
  ASSERT_TRUE(result.success) << result.message;
  EXPECT_EQ(result.num_landmarks, num_kept);
  EXPECT_EQ(result.num_filtered_observations, 0u);  // exact data: every point on its rays
  EXPECT_EQ(scene.sfm_data.poses.count(scene.sfm_data.views.at(10).id_pose), 0u);
  for (const auto& [landmark_id, landmark] : scene.sfm_data.structure) EXPECT_EQ(landmark.observations.count(10), 0u);
  EXPECT_LT(testing::MaxRelativeCenterError(scene.true_poses, scene.sfm_data), 1e-4);
}

TEST(GlobalPositioning, ReportsProgressPerIteration) {
  testing::PositioningSceneOptions options = testing::SmallSceneOptions();
  testing::PositioningScene scene = testing::MakePositioningScene(options);
  GlobalPositioningOptions positioning;
  std::vector<size_t> iterations;
  positioning.solver.progress = [&](const std::string& stage, size_t done, size_t total) {
    EXPECT_EQ(stage, "global_positioning");
    EXPECT_EQ(total, static_cast<size_t>(positioning.solver.max_num_iterations));
    iterations.push_back(done);
  };
  const PositioningResult result =
      PositionCamerasAndPoints(positioning, scene.rotations, TracksOf(scene), scene.features, &scene.sfm_data);
  ASSERT_TRUE(result.success);
  EXPECT_GE(iterations.size(), static_cast<size_t>(result.num_solver_iterations));
}

TEST(GlobalPositioning, ThrowsOnAMissingFeature) {
  testing::PositioningScene scene = testing::MakePositioningScene({});
  std::vector<Track> tracks = TracksOf(scene);
  tracks[0].begin()->second = 1000000;
  EXPECT_THROW(PositionCamerasAndPoints({}, scene.rotations, tracks, scene.features, &scene.sfm_data), Error);
}

TEST(RayAngularResidualDeg, ZeroOnTheRayAndHalfTurnBehind) {
  PositioningObservation observation;
  observation.ray_world = Eigen::Vector3d(0.0, 0.6, 0.8);
  const Eigen::Vector3d center(1.0, 2.0, 3.0);
  EXPECT_NEAR(RayAngularResidualDeg(observation, center, center + 5.0 * observation.ray_world), 0.0, 1e-12);
  EXPECT_NEAR(RayAngularResidualDeg(observation, center, center - 5.0 * observation.ray_world), 180.0, 1e-12);
  EXPECT_NEAR(RayAngularResidualDeg(observation, center, center + Eigen::Vector3d(1.0, 0.0, 0.0)), 90.0, 1e-12);
}

}  // namespace
}  // namespace sfm_pruning
