#include "sfm_pruning/sfm/pose.hpp"

#include <gtest/gtest.h>

namespace sfm_pruning {
namespace {

Eigen::Matrix3d RotY(double angle) { return Eigen::AngleAxisd(angle, Eigen::Vector3d::UnitY()).toRotationMatrix(); }

TEST(Pose, WorldToCameraConvention) {
  // A camera at (1, 0, 0) turned 90 degrees about y. Its rotation maps world x to camera -z
  // (R * (1,0,0) = (0,0,-1)), so a point 2 m along world -x from the centre lies 2 m in front.
  const Pose pose(RotY(M_PI / 2), Eigen::Vector3d(1, 0, 0));
  const Eigen::Vector3d in_front = pose.ToCamera(Eigen::Vector3d(-1, 0, 0));
  EXPECT_TRUE(in_front.isApprox(Eigen::Vector3d(0, 0, 2), 1e-12)) << in_front.transpose();
  EXPECT_TRUE(pose.ToWorld(in_front).isApprox(Eigen::Vector3d(-1, 0, 0), 1e-12));
  EXPECT_TRUE(pose.translation().isApprox(-pose.rotation * pose.center));
  EXPECT_TRUE(pose.ViewingDirection().isApprox(Eigen::Vector3d(-1, 0, 0), 1e-12));
}

TEST(Pose, FromRotationTranslationRecoversCentre) {
  const Eigen::Matrix3d R = RotY(0.3);
  const Eigen::Vector3d c(0.5, -2.0, 3.0);
  const Pose pose = Pose::FromRotationTranslation(R, -R * c);
  EXPECT_TRUE(pose.center.isApprox(c, 1e-12));
}

TEST(RelativePose, HandMadeCase) {
  // Camera i at the origin looking down +z; camera j one metre to the right (+x), same
  // orientation. A point seen by i at (0,0,5) is seen by j at (-1,0,5): X_j = X_i + (-1,0,0).
  const Pose i;
  const Pose j(Eigen::Matrix3d::Identity(), Eigen::Vector3d(1, 0, 0));
  const RelativePose ij = RelativePoseBetween(i, j);
  EXPECT_TRUE(ij.rotation.isApprox(Eigen::Matrix3d::Identity()));
  EXPECT_TRUE(ij.translation.isApprox(Eigen::Vector3d(-1, 0, 0)));
  EXPECT_TRUE(ij.CenterOfJInI().isApprox(Eigen::Vector3d(1, 0, 0)));
  const Eigen::Vector3d X_i(0, 0, 5);
  EXPECT_TRUE((ij.rotation * X_i + ij.translation).isApprox(Eigen::Vector3d(-1, 0, 5)));
}

TEST(RelativePose, RotatedHandMadeCase) {
  // Camera j sits at the world origin turned 90 degrees about y (R_j maps world x to -z);
  // camera i is the identity at the origin. Then R_ij = R_j and t_ij = 0.
  const Pose i;
  const Pose j(RotY(M_PI / 2), Eigen::Vector3d::Zero());
  const RelativePose ij = RelativePoseBetween(i, j);
  EXPECT_TRUE(ij.rotation.isApprox(RotY(M_PI / 2)));
  EXPECT_NEAR(ij.translation.norm(), 0.0, 1e-15);
}

TEST(RelativePose, ComposeInvertsRelativePoseBetween) {
  const Pose i(RotY(0.4) * Eigen::AngleAxisd(0.2, Eigen::Vector3d::UnitX()).toRotationMatrix(),
               Eigen::Vector3d(1, 2, 3));
  const Pose j(RotY(-0.7), Eigen::Vector3d(-2, 0.5, 1));
  const RelativePose ij = RelativePoseBetween(i, j);
  const Pose j_again = ComposePose(i, ij);
  EXPECT_TRUE(j_again.rotation.isApprox(j.rotation, 1e-12));
  EXPECT_TRUE(j_again.center.isApprox(j.center, 1e-12));
  // A world point expressed in both cameras agrees with the relative pose.
  const Eigen::Vector3d X(0.3, -0.4, 7.0);
  EXPECT_TRUE((ij.rotation * i.ToCamera(X) + ij.translation).isApprox(j.ToCamera(X), 1e-12));
  // The inverse relative pose maps back.
  const RelativePose ji = ij.Inverse();
  EXPECT_TRUE((ji.rotation * j.ToCamera(X) + ji.translation).isApprox(i.ToCamera(X), 1e-12));
}

TEST(Angles, RotationAngleAndVectorAngle) {
  EXPECT_NEAR(RotationAngleBetween(RotY(0.1), RotY(0.35)), 0.25, 1e-12);
  EXPECT_NEAR(RotationAngleBetween(RotY(0.0), RotY(M_PI)), M_PI, 1e-9);
  EXPECT_NEAR(RotationAngleBetween(RotY(0.0), RotY(1e-9)), 1e-9, 1e-20);
  EXPECT_NEAR(AngleBetweenVectors({1, 0, 0}, {0, 2, 0}), M_PI / 2, 1e-15);
  EXPECT_NEAR(AngleBetweenVectors({1, 0, 0}, {-3, 0, 0}), M_PI, 1e-15);
  EXPECT_NEAR(AngleBetweenVectors({1, 1e-9, 0}, {1, 0, 0}), 1e-9, 1e-20);
  EXPECT_NEAR(RadToDeg(DegToRad(37.5)), 37.5, 1e-12);
}

}  // namespace
}  // namespace sfm_pruning
