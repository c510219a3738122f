#include "sfm_pruning/global/structure_filtering.hpp"

#include <set>
#include <utility>

#include <gtest/gtest.h>

#include "bundle_test_scene.hpp"
#include "sfm_pruning/global/bundle_adjustment.hpp"
#include "sfm_pruning/global/bundle_observations.hpp"

namespace sfm_pruning {
namespace {

using bundle_test::Scene;
using bundle_test::SceneOptions;

TEST(StructureFiltering, RemovesPlantedOutliersAfterBundleAdjustment) {
  const SceneOptions scene_options = bundle_test::NoisySceneOptions(500);
  const Scene scene = bundle_test::MakeScene(scene_options);
  ASSERT_GT(scene.outliers.size(), 100u);
  SfmData data = scene.truth;
  bundle_test::PerturbPoses(1.0, 0.01, scene.radius, 21, &data);
  bundle_test::PerturbPoints(0.01, scene.radius, 22, &data);
  ASSERT_TRUE(AdjustBundle({}, &data).success);

  const StructureFilteringResult result = FilterStructure({}, &data);
  std::set<std::pair<IndexT, IndexT>> removed;
  for (const auto& [landmark_id, landmark] : result.removed) {
    for (const auto& [view_id, obs] : landmark.observations) {
      // Only landmarks that were dropped whole carry observations that were not rejected.
      if (data.structure.count(landmark_id) || scene.outliers.count({landmark_id, view_id})) {
        removed.insert({landmark_id, view_id});
      }
    }
  }
  size_t true_positives = 0;
  for (const auto& key : removed) true_positives += scene.outliers.count(key);
  const double precision = static_cast<double>(true_positives) / removed.size();
  const double recall = static_cast<double>(true_positives) / scene.outliers.size();
  EXPECT_GT(precision, 0.95);
  EXPECT_GT(recall, 0.95);
  EXPECT_EQ(result.num_observations_removed_behind, 0u);
  EXPECT_EQ(result.NumObservationsRemoved(), removed.size());
  // The ring sees every point under tens of degrees: nothing is lost to the angle test.
  EXPECT_EQ(result.num_landmarks_removed_angle, 0u);
  EXPECT_EQ(result.num_landmarks_kept + result.NumLandmarksRemoved(), 500u);
}

class StructureFilteringCases : public ::testing::Test {
 protected:
  void SetUp() override {
    SceneOptions scene_options;
    scene_options.num_points = 50;
    data_ = bundle_test::MakeScene(scene_options).truth;
  }
  Observation Exact(IndexT view_id, const Eigen::Vector3d& X) const {
    const View& view = data_.views.at(view_id);
    return {data_.IntrinsicsOf(view).Project(data_.PoseOf(view).ToCamera(X)), 0};
  }
  SfmData data_;
};

TEST_F(StructureFilteringCases, DropsLandmarkWithFewerThanTwoPosedViews) {
  View unposed = data_.views.at(0);
  unposed.id_view = unposed.id_pose = 100;
  data_.views[100] = unposed;
  Landmark lonely;
  lonely.X = Eigen::Vector3d(0.1, 0.2, 0.3);
  lonely.observations[0] = Exact(0, lonely.X);
  lonely.observations[100] = Observation{Eigen::Vector2d(10.0, 20.0), 0};
  data_.structure[1000] = lonely;
  const StructureFilteringResult result = FilterStructure({}, &data_);
  EXPECT_EQ(data_.structure.count(1000), 0u);
  EXPECT_EQ(result.num_landmarks_removed_few_observations, 1u);
  EXPECT_EQ(result.num_landmarks_kept, 50u);
  EXPECT_EQ(result.NumObservationsRemoved(), 0u);
  ASSERT_EQ(result.removed.count(1000), 1u);
  EXPECT_EQ(result.removed.at(1000).observations.size(), 2u);  // kept whole for retriangulation
}

TEST_F(StructureFilteringCases, RemovesObservationsBehindTheCamera) {
  // Camera 10 faces camera 0 across the ring: a point just behind camera 0 is in front of
  // camera 10 and the cameras beside it, but behind camera 0.
  const Pose& pose0 = data_.poses.at(0);
  Landmark landmark;
  landmark.X = pose0.center - 0.5 * pose0.ViewingDirection();
  for (const IndexT view_id : {9u, 10u, 11u}) landmark.observations[view_id] = Exact(view_id, landmark.X);
  landmark.observations[0] = Observation{Eigen::Vector2d(500.0, 400.0), 0};
  data_.structure[1000] = landmark;
  const StructureFilteringResult result = FilterStructure({}, &data_);
  EXPECT_EQ(result.num_observations_removed_behind, 1u);
  ASSERT_EQ(data_.structure.count(1000), 1u);
  EXPECT_EQ(data_.structure.at(1000).observations.size(), 3u);
  EXPECT_EQ(data_.structure.at(1000).observations.count(0), 0u);
}

// COLMAP's ERROR of a point: the mean pixel error of its posed observations.
TEST_F(StructureFilteringCases, LandmarkErrorIsTheMeanReprojectionError) {
  Landmark landmark;
  landmark.X = Eigen::Vector3d(0.1, 0.2, 0.3);
  landmark.observations[0] = Exact(0, landmark.X);
  landmark.observations[1] = Exact(1, landmark.X);
  landmark.observations[1].x += Eigen::Vector2d(3.0, 4.0);  // 5 px off
  data_.structure[1000] = landmark;
  Landmark behind = landmark;
  behind.X = data_.poses.at(0).center - 0.5 * data_.poses.at(0).ViewingDirection();
  data_.structure[1001] = behind;
  Landmark unobserved;
  data_.structure[1002] = unobserved;
  SetLandmarkReprojectionErrors(&data_);
  EXPECT_NEAR(data_.structure.at(1000).error, 2.5, 1e-9);
  EXPECT_EQ(data_.structure.at(1001).error, -1.0);  // infinite: unknown, not a number COLMAP prints
  EXPECT_EQ(data_.structure.at(1002).error, -1.0);
  EXPECT_NEAR(data_.structure.at(0).error, 0.0, 1e-9);
}

TEST_F(StructureFilteringCases, DropsLandmarksUnderTooSmallAnAngle) {
  // Far along camera 0's axis, seen by cameras 0 and 1: about 0.04 degrees of parallax.
  const Pose& pose0 = data_.poses.at(0);
  Landmark far;
  far.X = pose0.center + 5000.0 * pose0.ViewingDirection();
  far.observations[0] = Exact(0, far.X);
  far.observations[1] = Exact(1, far.X);
  data_.structure[1000] = far;
  const StructureFilteringResult result = FilterStructure({}, &data_);
  EXPECT_EQ(data_.structure.count(1000), 0u);
  EXPECT_EQ(result.num_landmarks_removed_angle, 1u);
  EXPECT_EQ(result.num_landmarks_kept, 50u);
}

}  // namespace
}  // namespace sfm_pruning
