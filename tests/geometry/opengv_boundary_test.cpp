#include "sfm_pruning/geometry/opengv_boundary.hpp"

#include <cmath>

#include <Eigen/Geometry>
#include <gtest/gtest.h>

namespace sfm_pruning {
namespace {

Pose PoseI() {
  return Pose(Eigen::AngleAxisd(0.4, Eigen::Vector3d(1, 2, -1).normalized()).toRotationMatrix(),
              Eigen::Vector3d(1.0, -0.5, 2.0));
}
Pose PoseJ() {
  return Pose(Eigen::AngleAxisd(-0.9, Eigen::Vector3d(0, 1, 0.3).normalized()).toRotationMatrix(),
              Eigen::Vector3d(-2.0, 0.3, 1.0));
}

TEST(OpenGVBoundary, RelativePoseFollowsOpenGVsConventionOnTheirSide) {
  // OpenGV: X_1 = R_12 X_2 + t_12 with viewpoint 1 = view i, viewpoint 2 = view j.
  const RelativePose ij = RelativePoseBetween(PoseI(), PoseJ());
  const OpenGVTransformation T_12 = RelativePoseToOpenGV(ij);
  const Eigen::Vector3d X(0.3, 0.7, 9.0);
  const Eigen::Vector3d X_1 = PoseI().ToCamera(X);
  const Eigen::Vector3d X_2 = PoseJ().ToCamera(X);
  EXPECT_TRUE((T_12.leftCols<3>() * X_2 + T_12.col(3)).isApprox(X_1, 1e-12));
  // And ours: X_j = R_ij X_i + t_ij after the round trip.
  const RelativePose back = RelativePoseFromOpenGV(T_12);
  EXPECT_TRUE((back.rotation * X_1 + back.translation).isApprox(X_2, 1e-12));
  EXPECT_TRUE(back.rotation.isApprox(ij.rotation, 1e-14));
  EXPECT_TRUE(back.translation.isApprox(ij.translation, 1e-14));
}

TEST(OpenGVBoundary, AbsolutePoseIsCameraToWorldOnTheirSide) {
  // OpenGV: X_world = R X_cam + t, t = camera centre.
  const Pose pose = PoseI();
  const OpenGVTransformation T_wc = PoseToOpenGV(pose);
  const Eigen::Vector3d X_cam(0.2, -0.1, 4.0);
  EXPECT_TRUE((T_wc.leftCols<3>() * X_cam + T_wc.col(3)).isApprox(pose.ToWorld(X_cam), 1e-12));
  EXPECT_TRUE(T_wc.col(3).isApprox(pose.center, 1e-15));
  const Pose back = PoseFromOpenGV(T_wc);
  EXPECT_TRUE(back.rotation.isApprox(pose.rotation, 1e-15));
  EXPECT_TRUE(back.center.isApprox(pose.center, 1e-15));
}

TEST(OpenGVBoundary, ThresholdIsOneMinusCosine) {
  EXPECT_DOUBLE_EQ(OpenGVThresholdFromAngle(0.0), 0.0);
  EXPECT_NEAR(OpenGVThresholdFromAngle(M_PI / 3), 0.5, 1e-15);
  // Small angles: ~ angle^2 / 2.
  EXPECT_NEAR(OpenGVThresholdFromAngle(1e-3), 5e-7, 1e-13);
}

TEST(OpenGVBoundary, VectorsAreCopiedInOrder) {
  const std::vector<Eigen::Vector3d> in = {{1, 2, 3}, {4, 5, 6}};
  const opengv::bearingVectors_t out = ToOpenGVVectors(in);
  ASSERT_EQ(out.size(), 2u);
  EXPECT_EQ(out[1], in[1]);
}

}  // namespace
}  // namespace sfm_pruning
