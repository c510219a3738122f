#include "sfm_pruning/geometry/fundamental_matrix.hpp"

#include <algorithm>
#include <random>

#include <gtest/gtest.h>
#include <Eigen/Geometry>

#include "geometry/synthetic_scene.hpp"
#include "sfm_pruning/geometry/epipolar_geometry.hpp"

namespace sfm_pruning {
namespace {

Eigen::Matrix3d CalibrationMatrix(const CameraIntrinsics& intrinsics) {
  Eigen::Matrix3d K = Eigen::Matrix3d::Identity();
  K(0, 0) = K(1, 1) = intrinsics.FocalLength();
  K.topRightCorner<2, 1>() = intrinsics.PrincipalPoint();
  return K;
}

// F = K_j^-T E K_i^-1 of the scene's two cameras, unit norm.
Eigen::Matrix3d TrueFundamental(const testing::SyntheticScene& scene) {
  const Eigen::Matrix3d E = EssentialMatrix(RelativePoseBetween(scene.poses[0], scene.poses[1]));
  const Eigen::Matrix3d F = CalibrationMatrix(scene.intrinsics[1]).inverse().transpose() * E *
                            CalibrationMatrix(scene.intrinsics[0]).inverse();
  return F / F.norm();
}

// Difference of two unit-norm matrices up to sign.
double SignFreeDistance(const Eigen::Matrix3d& a, const Eigen::Matrix3d& b) {
  return std::min((a - b).norm(), (a + b).norm());
}

TEST(FundamentalMatrix, ExactCorrespondencesGiveTheTrueMatrix) {
  testing::SyntheticViewOptions options;
  options.distortion = false;
  options.num_points = 50;
  const testing::SyntheticScene scene = testing::MakeSyntheticScene(2, options);
  Eigen::Matrix3d F;
  double definition = 0.0;
  ASSERT_TRUE(EstimateFundamentalMatrix(scene.pixels[0], scene.pixels[1], {}, &F, &definition));
  EXPECT_LT(SignFreeDistance(F, TrueFundamental(scene)), 1e-6);
  EXPECT_GT(definition, 100.0);
  for (size_t k = 0; k < scene.points.size(); ++k) {
    EXPECT_LT(SampsonDistance(F, scene.pixels[0][k], scene.pixels[1][k]), 1e-6);
  }
}

TEST(FundamentalMatrix, ReweightingResistsAFewOutliers) {
  testing::SyntheticViewOptions options;
  options.distortion = false;
  options.num_points = 300;
  options.pixel_noise_std = 0.5;
  options.outlier_ratio = 0.1;
  const testing::SyntheticScene scene = testing::MakeSyntheticScene(2, options);
  const Eigen::Matrix3d truth = TrueFundamental(scene);
  FundamentalMatrixOptions linear_only;
  linear_only.num_reweighting_iterations = 0;
  Eigen::Matrix3d linear, robust;
  ASSERT_TRUE(EstimateFundamentalMatrix(scene.pixels[0], scene.pixels[1], linear_only, &linear));
  FundamentalMatrixOptions reweighted;
  reweighted.num_reweighting_iterations = 10;
  ASSERT_TRUE(EstimateFundamentalMatrix(scene.pixels[0], scene.pixels[1], reweighted, &robust));
  // The inliers' Sampson distances: at the noise level for the reweighted fit.
  std::vector<double> distances;
  for (size_t k = 0; k < scene.points.size(); ++k) {
    if (!scene.is_outlier[k]) distances.push_back(SampsonDistance(robust, scene.pixels[0][k], scene.pixels[1][k]));
  }
  std::sort(distances.begin(), distances.end());
  EXPECT_LT(distances[distances.size() / 2], 0.5);
  EXPECT_LT(SignFreeDistance(robust, truth), 0.5 * SignFreeDistance(linear, truth));
}

TEST(FundamentalMatrix, PlanarPointsLeaveItUndefined) {
  std::mt19937 rng(5);
  std::uniform_real_distribution<double> uniform(-2.0, 2.0);
  std::normal_distribution<double> noise(0.0, 0.5);  // pixels
  const CameraIntrinsics intrinsics = CameraIntrinsics::Pinhole(1000, 750, 900.0, 500.0, 375.0);
  const Pose pose_i = testing::LookAtPose(Eigen::Vector3d(-1.0, 0.0, -8.0), Eigen::Vector3d::Zero(), 0.0);
  const Pose pose_j = testing::LookAtPose(Eigen::Vector3d(1.5, 0.5, -7.5), Eigen::Vector3d::Zero(), 0.1);
  std::vector<Eigen::Vector2d> pixels_i, pixels_j;
  for (int k = 0; k < 100; ++k) {
    const Eigen::Vector3d X(uniform(rng), uniform(rng), 0.0);  // the plane z = 0
    pixels_i.push_back(intrinsics.Project(pose_i.ToCamera(X)) + Eigen::Vector2d(noise(rng), noise(rng)));
    pixels_j.push_back(intrinsics.Project(pose_j.ToCamera(X)) + Eigen::Vector2d(noise(rng), noise(rng)));
  }
  Eigen::Matrix3d F;
  double definition = 0.0;
  if (EstimateFundamentalMatrix(pixels_i, pixels_j, {}, &F, &definition)) {
    EXPECT_LT(definition, 5.0);  // general position with this noise: > 20
  }
}

TEST(FundamentalMatrix, TooFewPointsFail) {
  const std::vector<Eigen::Vector2d> points(7, Eigen::Vector2d(1.0, 2.0));
  Eigen::Matrix3d F = Eigen::Matrix3d::Identity();
  EXPECT_FALSE(EstimateFundamentalMatrix(points, points, {}, &F));
  EXPECT_EQ(F, Eigen::Matrix3d::Identity());
}

}  // namespace
}  // namespace sfm_pruning
