#include "sfm_pruning/geometry/so3.hpp"

#include <cmath>
#include <random>

#include <Eigen/Geometry>
#include <gtest/gtest.h>

#include "sfm_pruning/sfm/pose.hpp"

namespace sfm_pruning {
namespace {

Eigen::Matrix3d AxisAngle(double angle, const Eigen::Vector3d& axis) {
  return Eigen::AngleAxisd(angle, axis.normalized()).toRotationMatrix();
}

TEST(So3, LogExpRoundTripOverTheWholeRange) {
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> unit(-1.0, 1.0);
  // Angles from tiny to just below pi, where naive formulas lose precision.
  for (const double angle : {0.0, 1e-15, 1e-12, 1e-8, 1e-4, 0.3, 1.0, M_PI / 2, 2.5, M_PI - 1e-4, M_PI - 1e-8}) {
    for (int trial = 0; trial < 5; ++trial) {
      const Eigen::Vector3d axis = Eigen::Vector3d(unit(rng), unit(rng), unit(rng)).normalized();
      const Eigen::Vector3d omega = angle * axis;
      const Eigen::Matrix3d R = ExpSO3(omega);
      EXPECT_TRUE(R.isApprox(AxisAngle(angle, axis), 1e-14) || angle == 0.0) << angle;
      EXPECT_NEAR((R.transpose() * R - Eigen::Matrix3d::Identity()).norm(), 0.0, 4e-15);
      const Eigen::Vector3d log = LogSO3(R);
      // Absolute error on omega: ~1e-16 near 0, and near pi limited by the rounding of R itself
      // (a perturbation eps of R moves the axis by ~eps / (1 - cos) at worst).
      EXPECT_LT((log - omega).norm(), 1e-12 + 1e-15 * angle) << "angle " << angle;
    }
  }
}

TEST(So3, LogAtExactlyPiGivesAHalfTurnAboutTheAxis) {
  const Eigen::Vector3d axis = Eigen::Vector3d(1, -2, 0.5).normalized();
  const Eigen::Vector3d log = LogSO3(AxisAngle(M_PI, axis));
  EXPECT_NEAR(log.norm(), M_PI, 1e-12);
  // +axis and -axis are the same half turn; either is correct.
  EXPECT_NEAR(std::abs(log.normalized().dot(axis)), 1.0, 1e-12);
  EXPECT_TRUE(ExpSO3(log).isApprox(AxisAngle(M_PI, axis), 1e-12));
}

TEST(So3, LogIsPreciseForTinyAnglesWhereTheTraceFormulaIsNot) {
  // 1e-9 rad: the trace-based arccos returns 0 here (cos = 1 - 5e-19 rounds to 1).
  const Eigen::Matrix3d R = AxisAngle(1e-9, Eigen::Vector3d::UnitZ());
  EXPECT_NEAR(LogSO3(R).z(), 1e-9, 1e-22);
}

TEST(So3, SkewMatrixIsTheCrossProduct) {
  const Eigen::Vector3d a(0.3, -1.2, 2.0), b(-0.7, 0.4, 1.1);
  EXPECT_TRUE((SkewMatrix(a) * b).isApprox(a.cross(b), 1e-15));
}

TEST(So3, ProjectToRotationRecoversANoisyRotationAndFixesReflections) {
  const Eigen::Matrix3d R = AxisAngle(0.8, Eigen::Vector3d(1, 1, 0));
  Eigen::Matrix3d noisy = R;
  noisy(0, 1) += 1e-3;
  noisy(2, 2) -= 2e-3;
  const Eigen::Matrix3d projected = ProjectToRotation(noisy);
  EXPECT_NEAR(projected.determinant(), 1.0, 1e-14);
  EXPECT_TRUE((projected.transpose() * projected).isIdentity(1e-14));
  EXPECT_LT(LogSO3(R.transpose() * projected).norm(), 2e-3);
  // A scaled rotation projects exactly onto the rotation.
  EXPECT_TRUE(ProjectToRotation(3.0 * R).isApprox(R, 1e-14));
  // A reflection (det -1) still yields a proper rotation.
  const Eigen::Matrix3d reflection = Eigen::Vector3d(1, 1, -1).asDiagonal();
  EXPECT_NEAR(ProjectToRotation(reflection).determinant(), 1.0, 1e-14);
}

// R0 Exp(+-theta a_k) for three orthogonal axes: symmetric about R0 in every sense, so every
// mean must return R0 exactly.
std::vector<Eigen::Matrix3d> SymmetricSet(const Eigen::Matrix3d& R0, double theta) {
  std::vector<Eigen::Matrix3d> set;
  for (int axis = 0; axis < 3; ++axis) {
    const Eigen::Vector3d a = Eigen::Vector3d::Unit(axis);
    set.push_back(R0 * ExpSO3(theta * a));
    set.push_back(R0 * ExpSO3(-theta * a));
  }
  return set;
}

TEST(So3, MeansOfASymmetricSetAreItsCentre) {
  const Eigen::Matrix3d R0 = AxisAngle(2.0, Eigen::Vector3d(0.2, -1, 0.4));
  const std::vector<Eigen::Matrix3d> set = SymmetricSet(R0, 0.6);
  EXPECT_LT(LogSO3(R0.transpose() * ChordalMeanRotation(set)).norm(), 1e-14);
  const RotationMeanResult l2 = GeodesicMeanRotation(set);
  EXPECT_TRUE(l2.converged);
  EXPECT_LT(LogSO3(R0.transpose() * l2.rotation).norm(), 1e-14);
  GeodesicMeanOptions l1_options;
  l1_options.norm = GeodesicMeanOptions::Norm::kL1;
  const RotationMeanResult l1 = GeodesicMeanRotation(set, l1_options);
  EXPECT_TRUE(l1.converged);
  EXPECT_LT(LogSO3(R0.transpose() * l1.rotation).norm(), 1e-14);
}

TEST(So3, KarcherMeanOfTwoRotationsIsTheGeodesicMidpoint) {
  const Eigen::Vector3d axis = Eigen::Vector3d(1, 2, 3).normalized();
  const std::vector<Eigen::Matrix3d> pair = {AxisAngle(0.2, axis), AxisAngle(1.4, axis)};
  const RotationMeanResult mean = GeodesicMeanRotation(pair);
  EXPECT_LT(LogSO3(AxisAngle(0.8, axis).transpose() * mean.rotation).norm(), 1e-13);
  // Weights 1:3 move it to 0.2 + 0.75 * 1.2 = 1.1 rad.
  const RotationMeanResult weighted = GeodesicMeanRotation(pair, {}, {1.0, 3.0});
  EXPECT_LT(LogSO3(AxisAngle(1.1, axis).transpose() * weighted.rotation).norm(), 1e-13);
}

TEST(So3, L1MedianResistsAnOutlierThatPullsTheL2Mean) {
  const Eigen::Matrix3d R0 = AxisAngle(0.5, Eigen::Vector3d::UnitY());
  std::vector<Eigen::Matrix3d> set = SymmetricSet(R0, 0.05);
  set.push_back(R0 * AxisAngle(2.5, Eigen::Vector3d::UnitX()));
  const double l2_error = LogSO3(R0.transpose() * GeodesicMeanRotation(set).rotation).norm();
  GeodesicMeanOptions l1_options;
  l1_options.norm = GeodesicMeanOptions::Norm::kL1;
  l1_options.max_iterations = 1000;
  const double l1_error = LogSO3(R0.transpose() * GeodesicMeanRotation(set, l1_options).rotation).norm();
  EXPECT_GT(l2_error, 0.3);  // 2.5 / 7
  EXPECT_LT(l1_error, 0.02);  // the median stays inside the cluster of radius 0.05
}

TEST(So3, EmptySetGivesIdentity) {
  EXPECT_TRUE(ChordalMeanRotation({}).isIdentity());
  EXPECT_TRUE(GeodesicMeanRotation({}).rotation.isIdentity());
}

}  // namespace
}  // namespace sfm_pruning
