// View-graph focal calibration from the fundamental matrices of the verified pairs.
#include "sfm_pruning/global/focal_calibration.hpp"

#include <gtest/gtest.h>

#include "calibration_test_scene.hpp"

namespace sfm_pruning::calibration_test {
namespace {

PairInliers AllPairs(const Scene& scene) {
  PairInliers pairs;
  for (const auto& [pair, matches] : scene.matches) pairs.emplace(pair, &matches);
  return pairs;
}

double RelativeError(double estimate, double truth) { return std::abs(estimate - truth) / truth; }

// 16 views: the even ones with a 1000 px camera (intrinsic 0), the odd ones 1400 px (intrinsic 1).
Scene TwoCameraScene() {
  SceneOptions options;
  options.num_views = 16;
  options.second_focal_px = 1400.0;
  return MakeScene(options);
}

TEST(FocalCalibration, RecoversAFocalStarted30PercentTooLong) {
  const Scene scene = MakeScene({});
  SfmData listing = ListingWithFocalOff(scene, 1.3);
  const FocalCalibrationReport report = CalibrateFocalLengths({}, {0}, AllPairs(scene), scene.features, &listing);
  EXPECT_EQ(report.num_pairs_used, scene.matches.size());
  EXPECT_EQ(report.num_pairs_undefined, 0u);
  ASSERT_EQ(report.intrinsics.size(), 1u);
  const IntrinsicFocalCalibration& entry = report.intrinsics[0];
  EXPECT_TRUE(entry.accepted) << entry.reason;
  EXPECT_DOUBLE_EQ(entry.prior_focal, 1300.0);
  EXPECT_LT(RelativeError(listing.intrinsics.at(0).FocalLength(), 1000.0), 0.01);
  EXPECT_LT(entry.median_gap_estimated, 0.5 * entry.median_gap_prior);
  // Only the focal moved.
  EXPECT_EQ(listing.intrinsics.at(0).PrincipalPoint(), scene.truth.intrinsics.at(0).PrincipalPoint());
}

TEST(FocalCalibration, RecoversAFocalStarted30PercentTooShort) {
  const Scene scene = MakeScene({});
  SfmData listing = ListingWithFocalOff(scene, 0.7);
  const FocalCalibrationReport report = CalibrateFocalLengths({}, {0}, AllPairs(scene), scene.features, &listing);
  ASSERT_EQ(report.intrinsics.size(), 1u);
  EXPECT_TRUE(report.intrinsics[0].accepted) << report.intrinsics[0].reason;
  EXPECT_LT(RelativeError(listing.intrinsics.at(0).FocalLength(), 1000.0), 0.01);
}

TEST(FocalCalibration, CalibratesTwoCamerasJointly) {
  const Scene scene = TwoCameraScene();
  SfmData listing = ListingWithFocalOff(scene, 1.3);
  const FocalCalibrationReport report =
      CalibrateFocalLengths({}, {0, 1}, AllPairs(scene), scene.features, &listing);
  ASSERT_EQ(report.intrinsics.size(), 2u);
  EXPECT_TRUE(report.intrinsics[0].accepted && report.intrinsics[1].accepted);
  EXPECT_LT(RelativeError(listing.intrinsics.at(0).FocalLength(), 1000.0), 0.01);
  EXPECT_LT(RelativeError(listing.intrinsics.at(1).FocalLength(), 1400.0), 0.01);
}

TEST(FocalCalibration, TrustedCameraIsHeldAndHelpsTheOther) {
  const Scene scene = TwoCameraScene();
  SfmData listing = ListingWithFocalOff(scene, 1.0);
  listing.intrinsics.at(1).SetFocalLength(1400.0 * 0.75);
  const FocalCalibrationReport report = CalibrateFocalLengths({}, {1}, AllPairs(scene), scene.features, &listing);
  ASSERT_EQ(report.intrinsics.size(), 1u);
  EXPECT_EQ(report.intrinsics[0].intrinsic_id, 1u);
  EXPECT_DOUBLE_EQ(listing.intrinsics.at(0).FocalLength(), 1000.0);
  EXPECT_LT(RelativeError(listing.intrinsics.at(1).FocalLength(), 1400.0), 0.01);
}

TEST(FocalCalibration, TooFewPairsKeepThePrior) {
  const Scene scene = MakeScene({});
  SfmData listing = ListingWithFocalOff(scene, 1.3);
  PairInliers two_pairs;
  for (const auto& [pair, matches] : scene.matches) {
    if (two_pairs.size() < 2) two_pairs.emplace(pair, &matches);
  }
  const FocalCalibrationReport report = CalibrateFocalLengths({}, {0}, two_pairs, scene.features, &listing);
  ASSERT_EQ(report.intrinsics.size(), 1u);
  EXPECT_FALSE(report.intrinsics[0].accepted);
  EXPECT_NE(report.intrinsics[0].reason.find("too few pairs"), std::string::npos);
  EXPECT_DOUBLE_EQ(listing.intrinsics.at(0).FocalLength(), 1300.0);
}

}  // namespace
}  // namespace sfm_pruning::calibration_test
