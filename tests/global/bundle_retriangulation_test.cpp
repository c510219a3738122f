#include "sfm_pruning/global/retriangulation.hpp"

#include <gtest/gtest.h>

#include "bundle_test_scene.hpp"
#include "sfm_pruning/global/bundle_observations.hpp"

namespace sfm_pruning {
namespace {

using bundle_test::Scene;
using bundle_test::SceneOptions;

double SumSquaredErrors(const SfmData& data, const Landmark& landmark) {
  double sum = 0.0;
  for (const PosedObservation& obs : PosedObservationsOf(data, landmark)) {
    sum += std::pow(ReprojectionErrorPx(obs, landmark.X), 2);
  }
  return sum;
}

TEST(Retriangulation, RestoresPerturbedPointsFromExactObservations) {
  SceneOptions scene_options;
  scene_options.num_points = 300;
  const Scene scene = bundle_test::MakeScene(scene_options);
  SfmData data = scene.truth;
  bundle_test::PerturbPoints(0.1, scene.radius, 31, &data);
  const RetriangulationResult result = RetriangulateLandmarks({}, nullptr, &data);
  EXPECT_EQ(result.num_landmarks_updated, 300u);
  EXPECT_EQ(result.num_landmarks_unchanged, 0u);
  double max_relative_error = 0.0;
  for (const auto& [id, landmark] : data.structure) {
    max_relative_error =
        std::max(max_relative_error, (landmark.X - scene.truth.structure.at(id).X).norm() / scene.radius);
  }
  EXPECT_LT(max_relative_error, 1e-3);
}

TEST(Retriangulation, NeverIncreasesTheReprojectionError) {
  const SceneOptions scene_options = bundle_test::NoisySceneOptions(300);
  const Scene scene = bundle_test::MakeScene(scene_options);
  SfmData data = scene.truth;
  RetriangulateLandmarks({}, nullptr, &data);
  for (const auto& [id, landmark] : data.structure) {
    EXPECT_LE(SumSquaredErrors(data, landmark), SumSquaredErrors(scene.truth, scene.truth.structure.at(id))) << id;
  }
}

TEST(Retriangulation, CompletesTracksAndRestoresLandmarks) {
  SceneOptions scene_options;
  scene_options.num_points = 100;
  const Scene scene = bundle_test::MakeScene(scene_options);
  SfmData data = scene.truth;
  std::map<IndexT, Landmark> removed;
  // Landmark 0: one good observation was removed, and one wrong one (30 px off) from another view.
  Landmark& first = data.structure.at(0);
  const IndexT good_view = first.observations.begin()->first;
  const IndexT bad_view = std::next(first.observations.begin())->first;
  removed[0].observations[good_view] = first.observations.at(good_view);
  removed[0].observations[bad_view] = first.observations.at(bad_view);
  removed[0].observations[bad_view].x += Eigen::Vector2d(30.0, 0.0);
  first.observations.erase(good_view);
  first.observations.erase(bad_view);
  // Landmark 1: removed entirely; landmark 2: removed entirely, with an inconsistent observation.
  removed[1] = data.structure.at(1);
  removed[2] = data.structure.at(2);
  removed[2].observations.begin()->second.x += Eigen::Vector2d(0.0, 25.0);
  data.structure.erase(1);
  data.structure.erase(2);

  const RetriangulationResult result = RetriangulateLandmarks({}, &removed, &data);
  EXPECT_EQ(data.structure.at(0).observations.count(good_view), 1u);
  EXPECT_EQ(data.structure.at(0).observations.count(bad_view), 0u);
  ASSERT_EQ(data.structure.count(1), 1u);
  EXPECT_LT((data.structure.at(1).X - scene.truth.structure.at(1).X).norm(), 1e-6);
  EXPECT_EQ(data.structure.count(2), 0u);
  EXPECT_EQ(result.num_landmarks_restored, 1u);
  EXPECT_EQ(result.num_observations_restored, 1u + scene.truth.structure.at(1).observations.size());
}

TEST(Retriangulation, WithoutPosesNothingChanges) {
  SfmData data = bundle_test::MakeScene({}).truth;
  data.poses.clear();
  const SfmData before = data;
  const RetriangulationResult result = RetriangulateLandmarks({}, nullptr, &data);
  EXPECT_EQ(result.num_landmarks_updated, 0u);
  EXPECT_TRUE(data == before);
}

}  // namespace
}  // namespace sfm_pruning
