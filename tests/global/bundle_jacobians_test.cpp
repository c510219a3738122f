// The analytic Jacobians of the bundle-adjustment costs against central differences taken through
// PoseManifold::Plus (the tangent the solver steps in), and the manifold itself.
#include <gtest/gtest.h>

#include <memory>
#include <vector>

#include <Eigen/Geometry>

#include "sfm_pruning/global/bundle_pose_manifold.hpp"
#include "sfm_pruning/global/bundle_reprojection_cost.hpp"

namespace sfm_pruning::bundle {
namespace {

// A pose looking roughly down +z at the point, slightly rotated.
std::vector<double> TestPose() {
  const Eigen::Quaterniond q(Eigen::AngleAxisd(0.3, Eigen::Vector3d(0.2, -1.0, 0.4).normalized()));
  return {q.w(), q.x(), q.y(), q.z(), 0.4, -0.3, -5.0};
}

// Residuals of `cost` at (pose, point, intrinsics).
Eigen::VectorXd Residuals(const ceres::CostFunction& cost, const std::vector<double*>& blocks) {
  Eigen::VectorXd r(cost.num_residuals());
  EXPECT_TRUE(cost.Evaluate(blocks.data(), r.data(), nullptr));
  return r;
}

// Compares the cost's Jacobians (pose mapped to the tangent by PlusJacobian) with central
// differences: the pose through the manifold, the other blocks directly.
void ExpectJacobiansMatchDifferences(const ceres::CostFunction& cost, std::vector<std::vector<double>> blocks,
                                     double tolerance) {
  const int rows = cost.num_residuals();
  const std::vector<int32_t>& sizes = cost.parameter_block_sizes();
  std::vector<double*> pointers;
  for (auto& block : blocks) pointers.push_back(block.data());
  std::vector<Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor>> jacobians;
  std::vector<double*> jacobian_pointers;
  for (const int32_t size : sizes) jacobians.emplace_back(rows, size);
  for (auto& J : jacobians) jacobian_pointers.push_back(J.data());
  Eigen::VectorXd r(rows);
  ASSERT_TRUE(cost.Evaluate(pointers.data(), r.data(), jacobian_pointers.data()));
  EXPECT_LT((r - Residuals(cost, pointers)).norm(), 1e-12);

  const PoseManifold manifold;
  Eigen::Matrix<double, 7, 6, Eigen::RowMajor> plus_jacobian;
  manifold.PlusJacobian(blocks[0].data(), plus_jacobian.data());
  const Eigen::MatrixXd pose_tangent = jacobians[0] * plus_jacobian;
  const double h = 1e-6;
  for (int k = 0; k < 6; ++k) {
    std::vector<double> delta(6, 0.0), plus(7), minus(7);
    delta[k] = h;
    manifold.Plus(blocks[0].data(), delta.data(), plus.data());
    delta[k] = -h;
    manifold.Plus(blocks[0].data(), delta.data(), minus.data());
    std::vector<double*> at_plus = pointers, at_minus = pointers;
    at_plus[0] = plus.data();
    at_minus[0] = minus.data();
    const Eigen::VectorXd numeric = (Residuals(cost, at_plus) - Residuals(cost, at_minus)) / (2.0 * h);
    EXPECT_LT((numeric - pose_tangent.col(k)).norm(), tolerance * (1.0 + numeric.norm())) << "pose tangent " << k;
  }
  for (size_t b = 1; b < blocks.size(); ++b) {
    for (int k = 0; k < sizes[b]; ++k) {
      std::vector<double> plus = blocks[b], minus = blocks[b];
      const double step = h * std::max(1.0, std::abs(blocks[b][k]));
      plus[k] += step;
      minus[k] -= step;
      std::vector<double*> at_plus = pointers, at_minus = pointers;
      at_plus[b] = plus.data();
      at_minus[b] = minus.data();
      const Eigen::VectorXd numeric = (Residuals(cost, at_plus) - Residuals(cost, at_minus)) / (2.0 * step);
      EXPECT_LT((numeric - jacobians[b].col(k)).norm(), tolerance * (1.0 + numeric.norm()))
          << "block " << b << " column " << k;
    }
  }
}

TEST(BundleJacobians, PinholeModelsMatchCentralDifferences) {
  struct Case {
    CameraModel model;
    std::vector<double> intrinsics;
  };
  const std::vector<Case> cases = {
      {CameraModel::kPinhole, {1200.0, 512.0, 384.0}},
      {CameraModel::kPinholeRadialK1, {1200.0, 512.0, 384.0, -0.08}},
      {CameraModel::kPinholeRadialK3, {1200.0, 512.0, 384.0, -0.08, 0.02, -0.004}},
      {CameraModel::kPinholeBrownT2, {1200.0, 512.0, 384.0, -0.08, 0.02, -0.004, 0.001, -0.002}},
      {CameraModel::kFisheye, {800.0, 512.0, 384.0, 0.01, -0.02, 0.003, -0.001}},
      {CameraModel::kPinholeFxFy, {1200.0, 1180.0, 512.0, 384.0}},
  };
  for (const Case& c : cases) {
    SCOPED_TRACE(static_cast<int>(c.model));
    std::unique_ptr<ceres::CostFunction> cost(CreatePinholeCost(c.model, Eigen::Vector2d(530.0, 370.0)));
    ASSERT_NE(cost, nullptr);
    ExpectJacobiansMatchDifferences(*cost, {TestPose(), {0.9, 0.7, 1.2}, c.intrinsics}, 1e-5);
  }
}

TEST(BundleJacobians, SphericalMatchesCentralDifferences) {
  const SphericalBearingCost cost(Eigen::Vector3d(0.1, 0.2, 1.0), 600.0);
  ExpectJacobiansMatchDifferences(cost, {TestPose(), {0.9, 0.7, 1.2}}, 1e-5);
}

TEST(BundleJacobians, ManifoldPlusMinusRoundTripAndFixedAxis) {
  const std::vector<double> x = TestPose();
  const double delta[6] = {0.02, -0.01, 0.03, 0.5, -0.25, 0.125};
  for (const int fixed_axis : {-1, 0, 1, 2}) {
    const PoseManifold manifold(fixed_axis);
    double moved[7], back[6];
    ASSERT_TRUE(manifold.Plus(x.data(), delta, moved));
    EXPECT_NEAR(Eigen::Vector4d(moved[0], moved[1], moved[2], moved[3]).norm(), 1.0, 1e-12);
    ASSERT_TRUE(manifold.Minus(moved, x.data(), back));
    for (int k = 0; k < 3; ++k) EXPECT_NEAR(back[k], delta[k], 1e-12);
    for (int k = 0; k < 3; ++k) {
      const double expected_offset = k == fixed_axis ? 0.0 : delta[3 + k];
      EXPECT_DOUBLE_EQ(moved[4 + k], x[4 + k] + expected_offset);
      EXPECT_DOUBLE_EQ(back[3 + k], expected_offset);
    }
  }
  // The rotation vector is applied on the camera side: R <- Exp(w) R.
  const PoseManifold manifold;
  const double turn[6] = {0.0, 0.0, 0.2, 0.0, 0.0, 0.0};
  double turned[7];
  manifold.Plus(x.data(), turn, turned);
  const Eigen::Matrix3d expected = Eigen::AngleAxisd(0.2, Eigen::Vector3d::UnitZ()).toRotationMatrix() *
                                   Eigen::Quaterniond(x[0], x[1], x[2], x[3]).toRotationMatrix();
  const Eigen::Matrix3d actual = Eigen::Quaterniond(turned[0], turned[1], turned[2], turned[3]).toRotationMatrix();
  EXPECT_LT((actual - expected).norm(), 1e-12);
}

}  // namespace
}  // namespace sfm_pruning::bundle
