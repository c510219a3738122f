#include <random>

#include <gtest/gtest.h>

#include "positioning_synthetic_scene.hpp"
#include "sfm_pruning/global/translation_averaging.hpp"

namespace sfm_pruning {
namespace {

// Replaces the translation of every `stride`-th valid edge by a random unit direction; returns
// how many were corrupted.
size_t CorruptDirections(ViewGraph* graph, size_t stride, uint64_t seed) {
  std::mt19937_64 rng(seed);
  std::normal_distribution<double> gaussian(0.0, 1.0);
  size_t count = 0;
  for (const ViewPair& pair : graph->ValidEdgePairs()) {
    if (count++ % stride != 0) continue;
    const double x = gaussian(rng), y = gaussian(rng), z = gaussian(rng);
    graph->MutableEdge(pair.first, pair.second)->relative_pose.translation = Eigen::Vector3d(x, y, z).normalized();
  }
  return (count + stride - 1) / stride;
}

TEST(TranslationAveraging, DirectionOfEdgeMatchesTheCentres) {
  // The derivation in translation_averaging.hpp, checked on one true edge: c_j - c_i is parallel
  // to -R_j^T t_ij.
  const testing::PositioningScene scene = testing::MakePositioningScene({});
  const auto& [pair, edge] = *scene.graph.Edges().begin();
  const Eigen::Vector3d baseline = scene.true_poses.at(pair.second).center - scene.true_poses.at(pair.first).center;
  const Eigen::Vector3d direction = -scene.rotations.at(pair.second).transpose() * edge.relative_pose.translation;
  EXPECT_NEAR(AngleBetweenVectors(baseline, direction), 0.0, 1e-12);
}

TEST(TranslationAveraging, RecoversExactCentresAndTriangulatesTheTracks) {
  testing::PositioningScene scene = testing::MakePositioningScene({});
  const std::vector<Track> tracks = BuildTracks(scene.graph).tracks;
  const TranslationAveragingResult result = PositionCamerasByTranslationAveraging(
      {}, scene.graph, scene.rotations, tracks, scene.features, &scene.sfm_data);
  ASSERT_TRUE(result.positioning.success) << result.positioning.message;
  EXPECT_EQ(result.num_edges, scene.graph.NumValidEdges());
  EXPECT_EQ(result.num_rejected_edges, 0u);
  EXPECT_EQ(result.positioning.num_positioned_views, scene.true_poses.size());
  EXPECT_LT(testing::MaxRelativeCenterError(scene.true_poses, scene.sfm_data), 1e-4);
  EXPECT_EQ(result.positioning.num_landmarks, tracks.size());
  EXPECT_EQ(result.positioning.num_filtered_observations, 0u);
}

TEST(TranslationAveraging, TenPercentCorruptedDirectionsAreRejected) {
  testing::PositioningScene scene = testing::MakePositioningScene({});
  const size_t num_corrupted = CorruptDirections(&scene.graph, 10, 3);
  const TranslationAveragingResult result = PositionCamerasByTranslationAveraging(
      {}, scene.graph, scene.rotations, BuildTracks(scene.graph).tracks, scene.features, &scene.sfm_data);
  ASSERT_TRUE(result.positioning.success) << result.positioning.message;
  EXPECT_LT(testing::MaxRelativeCenterError(scene.true_poses, scene.sfm_data), 1e-4);
  // Random directions that happen to fall within the threshold stay; the rest go.
  EXPECT_LE(result.num_rejected_edges, num_corrupted);
  EXPECT_GE(result.num_rejected_edges, num_corrupted * 9 / 10);
}

TEST(TranslationAveraging, OutlierObservationsAreFilteredFromTheTriangulatedPoints) {
  testing::PositioningSceneOptions options;
  options.pixel_noise_std = 1.0;
  options.outlier_ratio = 0.05;
  testing::PositioningScene scene = testing::MakePositioningScene(options);
  const TranslationAveragingResult result = PositionCamerasByTranslationAveraging(
      {}, scene.graph, scene.rotations, BuildTracks(scene.graph).tracks, scene.features, &scene.sfm_data);
  ASSERT_TRUE(result.positioning.success) << result.positioning.message;
  // The directions are exact, so are the centres; the points see the noise and outliers.
  EXPECT_LT(testing::MaxRelativeCenterError(scene.true_poses, scene.sfm_data), 1e-4);
  const testing::KeptObservations kept = testing::CountKeptObservations(scene, scene.sfm_data);
  EXPECT_LT(kept.num_outliers_kept, kept.num_outliers / 5);
  EXPECT_GT(kept.num_inliers_kept, kept.num_inliers * 95 / 100);
}

TEST(TranslationAveraging, DeterministicForASeed) {
  testing::PositioningSceneOptions options = testing::SmallSceneOptions();
  testing::PositioningScene scene = testing::MakePositioningScene(options);
  CorruptDirections(&scene.graph, 10, 5);
  const std::vector<Track> tracks = BuildTracks(scene.graph).tracks;
  SfmData first = scene.sfm_data, second = scene.sfm_data;
  PositionCamerasByTranslationAveraging({}, scene.graph, scene.rotations, tracks, scene.features, &first);
  PositionCamerasByTranslationAveraging({}, scene.graph, scene.rotations, tracks, scene.features, &second);
  EXPECT_TRUE(first == second);
}

TEST(TranslationAveraging, FailsWithoutEdges) {
  testing::PositioningScene scene = testing::MakePositioningScene({});
  const SfmData before = scene.sfm_data;
  const TranslationAveragingResult result =
      PositionCamerasByTranslationAveraging({}, ViewGraph(), scene.rotations, {}, scene.features, &scene.sfm_data);
  EXPECT_FALSE(result.positioning.success);
  EXPECT_TRUE(scene.sfm_data == before);
}

}  // namespace
}  // namespace sfm_pruning
