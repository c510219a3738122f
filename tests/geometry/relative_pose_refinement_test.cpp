#include "sfm_pruning/geometry/relative_pose_refinement.hpp"

#include <cmath>
#include <numeric>

#include <ceres/ceres.h>
#include <ceres/rotation.h>
#include <gtest/gtest.h>

#include "geometry/synthetic_scene.hpp"
#include "sfm_pruning/geometry/epipolar_geometry.hpp"
#include "sfm_pruning/geometry/so3.hpp"

namespace sfm_pruning {
namespace {

// The truth moved by `rotation_deg` about a fixed axis and its direction tilted by about
// `direction_deg`.
RelativePose Perturbed(const RelativePose& truth, double rotation_deg, double direction_deg) {
  RelativePose start = truth;
  start.rotation = ExpSO3(DegToRad(rotation_deg) * Eigen::Vector3d(1.0, -2.0, 0.5).normalized()) * truth.rotation;
  const Eigen::Vector3d tilt = truth.translation.cross(Eigen::Vector3d(0.3, 1.0, -0.2)).normalized();
  start.translation = (truth.translation + std::tan(DegToRad(direction_deg)) * tilt).normalized();
  return start;
}

std::vector<int> AllIndices(size_t n) {
  std::vector<int> indices(n);
  std::iota(indices.begin(), indices.end(), 0);
  return indices;
}

// A two-view scene of `num_points` correspondences with `pixel_noise` px of noise, its pose refined
// from the truth moved by `rotation_deg` and tilted by `direction_deg`.
struct RefinedScene {
  testing::SyntheticScene scene;
  RelativePose truth;
  RelativePose pose;
  RelativePoseRefinementSummary summary;
};

RefinedScene RefineFromPerturbedTruth(int num_points, double pixel_noise, uint32_t seed, double rotation_deg,
                                      double direction_deg) {
  RefinedScene refined;
  // {points, pixel noise, outlier ratio, distortion, seed}
  refined.scene = testing::MakeSyntheticScene(2, {num_points, pixel_noise, 0.0, true, seed});
  refined.truth = testing::TrueRelativePose(refined.scene);
  refined.pose = Perturbed(refined.truth, rotation_deg, direction_deg);
  refined.summary = RefineRelativePose(refined.scene.bearings[0], refined.scene.bearings[1],
                                       AllIndices(static_cast<size_t>(num_points)), {}, &refined.pose);
  return refined;
}

double HalfSumOfSquaredErrors(const testing::SyntheticScene& scene, const std::vector<int>& indices,
                              const RelativePose& pose) {
  double cost = 0.0;
  for (const int k : indices) {
    const double e = AngularEpipolarError(pose, scene.bearings[0][k], scene.bearings[1][k]);
    cost += e * e;
  }
  return 0.5 * cost;
}

// The refinement as a ceres::Problem (one residual block per correspondence, the translation on
// ceres::SphereManifold): the reference the hand-written solver must agree with.
struct ReferenceCost {
  template <typename T>
  bool operator()(const T* delta, const T* translation, T* residual) const {
    using Vector3T = Eigen::Matrix<T, 3, 1>;
    const Vector3T r0_bi = rotated_bearing_i.cast<T>();
    Vector3T r_bi;
    ceres::AngleAxisRotatePoint(delta, r0_bi.data(), r_bi.data());
    const Eigen::Map<const Vector3T> t(translation);
    const Vector3T b_j = bearing_j.cast<T>();
    const Vector3T E_bi = t.cross(r_bi);
    residual[0] = b_j.dot(E_bi) / ceres::sqrt(E_bi.squaredNorm() + b_j.cross(t).squaredNorm() + T(1e-20));
    return true;
  }
  Eigen::Vector3d rotated_bearing_i;
  Eigen::Vector3d bearing_j;
};

void CeresReferenceRefinement(const testing::SyntheticScene& scene, const std::vector<int>& indices,
                              RelativePose* pose) {
  const Eigen::Matrix3d R0 = pose->rotation;
  double delta[3] = {0.0, 0.0, 0.0};
  Eigen::Vector3d translation = pose->translation.normalized();
  ceres::Problem problem;
  for (const int k : indices) {
    problem.AddResidualBlock(new ceres::AutoDiffCostFunction<ReferenceCost, 1, 3, 3>(new ReferenceCost{
                                 R0 * scene.bearings[0][k].normalized(), scene.bearings[1][k].normalized()}),
                             nullptr, delta, translation.data());
  }
  problem.SetManifold(translation.data(), new ceres::SphereManifold<3>());
  ceres::Solver::Options options;
  options.linear_solver_type = ceres::DENSE_QR;
  options.max_num_iterations = 200;
  options.function_tolerance = 1e-16;
  options.gradient_tolerance = 1e-16;
  options.parameter_tolerance = 1e-14;
  ceres::Solver::Summary summary;
  ceres::Solve(options, &problem, &summary);
  pose->rotation = ExpSO3(Eigen::Vector3d(delta[0], delta[1], delta[2])) * R0;
  pose->translation = translation.normalized();
}

TEST(RelativePoseRefinement, NoiseFreeConvergesToTheTruth) {
  for (uint32_t seed = 1; seed <= 5; ++seed) {
    const auto [scene, truth, pose, summary] = RefineFromPerturbedTruth(100, 0.0, seed, 3.0, 5.0);
    ASSERT_TRUE(summary.converged) << "seed " << seed;
    EXPECT_GT(summary.initial_cost, 1e-6);
    EXPECT_LT(summary.final_cost, 1e-20);
    EXPECT_LT(LogSO3(truth.rotation.transpose() * pose.rotation).norm(), 1e-8) << "seed " << seed;
    EXPECT_LT(AngleBetweenVectors(truth.translation, pose.translation), 1e-8) << "seed " << seed;
    EXPECT_NEAR(pose.translation.norm(), 1.0, 1e-12);
    EXPECT_NEAR((pose.rotation.transpose() * pose.rotation - Eigen::Matrix3d::Identity()).norm(), 0.0, 1e-12);
  }
}

TEST(RelativePoseRefinement, NoisyReachesALowerCostThanTheTruth) {
  for (uint32_t seed = 1; seed <= 5; ++seed) {
    // {points, pixel noise, outlier ratio, distortion, seed}
    const testing::SyntheticScene scene = testing::MakeSyntheticScene(2, {200, 1.0, 0.0, true, seed});
    const std::vector<int> indices = AllIndices(200);
    const RelativePose truth = testing::TrueRelativePose(scene);
    RelativePose pose = Perturbed(truth, 1.0, 2.0);
    const RelativePoseRefinementSummary summary =
        RefineRelativePose(scene.bearings[0], scene.bearings[1], indices, {}, &pose);
    ASSERT_TRUE(summary.converged);
    // The least-squares optimum fits the noisy bearings at least as well as the truth does, and
    // the reported cost is that of the returned pose.
    EXPECT_LE(summary.final_cost, HalfSumOfSquaredErrors(scene, indices, truth));
    EXPECT_NEAR(summary.final_cost, HalfSumOfSquaredErrors(scene, indices, pose), 1e-15);
    EXPECT_LT(RadToDeg(LogSO3(truth.rotation.transpose() * pose.rotation).norm()), 0.5) << "seed " << seed;
    EXPECT_LT(RadToDeg(AngleBetweenVectors(truth.translation, pose.translation)), 3.0) << "seed " << seed;
    // The same minimum as Ceres' Levenberg-Marquardt on the same cost (the reference below).
    RelativePose reference = Perturbed(truth, 1.0, 2.0);
    CeresReferenceRefinement(scene, indices, &reference);
    EXPECT_LT(LogSO3(reference.rotation.transpose() * pose.rotation).norm(), 1e-9) << "seed " << seed;
    EXPECT_LT(AngleBetweenVectors(reference.translation, pose.translation), 1e-9) << "seed " << seed;
  }
}

TEST(RelativePoseRefinement, TheCauchyLossResistsOutliers) {
  // {points, pixel noise, outlier ratio, distortion, seed}
  const testing::SyntheticScene scene = testing::MakeSyntheticScene(2, {200, 0.5, 0.1, true, 3});
  const std::vector<int> indices = AllIndices(200);
  const RelativePose truth = testing::TrueRelativePose(scene);
  RelativePose plain = truth;
  RelativePose robust = truth;
  RelativePoseRefinementOptions cauchy;
  cauchy.loss_scale_rad = DegToRad(0.05);
  ASSERT_TRUE(RefineRelativePose(scene.bearings[0], scene.bearings[1], indices, {}, &plain).converged);
  ASSERT_TRUE(RefineRelativePose(scene.bearings[0], scene.bearings[1], indices, cauchy, &robust).converged);
  const double plain_error = LogSO3(truth.rotation.transpose() * plain.rotation).norm();
  const double robust_error = LogSO3(truth.rotation.transpose() * robust.rotation).norm();
  EXPECT_LT(robust_error, 0.5 * plain_error);
  EXPECT_LT(RadToDeg(robust_error), 0.3);
}

TEST(RelativePoseRefinement, TheRotationCovariancePredictsTheError) {
  // Over independent noisy scenes, the mean squared rotation error of the refined pose equals the
  // mean trace of its predicted covariance (the expected squared norm of the increment), and no
  // error is far beyond the predicted standard deviation along the least determined axis.
  double squared_errors = 0.0;
  double predicted = 0.0;
  double worst_ratio = 0.0;
  constexpr int kScenes = 60;
  for (uint32_t seed = 1; seed <= kScenes; ++seed) {
    const auto [scene, truth, pose, summary] = RefineFromPerturbedTruth(60, 1.0, seed, 1.0, 2.0);
    ASSERT_TRUE(summary.converged) << "seed " << seed;
    ASSERT_TRUE(summary.rotation_covariance.allFinite()) << "seed " << seed;
    const double error = LogSO3(truth.rotation * pose.rotation.transpose()).norm();
    squared_errors += error * error;
    predicted += summary.rotation_covariance.trace();
    worst_ratio = std::max(worst_ratio, error / summary.RotationStdRad());
  }
  // 60 draws of a three-dimensional Gaussian: the ratio is 1 within about 10 % (one sigma).
  EXPECT_NEAR(squared_errors / predicted, 1.0, 0.4);
  EXPECT_LT(worst_ratio, 5.0);
}

TEST(RelativePoseRefinement, NoiseFreeHasNoRotationUncertaintyAndFewPointsAnInfiniteOne) {
  // {points, pixel noise, outlier ratio, distortion, seed}
  const testing::SyntheticScene scene = testing::MakeSyntheticScene(2, {40, 0.0, 0.0, true, 4});
  RelativePose pose = testing::TrueRelativePose(scene);
  const RelativePoseRefinementSummary exact =
      RefineRelativePose(scene.bearings[0], scene.bearings[1], AllIndices(40), {}, &pose);
  ASSERT_TRUE(exact.converged);
  EXPECT_LT(exact.RotationStdRad(), 1e-9);
  RelativePose five = testing::TrueRelativePose(scene);
  const RelativePoseRefinementSummary minimal =
      RefineRelativePose(scene.bearings[0], scene.bearings[1], {0, 1, 2, 3, 4}, {}, &five);
  EXPECT_TRUE(std::isinf(minimal.RotationStdRad()));
}

TEST(RelativePoseRefinement, FewerThanFiveCorrespondencesLeaveThePose) {
  // {points, pixel noise, outlier ratio, distortion, seed}
  const testing::SyntheticScene scene = testing::MakeSyntheticScene(2, {20, 0.0, 0.0, true, 1});
  const RelativePose start = Perturbed(testing::TrueRelativePose(scene), 3.0, 5.0);
  RelativePose pose = start;
  EXPECT_FALSE(RefineRelativePose(scene.bearings[0], scene.bearings[1], {0, 1, 2, 3}, {}, &pose).converged);
  EXPECT_EQ(pose.rotation, start.rotation);
  EXPECT_EQ(pose.translation, start.translation);
}

TEST(RelativePoseRefinement, ZeroIterationsOnlyEvaluate) {
  // {points, pixel noise, outlier ratio, distortion, seed}
  const testing::SyntheticScene scene = testing::MakeSyntheticScene(2, {50, 0.0, 0.0, true, 2});
  const std::vector<int> indices = AllIndices(50);
  const RelativePose start = Perturbed(testing::TrueRelativePose(scene), 3.0, 5.0);
  RelativePose pose = start;
  RelativePoseRefinementOptions none;
  none.max_num_iterations = 0;
  const RelativePoseRefinementSummary summary =
      RefineRelativePose(scene.bearings[0], scene.bearings[1], indices, none, &pose);
  EXPECT_TRUE(summary.converged);
  EXPECT_NEAR(summary.initial_cost, HalfSumOfSquaredErrors(scene, indices, start), 1e-15);
  EXPECT_EQ(summary.final_cost, summary.initial_cost);
  EXPECT_LT((pose.rotation - start.rotation).norm(), 1e-15);
}

}  // namespace
}  // namespace sfm_pruning
