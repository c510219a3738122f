#include "sfm_pruning/geometry/opengv_relative_pose.hpp"

#include <algorithm>

#include <gtest/gtest.h>

#include "geometry/synthetic_scene.hpp"
#include "sfm_pruning/geometry/so3.hpp"

namespace sfm_pruning {
namespace {

double RotationError(const RelativePose& a, const RelativePose& b) {
  return LogSO3(a.rotation.transpose() * b.rotation).norm();
}
double DirectionError(const RelativePose& a, const RelativePose& b) {
  return AngleBetweenVectors(a.translation, b.translation);
}

// Fraction of the true inliers that the estimator kept.
double InlierRecall(const testing::SyntheticScene& scene, const std::vector<int>& inliers) {
  int true_total = 0, true_found = 0;
  for (size_t k = 0; k < scene.is_outlier.size(); ++k) {
    if (scene.is_outlier[k]) continue;
    ++true_total;
    if (std::binary_search(inliers.begin(), inliers.end(), static_cast<int>(k))) ++true_found;
  }
  return static_cast<double>(true_found) / true_total;
}

TEST(OpenGVRelativePose, NoiseFreeRecoversThePoseInOurConvention) {
  // The convention test: the truth comes from pose.hpp's RelativePoseBetween, normalised.
  for (const auto solver : {RelativePoseOptions::Solver::kStewenius, RelativePoseOptions::Solver::kNister}) {
    for (uint32_t seed = 1; seed <= 5; ++seed) {
      // {points, pixel noise, outlier ratio, distortion, seed}
      const testing::SyntheticScene scene = testing::MakeSyntheticScene(2, {200, 0.0, 0.0, true, seed});
      RelativePoseOptions options;
      options.solver = solver;
      const RelativePoseResult result = EstimateRelativePose(scene.bearings[0], scene.bearings[1], options);
      ASSERT_TRUE(result.success) << result.reason;
      const RelativePose truth = testing::TrueRelativePose(scene);
      EXPECT_LT(RotationError(result.relative_pose, truth), 1e-6) << "seed " << seed;
      EXPECT_LT(DirectionError(result.relative_pose, truth), 1e-6) << "seed " << seed;
      EXPECT_NEAR(result.relative_pose.translation.norm(), 1.0, 1e-12);
      EXPECT_EQ(result.num_inliers, static_cast<int>(scene.points.size()));
      EXPECT_EQ(result.num_inliers_in_front, result.num_inliers);
    }
  }
}

TEST(OpenGVRelativePose, NoisyWithOutliers) {
  for (uint32_t seed = 1; seed <= 5; ++seed) {
    // {points, pixel noise, outlier ratio, distortion, seed}
    const testing::SyntheticScene scene = testing::MakeSyntheticScene(2, {200, 0.5, 0.25, true, seed});
    const RelativePoseResult result = EstimateRelativePose(scene.bearings[0], scene.bearings[1]);
    ASSERT_TRUE(result.success) << result.reason;
    const RelativePose truth = testing::TrueRelativePose(scene);
    EXPECT_LT(RadToDeg(RotationError(result.relative_pose, truth)), 0.5) << "seed " << seed;
    EXPECT_LT(RadToDeg(DirectionError(result.relative_pose, truth)), 0.5) << "seed " << seed;
    EXPECT_GE(InlierRecall(scene, result.inliers), 0.95) << "seed " << seed;
    EXPECT_TRUE(std::is_sorted(result.inliers.begin(), result.inliers.end()));
  }
}

// Model choice by precision on a scene without a competing structure: whichever model is kept,
// it is right and its inliers are selected at the full threshold, so none of the true matches the
// single-threshold estimate keeps is lost (a tight threshold alone would lose the noisier ones).
TEST(OpenGVRelativePose, PrecisionCheckKeepsTheRightModelAndTheFullThresholdsInliers) {
  for (uint32_t seed = 1; seed <= 5; ++seed) {
    // {points, pixel noise, outlier ratio, distortion, seed}
    const testing::SyntheticScene scene = testing::MakeSyntheticScene(2, {200, 0.5, 0.25, true, seed});
    const RelativePoseResult single = EstimateRelativePose(scene.bearings[0], scene.bearings[1]);
    RelativePoseOptions options;
    options.precision_check_ratio = 0.25;
    const RelativePoseResult checked = EstimateRelativePose(scene.bearings[0], scene.bearings[1], options);
    RelativePoseOptions tight = options;
    tight.precision_check_ratio = 0.0;
    tight.max_angular_error_deg *= options.precision_check_ratio;
    const RelativePoseResult tight_only = EstimateRelativePose(scene.bearings[0], scene.bearings[1], tight);
    ASSERT_TRUE(single.success && checked.success && tight_only.success);
    const RelativePose truth = testing::TrueRelativePose(scene);
    EXPECT_LT(RadToDeg(RotationError(checked.relative_pose, truth)), 0.5) << "seed " << seed;
    EXPECT_LT(RadToDeg(DirectionError(checked.relative_pose, truth)), 0.5) << "seed " << seed;
    EXPECT_GE(InlierRecall(scene, checked.inliers), InlierRecall(scene, single.inliers) - 0.01) << "seed " << seed;
    EXPECT_GT(checked.num_inliers, tight_only.num_inliers) << "seed " << seed;
    EXPECT_GT(checked.num_ransac_iterations, single.num_ransac_iterations) << "both thresholds ran";
  }
}

TEST(OpenGVRelativePose, MinimalSamplesCopeWithALowInlierRatio) {
  // 35 % inliers: hopeless for 8-correspondence samples (0.35^8 = 2e-4), routine for 5.
  // {points, pixel noise, outlier ratio, distortion, seed}
  const testing::SyntheticScene scene = testing::MakeSyntheticScene(2, {400, 0.5, 0.65, true, 1});
  const RelativePoseResult result = EstimateRelativePose(scene.bearings[0], scene.bearings[1]);
  ASSERT_TRUE(result.success) << result.reason;
  const RelativePose truth = testing::TrueRelativePose(scene);
  EXPECT_LT(RadToDeg(RotationError(result.relative_pose, truth)), 0.5);
  EXPECT_LT(RadToDeg(DirectionError(result.relative_pose, truth)), 0.5);
  EXPECT_GE(InlierRecall(scene, result.inliers), 0.95);
  EXPECT_LT(result.num_ransac_iterations, 3000);
}

TEST(OpenGVRelativePose, SameSeedSameOutput) {
  // {points, pixel noise, outlier ratio, distortion, seed}
  const testing::SyntheticScene scene = testing::MakeSyntheticScene(2, {200, 1.0, 0.4, true, 1});
  RelativePoseOptions options;
  options.ransac.seed = 42;
  const RelativePoseResult a = EstimateRelativePose(scene.bearings[0], scene.bearings[1], options);
  const RelativePoseResult b = EstimateRelativePose(scene.bearings[0], scene.bearings[1], options);
  ASSERT_TRUE(a.success);
  EXPECT_EQ(a.relative_pose.rotation, b.relative_pose.rotation);  // bitwise
  EXPECT_EQ(a.relative_pose.translation, b.relative_pose.translation);
  EXPECT_EQ(a.inliers, b.inliers);
  EXPECT_EQ(a.num_ransac_iterations, b.num_ransac_iterations);
}

TEST(OpenGVRelativePose, FailsWithAReasonOnBadInput) {
  const std::vector<Eigen::Vector3d> few(4, Eigen::Vector3d(0, 0, 1));
  const RelativePoseResult too_few = EstimateRelativePose(few, few);
  EXPECT_FALSE(too_few.success);
  EXPECT_NE(too_few.reason.find("too few correspondences"), std::string::npos) << too_few.reason;
  const RelativePoseResult mismatched = EstimateRelativePose(few, std::vector<Eigen::Vector3d>(5));
  EXPECT_FALSE(mismatched.success);
  EXPECT_NE(mismatched.reason.find("size"), std::string::npos) << mismatched.reason;
}

}  // namespace
}  // namespace sfm_pruning
