#include "sfm_pruning/geometry/epipolar_geometry.hpp"

#include <cmath>

#include <Eigen/Geometry>
#include <gtest/gtest.h>

#include "sfm_pruning/geometry/triangulation.hpp"

namespace sfm_pruning {
namespace {

// Camera i at the origin, camera j one unit to the right, same orientation: t_ij = (-1, 0, 0).
// The point (0, 0, 5) lies in the epipolar plane y = 0.
const RelativePose kSideStep(Eigen::Matrix3d::Identity(), Eigen::Vector3d(-1, 0, 0));
const Eigen::Vector3d kBearingI(0, 0, 1);
const Eigen::Vector3d kBearingJ = Eigen::Vector3d(-1, 0, 5).normalized();

TEST(EpipolarGeometry, EssentialMatrixAnnihilatesCorrespondences) {
  EXPECT_NEAR(kBearingJ.dot(EssentialMatrix(kSideStep) * kBearingI), 0.0, 1e-15);
  const RelativePose general(Eigen::AngleAxisd(0.3, Eigen::Vector3d(1, 1, 0).normalized()).toRotationMatrix(),
                             Eigen::Vector3d(0.2, -0.4, 0.9));
  const Eigen::Vector3d X_i(0.5, -0.2, 4.0);
  const Eigen::Vector3d X_j = general.rotation * X_i + general.translation;
  EXPECT_NEAR(X_j.normalized().dot(EssentialMatrix(general) * X_i.normalized()), 0.0, 1e-15);
  EXPECT_NEAR(AngularEpipolarError(general, X_i, X_j), 0.0, 1e-15);
}

TEST(EpipolarGeometry, AngularErrorMatchesAHandComputedCase) {
  // Lift b_j out of the epipolar plane by delta. Sampson spreads the correction over both rays:
  // e = delta * |t x b_i| = delta, |b_j x t| = 5 / sqrt(26), error = delta / sqrt(1 + 25/26).
  const double delta = 1e-4;
  const Eigen::Vector3d lifted = std::cos(delta) * kBearingJ + std::sin(delta) * Eigen::Vector3d::UnitY();
  const double expected = delta / std::sqrt(1.0 + 25.0 / 26.0);
  EXPECT_NEAR(AngularEpipolarError(kSideStep, kBearingI, lifted), expected, 1e-4 * expected);
  // The scale of t does not matter.
  const RelativePose scaled(kSideStep.rotation, 7.0 * kSideStep.translation);
  EXPECT_NEAR(AngularEpipolarError(scaled, kBearingI, lifted), expected, 1e-4 * expected);
}

TEST(EpipolarGeometry, OnlyOneOfTheFourCandidatesPutsPointsInFront) {
  const RelativePose truth(Eigen::AngleAxisd(0.25, Eigen::Vector3d(0, 1, 0.2).normalized()).toRotationMatrix(),
                           Eigen::Vector3d(-0.8, 0.1, 0.2).normalized());
  const std::vector<Eigen::Vector3d> points = {{0.3, 0.2, 5.0}, {-1.0, 0.5, 7.0}, {0.8, -0.6, 4.0}};
  const std::array<RelativePose, 4> candidates = EssentialPoseCandidates(truth);
  const Eigen::Matrix3d E = EssentialMatrix(truth);
  int num_all_in_front = 0;
  for (const RelativePose& candidate : candidates) {
    // Same essential matrix up to sign.
    const Eigen::Matrix3d E_candidate = EssentialMatrix(candidate);
    EXPECT_TRUE(E_candidate.isApprox(E, 1e-12) || E_candidate.isApprox(-E, 1e-12));
    bool all_in_front = true;
    for (const Eigen::Vector3d& X_i : points) {
      const Eigen::Vector3d b_i = X_i.normalized();
      const Eigen::Vector3d b_j = (truth.rotation * X_i + truth.translation).normalized();
      EXPECT_NEAR(AngularEpipolarError(candidate, b_i, b_j), 0.0, 1e-14);
      const auto point = TriangulateTwoView(candidate, b_i, b_j);
      ASSERT_TRUE(point.has_value());
      all_in_front = all_in_front && point->depth_i > 0 && point->depth_j > 0;
    }
    if (all_in_front) {
      ++num_all_in_front;
      EXPECT_TRUE(candidate.rotation.isApprox(truth.rotation, 1e-12));
      EXPECT_TRUE(candidate.translation.isApprox(truth.translation, 1e-12));
    }
  }
  EXPECT_EQ(num_all_in_front, 1);
}

}  // namespace
}  // namespace sfm_pruning

namespace sfm_pruning {
namespace {

TEST(EpipolarGeometry, DecompositionOfAnEssentialMatrixContainsTheTruth) {
  const RelativePose truth(Eigen::AngleAxisd(-1.1, Eigen::Vector3d(0.3, 1, -0.2).normalized()).toRotationMatrix(),
                           Eigen::Vector3d(0.5, -0.2, 0.6).normalized());
  // Scale and sign of E are arbitrary.
  const RelativePose decomposed = RelativePoseFromEssential(-3.0 * EssentialMatrix(truth));
  EXPECT_NEAR(decomposed.rotation.determinant(), 1.0, 1e-12);
  EXPECT_NEAR(decomposed.translation.norm(), 1.0, 1e-12);
  int matches = 0;
  for (const RelativePose& candidate : EssentialPoseCandidates(decomposed)) {
    matches += candidate.rotation.isApprox(truth.rotation, 1e-12) && candidate.translation.isApprox(truth.translation, 1e-12);
  }
  EXPECT_EQ(matches, 1);
}

}  // namespace
}  // namespace sfm_pruning
