#include "sfm_pruning/geometry/triangulation.hpp"

#include <cmath>

#include <gtest/gtest.h>

#include "geometry/synthetic_scene.hpp"

namespace sfm_pruning {
namespace {

TEST(Triangulation, TwoViewHandCase) {
  // i at the origin, j one unit to the right: the point (0, 0, 5) is 5 along b_i and sqrt(26)
  // along the unit b_j.
  const RelativePose side_step(Eigen::Matrix3d::Identity(), Eigen::Vector3d(-1, 0, 0));
  const auto point = TriangulateTwoView(side_step, Eigen::Vector3d(0, 0, 1), Eigen::Vector3d(-1, 0, 5).normalized());
  ASSERT_TRUE(point.has_value());
  EXPECT_TRUE(point->point_i.isApprox(Eigen::Vector3d(0, 0, 5), 1e-14));
  EXPECT_NEAR(point->depth_i, 5.0, 1e-13);
  EXPECT_NEAR(point->depth_j, std::sqrt(26.0), 1e-13);
  // The opposite rays meet behind both cameras.
  const auto behind = TriangulateTwoView(side_step, Eigen::Vector3d(0, 0, -1), Eigen::Vector3d(1, 0, -5).normalized());
  ASSERT_TRUE(behind.has_value());
  EXPECT_LT(behind->depth_i, 0.0);
  EXPECT_LT(behind->depth_j, 0.0);
  // Parallel rays: no point.
  EXPECT_FALSE(TriangulateTwoView(side_step, Eigen::Vector3d(0, 0, 1), Eigen::Vector3d(0, 0, 1)).has_value());
}

TEST(Triangulation, AnglesAgainstAHandCase) {
  const Eigen::Vector3d X(0, 0, 5);
  EXPECT_NEAR(TriangulationAngle(Eigen::Vector3d::Zero(), Eigen::Vector3d(1, 0, 0), X), std::atan(0.2), 1e-15);
  // Symmetric pair at +-1: 2 atan(1/5); that is the widest of the three.
  const std::vector<Eigen::Vector3d> centers = {{-1, 0, 0}, {0, 0, 0}, {1, 0, 0}};
  EXPECT_NEAR(MaxTriangulationAngle(centers, X), 2.0 * std::atan(0.2), 1e-15);
  EXPECT_EQ(MaxTriangulationAngle({Eigen::Vector3d::Zero()}, X), 0.0);
}

TEST(Triangulation, MultiViewIsExactOnNoiseFreeData) {
  testing::SyntheticViewOptions options;
  options.num_points = 50;
  const testing::SyntheticScene scene = testing::MakeSyntheticScene(4, options);
  for (const TriangulationMethod method : {TriangulationMethod::kDlt, TriangulationMethod::kMidpoint}) {
    for (size_t k = 0; k < scene.points.size(); ++k) {
      std::vector<Eigen::Vector3d> bearings;
      for (const auto& per_camera : scene.bearings) bearings.push_back(per_camera[k]);
      const auto X = TriangulateMultiView(scene.poses, bearings, method);
      ASSERT_TRUE(X.has_value());
      EXPECT_LT((*X - scene.points[k]).norm(), 1e-9) << "method " << static_cast<int>(method) << " point " << k;
      EXPECT_TRUE(IsInFrontOfAll(scene.poses, bearings, *X));
    }
  }
}

TEST(Triangulation, MultiViewRejectsDegenerateInput) {
  const std::vector<Pose> one = {Pose()};
  EXPECT_FALSE(TriangulateMultiView(one, {Eigen::Vector3d(0, 0, 1)}).has_value());
  // Two cameras at the same centre: the rays meet only at the centre, with no depth information.
  const std::vector<Pose> same = {Pose(), Pose()};
  const std::vector<Eigen::Vector3d> parallel = {Eigen::Vector3d(0, 0, 1), Eigen::Vector3d(0, 0, 1)};
  EXPECT_FALSE(TriangulateMultiView(same, parallel, TriangulationMethod::kDlt).has_value());
  EXPECT_FALSE(TriangulateMultiView(same, parallel, TriangulationMethod::kMidpoint).has_value());
}

TEST(Triangulation, CheiralityWithoutProjection) {
  const Pose pose;  // identity at the origin
  EXPECT_TRUE(IsInFront(pose, Eigen::Vector3d(0, 0, 1), Eigen::Vector3d(0.1, 0, 3)));
  EXPECT_FALSE(IsInFront(pose, Eigen::Vector3d(0, 0, 1), Eigen::Vector3d(0.1, 0, -3)));
  // A spherical camera observing a point behind its optical axis: in front along its own ray.
  EXPECT_TRUE(IsInFront(pose, Eigen::Vector3d(0, 0, -1), Eigen::Vector3d(0, 0, -3)));
}

}  // namespace
}  // namespace sfm_pruning
