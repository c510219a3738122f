#include "sfm_pruning/geometry/opengv_absolute_pose.hpp"

#include <algorithm>
#include <cmath>

#include <gtest/gtest.h>

#include "geometry/synthetic_scene.hpp"
#include "sfm_pruning/geometry/so3.hpp"

namespace sfm_pruning {
namespace {

double RotationError(const Pose& a, const Pose& b) { return LogSO3(a.rotation.transpose() * b.rotation).norm(); }

// Distance from the camera to the scene centre: the scale of "1 % of scene depth".
double SceneDepth(const Pose& pose) { return pose.center.norm(); }

TEST(OpenGVAbsolutePose, NoiseFreeRecoversThePose) {
  for (const auto solver : {AbsolutePoseOptions::Solver::kEpnp, AbsolutePoseOptions::Solver::kP3pKneip}) {
    for (uint32_t seed = 1; seed <= 5; ++seed) {
      testing::SyntheticViewOptions scene_options;
      scene_options.seed = seed;
      scene_options.num_points = 100;
      const testing::SyntheticScene scene = testing::MakeSyntheticScene(1, scene_options);
      AbsolutePoseOptions options;
      options.solver = solver;
      const AbsolutePoseResult result = EstimateAbsolutePose(scene.bearings[0], scene.points, options);
      ASSERT_TRUE(result.success) << result.reason;
      const Pose& truth = scene.poses[0];
      EXPECT_LT(RotationError(result.pose, truth), 1e-6) << "seed " << seed;
      EXPECT_LT((result.pose.center - truth.center).norm(), 1e-6 * SceneDepth(truth)) << "seed " << seed;
      EXPECT_EQ(result.num_inliers, 100);
    }
  }
}

TEST(OpenGVAbsolutePose, NoisyWithOutliers) {
  for (const auto solver : {AbsolutePoseOptions::Solver::kEpnp, AbsolutePoseOptions::Solver::kP3pKneip}) {
    for (uint32_t seed = 1; seed <= 5; ++seed) {
      testing::SyntheticViewOptions scene_options;
      scene_options.seed = seed;
      scene_options.num_points = 200;
      scene_options.pixel_noise_std = 0.5;
      scene_options.outlier_ratio = 0.2;
      const testing::SyntheticScene scene = testing::MakeSyntheticScene(1, scene_options);
      AbsolutePoseOptions options;
      options.solver = solver;
      const AbsolutePoseResult result = EstimateAbsolutePose(scene.bearings[0], scene.points, options);
      ASSERT_TRUE(result.success) << result.reason;
      const Pose& truth = scene.poses[0];
      EXPECT_LT(RadToDeg(RotationError(result.pose, truth)), 0.5) << "seed " << seed;
      EXPECT_LT((result.pose.center - truth.center).norm(), 0.01 * SceneDepth(truth)) << "seed " << seed;
      // Every kept correspondence that is a true outlier must be one that happens to fit.
      int true_inliers_found = 0;
      int true_inliers = 0;
      for (size_t k = 0; k < scene.is_outlier.size(); ++k) {
        if (scene.is_outlier[k]) continue;
        ++true_inliers;
        if (std::binary_search(result.inliers.begin(), result.inliers.end(), static_cast<int>(k))) {
          ++true_inliers_found;
        }
      }
      EXPECT_GE(true_inliers_found, 0.95 * true_inliers) << "seed " << seed;
    }
  }
}

TEST(OpenGVAbsolutePose, PixelThresholdBecomesAnAngle) {
  AbsolutePoseOptions options;
  EXPECT_DOUBLE_EQ(AbsolutePoseThresholdRad(options), DegToRad(options.max_angular_error_deg));
  options.max_reprojection_error_px = 4.0;
  options.focal_length_px = 1000.0;
  EXPECT_DOUBLE_EQ(AbsolutePoseThresholdRad(options), std::atan(0.004));
}

TEST(OpenGVAbsolutePose, SameSeedSameOutput) {
  testing::SyntheticViewOptions scene_options;
  scene_options.pixel_noise_std = 1.0;
  scene_options.outlier_ratio = 0.3;
  const testing::SyntheticScene scene = testing::MakeSyntheticScene(1, scene_options);
  AbsolutePoseOptions options;
  options.seed = 7;
  const AbsolutePoseResult a = EstimateAbsolutePose(scene.bearings[0], scene.points, options);
  const AbsolutePoseResult b = EstimateAbsolutePose(scene.bearings[0], scene.points, options);
  ASSERT_TRUE(a.success);
  EXPECT_EQ(a.pose.rotation, b.pose.rotation);
  EXPECT_EQ(a.pose.center, b.pose.center);
  EXPECT_EQ(a.inliers, b.inliers);
}

TEST(OpenGVAbsolutePose, FailsWithAReasonOnTooFewCorrespondences) {
  const std::vector<Eigen::Vector3d> bearings(5, Eigen::Vector3d(0, 0, 1));
  const std::vector<Eigen::Vector3d> points(5, Eigen::Vector3d(0, 0, 3));
  const AbsolutePoseResult result = EstimateAbsolutePose(bearings, points);
  EXPECT_FALSE(result.success);
  EXPECT_NE(result.reason.find("too few correspondences"), std::string::npos) << result.reason;
}

}  // namespace
}  // namespace sfm_pruning
