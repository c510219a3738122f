#include "sfm_pruning/global/bundle_adjustment.hpp"

#include <cmath>

#include <gtest/gtest.h>

#include "bundle_test_scene.hpp"

namespace sfm_pruning {
namespace {

using bundle_test::InlierRmsPx;
using bundle_test::Scene;
using bundle_test::SceneOptions;

double MaxRotationErrorDeg(const SfmData& truth, const SfmData& aligned) {
  double max_error = 0.0;
  for (const auto& [id, pose] : aligned.poses) {
    max_error = std::max(max_error, RadToDeg(RotationAngleBetween(pose.rotation, truth.poses.at(id).rotation)));
  }
  return max_error;
}

Scene NoisyScene() {
  return bundle_test::MakeScene(bundle_test::NoisySceneOptions(1000));
}

TEST(BundleAdjustment, RecoversPerturbedPosesAndPointsToNoiseLevel) {
  const Scene scene = NoisyScene();
  SfmData data = scene.truth;
  bundle_test::PerturbPoses(1.0, 0.01, scene.radius, 11, &data);
  bundle_test::PerturbPoints(0.01, scene.radius, 12, &data);
  ASSERT_GT(InlierRmsPx(data, scene), 10.0);  // the perturbation is far above the noise

  const BundleAdjustmentResult result = AdjustBundle({}, &data);
  ASSERT_TRUE(result.success) << result.message;
  EXPECT_EQ(result.num_poses, 20u);
  EXPECT_EQ(result.num_intrinsics, 2u);
  EXPECT_EQ(result.num_landmarks, 1000u);
  EXPECT_EQ(result.num_observations_behind, 0u);
  EXPECT_LT(result.final_cost, result.initial_cost);
  EXPECT_LT(result.final_rms_px, result.initial_rms_px);
  const double inlier_rms = InlierRmsPx(data, scene);
  EXPECT_LE(inlier_rms, 1.2);
  EXPECT_GE(inlier_rms, 0.8);  // a fit below the noise would mean the outliers bent the model
  bundle_test::AlignToTruth(scene.truth, &data);
  EXPECT_LT(MaxRotationErrorDeg(scene.truth, data), 0.05);
}

TEST(BundleAdjustment, RefinesFocalLength) {
  const Scene scene = NoisyScene();
  SfmData data = scene.truth;
  for (auto& [id, intrinsics] : data.intrinsics) intrinsics.SetFocalLength(1.05 * intrinsics.FocalLength());
  bundle_test::PerturbPoints(0.01, scene.radius, 13, &data);
  BundleAdjustmentOptions options;
  options.refine_focal = true;
  const BundleAdjustmentResult result = AdjustBundle(options, &data);
  ASSERT_TRUE(result.success) << result.message;
  for (const auto& [id, intrinsics] : data.intrinsics) {
    const double truth = scene.truth.intrinsics.at(id).FocalLength();
    EXPECT_LT(std::abs(intrinsics.FocalLength() - truth) / truth, 0.005) << "intrinsic " << id;
    // Only the focal was free.
    EXPECT_EQ(intrinsics.PrincipalPoint(), scene.truth.intrinsics.at(id).PrincipalPoint());
    EXPECT_EQ(intrinsics.DistortionParams(), scene.truth.intrinsics.at(id).DistortionParams());
  }
  EXPECT_LE(InlierRmsPx(data, scene), 1.2);
}

TEST(BundleAdjustment, RefinesPrincipalPoint) {
  const Scene scene = NoisyScene();
  SfmData data = scene.truth;
  for (auto& [id, intrinsics] : data.intrinsics) {
    intrinsics.SetPrincipalPoint(intrinsics.PrincipalPoint() + Eigen::Vector2d(12.0, -9.0));  // 15 px
  }
  BundleAdjustmentOptions options;
  options.refine_principal_point = true;
  const BundleAdjustmentResult result = AdjustBundle(options, &data);
  ASSERT_TRUE(result.success) << result.message;
  for (const auto& [id, intrinsics] : data.intrinsics) {
    const Eigen::Vector2d truth = scene.truth.intrinsics.at(id).PrincipalPoint();
    EXPECT_LT((intrinsics.PrincipalPoint() - truth).norm(), 2.0) << "intrinsic " << id;
    EXPECT_EQ(intrinsics.FocalLength(), scene.truth.intrinsics.at(id).FocalLength());
  }
}

// The weak priors on principal point and distortion leave well-observed values to the data, and
// a strong prior holds them at the image centre and zero.
TEST(BundleAdjustment, IntrinsicsPriorsWeighAgainstTheData) {
  const Scene scene = NoisyScene();
  const auto refine = [&](double sigma) {
    SfmData data = scene.truth;
    for (auto& [id, intrinsics] : data.intrinsics) {
      intrinsics.SetPrincipalPoint(intrinsics.PrincipalPoint() + Eigen::Vector2d(12.0, -9.0));
    }
    BundleAdjustmentOptions options;
    options.refine_principal_point = true;
    options.refine_distortion = true;
    options.principal_point_prior_sigma = sigma;
    options.distortion_prior_sigma = sigma;
    const BundleAdjustmentResult result = AdjustBundle(options, &data);
    EXPECT_TRUE(result.success) << result.message;
    return data;
  };
  const SfmData weak = refine(BundleAdjustmentOptions().principal_point_prior_sigma);
  for (const auto& [id, intrinsics] : weak.intrinsics) {
    EXPECT_LT((intrinsics.PrincipalPoint() - scene.truth.intrinsics.at(id).PrincipalPoint()).norm(), 2.0) << id;
  }
  EXPECT_NEAR(weak.intrinsics.at(1).DistortionParams()[0], -0.08, 0.01);
  const SfmData strong = refine(1e-5);
  for (const auto& [id, intrinsics] : strong.intrinsics) {
    const Eigen::Vector2d centre(0.5 * (intrinsics.width() - 1.0), 0.5 * (intrinsics.height() - 1.0));
    EXPECT_LT((intrinsics.PrincipalPoint() - centre).norm(), 0.5) << id;
  }
  EXPECT_LT(std::abs(strong.intrinsics.at(1).DistortionParams()[0]), 1e-3);
}

TEST(BundleAdjustment, SameInputGivesBitwiseSameOutput) {
  const SceneOptions scene_options = bundle_test::NoisySceneOptions(300);
  const Scene scene = bundle_test::MakeScene(scene_options);
  SfmData first = scene.truth;
  bundle_test::PerturbPoses(1.0, 0.01, scene.radius, 11, &first);
  SfmData second = first;
  BundleAdjustmentOptions options;
  options.refine_focal = true;
  const BundleAdjustmentResult result_first = AdjustBundle(options, &first);
  const BundleAdjustmentResult result_second = AdjustBundle(options, &second);
  ASSERT_TRUE(result_first.success);
  EXPECT_EQ(result_first.final_cost, result_second.final_cost);
  EXPECT_EQ(result_first.num_iterations, result_second.num_iterations);
  EXPECT_TRUE(first == second);
}

TEST(BundleAdjustment, GaugeHoldsFirstPoseAndScale) {
  const Scene scene = NoisyScene();
  SfmData data = scene.truth;
  bundle_test::PerturbPoses(1.0, 0.01, scene.radius, 11, &data);
  const SfmData before = data;
  ASSERT_TRUE(AdjustBundle({}, &data).success);
  EXPECT_EQ(data.poses.at(0).rotation, before.poses.at(0).rotation);
  EXPECT_EQ(data.poses.at(0).center, before.poses.at(0).center);
  // The camera farthest from the first keeps the coordinate of their largest offset.
  IndexT farthest = 0;
  for (const auto& [id, pose] : before.poses) {
    const Eigen::Vector3d& first = before.poses.at(0).center;
    if ((pose.center - first).norm() > (before.poses.at(farthest).center - first).norm()) farthest = id;
  }
  const Eigen::Vector3d offset_before = before.poses.at(farthest).center - before.poses.at(0).center;
  const Eigen::Vector3d offset_after = data.poses.at(farthest).center - data.poses.at(0).center;
  int axis = 0;
  offset_before.cwiseAbs().maxCoeff(&axis);
  EXPECT_NE(data.poses.at(farthest).center, before.poses.at(farthest).center);  // the rest moved
  EXPECT_EQ(offset_after[axis], offset_before[axis]);
}

TEST(BundleAdjustment, NoPoseIsAClearFailure) {
  SfmData data = bundle_test::MakeScene({}).truth;
  data.poses.clear();
  const SfmData before = data;
  const BundleAdjustmentResult result = AdjustBundle({}, &data);
  EXPECT_FALSE(result.success);
  EXPECT_NE(result.message.find("no posed view"), std::string::npos) << result.message;
  EXPECT_TRUE(data == before);
}

TEST(BundleAdjustment, SkipsObservationsOfUnposedViewsAndLonelyLandmarks) {
  SceneOptions scene_options;
  scene_options.num_points = 200;
  SfmData data = bundle_test::MakeScene(scene_options).truth;
  // A landmark seen by one posed view and one view without a pose.
  View unposed = data.views.at(0);
  unposed.id_view = unposed.id_pose = 100;
  data.views[100] = unposed;
  Landmark lonely;
  lonely.X = Eigen::Vector3d(0.1, 0.2, 0.3);
  lonely.observations[0] = Observation{data.intrinsics.at(0).Project(data.poses.at(0).ToCamera(lonely.X)), 0};
  lonely.observations[100] = Observation{Eigen::Vector2d(10.0, 20.0), 0};
  data.structure[1000] = lonely;
  const BundleAdjustmentResult result = AdjustBundle({}, &data);
  ASSERT_TRUE(result.success) << result.message;
  EXPECT_EQ(result.num_skipped_landmarks, 1u);
  EXPECT_EQ(result.num_skipped_observations, 1u);
  EXPECT_EQ(result.num_landmarks, 200u);
  EXPECT_EQ(data.structure.at(1000).X, lonely.X);
  EXPECT_LT(result.final_rms_px, 1e-6);  // exact data stays exact
}

TEST(BundleAdjustment, NoLandmarkWithTwoPosedViewsIsAClearFailure) {
  SfmData data = bundle_test::MakeScene({}).truth;
  for (auto& [id, landmark] : data.structure) {
    landmark.observations.erase(landmark.observations.begin(), std::prev(landmark.observations.end()));
  }
  const BundleAdjustmentResult result = AdjustBundle({}, &data);
  EXPECT_FALSE(result.success);
  EXPECT_NE(result.message.find("two posed views"), std::string::npos) << result.message;
}

}  // namespace
}  // namespace sfm_pruning
