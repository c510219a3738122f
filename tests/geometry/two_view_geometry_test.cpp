#include "sfm_pruning/geometry/two_view_geometry.hpp"

#include <algorithm>
#include <numeric>
#include <random>

#include <gtest/gtest.h>

#include "geometry/synthetic_scene.hpp"
#include "sfm_pruning/geometry/so3.hpp"
#include "sfm_pruning/util/error.hpp"

namespace sfm_pruning {
namespace {

// Features of both views in a shuffled order, so that feature index != correspondence index and
// the match bookkeeping is really exercised.
struct TwoViewInput {
  FeatureSet features_i, features_j;
  std::vector<FeatureMatch> matches;  // one per scene correspondence, in correspondence order
};

TwoViewInput MakeInput(const testing::SyntheticScene& scene, uint32_t seed) {
  const size_t n = scene.points.size();
  std::vector<IndexT> order_i(n), order_j(n);
  std::iota(order_i.begin(), order_i.end(), 0);
  std::iota(order_j.begin(), order_j.end(), 0);
  std::mt19937 rng(seed);
  std::shuffle(order_i.begin(), order_i.end(), rng);
  std::shuffle(order_j.begin(), order_j.end(), rng);
  TwoViewInput input;
  input.features_i.keypoints.resize(n);
  input.features_j.keypoints.resize(n);
  for (size_t k = 0; k < n; ++k) {
    const Eigen::Vector2d& p_i = scene.pixels[0][k];
    const Eigen::Vector2d& p_j = scene.pixels[1][k];
    input.features_i.keypoints[order_i[k]] = {static_cast<float>(p_i.x()), static_cast<float>(p_i.y())};
    input.features_j.keypoints[order_j[k]] = {static_cast<float>(p_j.x()), static_cast<float>(p_j.y())};
    input.matches.push_back({order_i[k], order_j[k]});
  }
  return input;
}

TEST(TwoViewGeometry, VerifiesAGoodPair) {
  // {points, pixel noise, outlier ratio, distortion, seed}
  const testing::SyntheticScene scene = testing::MakeSyntheticScene(2, {300, 0.5, 0.25, true, 1});
  const TwoViewInput input = MakeInput(scene, 5);
  const TwoViewGeometry geometry = EstimateTwoViewGeometry(input.features_i, scene.intrinsics[0], input.features_j,
                                                           scene.intrinsics[1], input.matches);
  ASSERT_TRUE(geometry.success) << geometry.reason;
  EXPECT_TRUE(geometry.reason.empty());
  RelativePose truth = RelativePoseBetween(scene.poses[0], scene.poses[1]);
  EXPECT_LT(RadToDeg(LogSO3(truth.rotation.transpose() * geometry.relative_pose.rotation).norm()), 0.5);
  EXPECT_LT(RadToDeg(AngleBetweenVectors(truth.translation, geometry.relative_pose.translation)), 0.5);
  EXPECT_EQ(geometry.num_inliers, static_cast<int>(geometry.inlier_matches.size()));
  EXPECT_DOUBLE_EQ(geometry.inlier_ratio, geometry.num_inliers / 300.0);
  // Inlier matches are input matches of true correspondences (bar the odd lucky outlier).
  int true_found = 0, true_total = 0, outliers_kept = 0;
  for (size_t k = 0; k < input.matches.size(); ++k) {
    const bool kept = std::find(geometry.inlier_matches.begin(), geometry.inlier_matches.end(), input.matches[k]) !=
                      geometry.inlier_matches.end();
    if (scene.is_outlier[k]) {
      outliers_kept += kept;
    } else {
      ++true_total;
      true_found += kept;
    }
  }
  EXPECT_GE(true_found, 0.95 * true_total);
  EXPECT_LE(outliers_kept, 0.05 * geometry.num_inliers);
}

TEST(TwoViewGeometry, RejectsRandomMatchesWithAReason) {
  // Features of two unrelated views: uniformly random pixels, matched one to one.
  // {points, pixel noise, outlier ratio, distortion, seed}
  const testing::SyntheticScene scene = testing::MakeSyntheticScene(2, {200, 0.0, 0.0, true, 1});
  std::mt19937 rng(11);
  std::uniform_real_distribution<double> x(0.0, 999.0), y(0.0, 749.0);
  FeatureSet features_i, features_j;
  std::vector<FeatureMatch> matches;
  for (IndexT k = 0; k < 200; ++k) {
    features_i.keypoints.push_back({static_cast<float>(x(rng)), static_cast<float>(y(rng))});
    features_j.keypoints.push_back({static_cast<float>(x(rng)), static_cast<float>(y(rng))});
    matches.push_back({k, k});
  }
  const TwoViewGeometry geometry =
      EstimateTwoViewGeometry(features_i, scene.intrinsics[0], features_j, scene.intrinsics[1], matches);
  EXPECT_FALSE(geometry.success);
  // Any 5-point model explains some random matches, but far below 25 % of them.
  EXPECT_LT(geometry.inlier_ratio, 0.25);
  EXPECT_TRUE(geometry.reason.find("too few inliers") != std::string::npos ||
              geometry.reason.find("inlier ratio too low") != std::string::npos)
      << geometry.reason;
}

TEST(TwoViewGeometry, RejectsTooFewMatchesBeforeRansac) {
  // {points, pixel noise, outlier ratio, distortion, seed}
  const testing::SyntheticScene scene = testing::MakeSyntheticScene(2, {20, 0.0, 0.0, true, 1});
  const TwoViewInput input = MakeInput(scene, 1);
  const TwoViewGeometry geometry = EstimateTwoViewGeometry(input.features_i, scene.intrinsics[0], input.features_j,
                                                           scene.intrinsics[1], input.matches);
  EXPECT_FALSE(geometry.success);
  EXPECT_NE(geometry.reason.find("too few matches: 20 < 30"), std::string::npos) << geometry.reason;
}

TEST(TwoViewGeometry, AMatchToAMissingFeatureIsAnError) {
  FeatureSet features;
  features.keypoints.resize(3);
  const CameraIntrinsics intrinsics = CameraIntrinsics::Pinhole(100, 100, 100.0, 50.0, 50.0);
  EXPECT_THROW(EstimateTwoViewGeometry(features, intrinsics, features, intrinsics, {{0, 3}}), Error);
}

}  // namespace
}  // namespace sfm_pruning
