// SIFT, matching and the two-view verification on rendered images with exact ground truth: the
// relative pose the front end recovers is the true one.
#include <gtest/gtest.h>

#include <cmath>

#include <opencv2/core.hpp>
#include <opencv2/imgproc.hpp>

#include "features/rendered_scene.hpp"
#include "sfm_pruning/features/descriptor_matching.hpp"
#include "sfm_pruning/features/sift_extraction.hpp"
#include "sfm_pruning/geometry/two_view_geometry.hpp"

namespace sfm_pruning::testing {
namespace {

double AngleDeg(const Eigen::Matrix3d& R) {
  return std::acos(std::clamp((R.trace() - 1.0) / 2.0, -1.0, 1.0)) * 180.0 / M_PI;
}

TEST(SiftExtraction, FeaturesAreStrongestFirstCappedAndInFullImagePixels) {
  const RenderedCamera camera = RoomCameras(1)[0];
  const cv::Mat image = RenderRoom(camera);
  SiftOptions options;
  options.max_features = 400;
  const FeatureSet features = ExtractSift(image, options);
  ASSERT_EQ(features.size(), 400u);
  ASSERT_EQ(features.descriptors.size(), 400u);
  // Extracting from a 2x larger copy downscaled back (max_image_size) gives keypoints at twice
  // the coordinates: compare the strongest ones by nearest neighbour.
  cv::Mat large;
  cv::resize(image, large, cv::Size(), 2.0, 2.0, cv::INTER_CUBIC);
  SiftOptions capped = options;
  capped.max_image_size = image.cols;
  const FeatureSet scaled = ExtractSift(large, capped);
  int close = 0;
  for (size_t k = 0; k < 100; ++k) {
    const Keypoint& a = features.keypoints[k];
    for (const Keypoint& b : scaled.keypoints) {
      if (std::hypot(b.x - (2 * a.x + 0.5), b.y - (2 * a.y + 0.5)) < 0.5 && std::abs(b.scale / a.scale - 2) < 0.2) {
        ++close;
        break;
      }
    }
  }
  EXPECT_GE(close, 90);
}

TEST(TwoViewFrontEnd, RecoversTheRenderedRelativePose) {
  const std::vector<RenderedCamera> cameras = RoomCameras(2);
  FeaturesPerView features;
  SiftOptions sift;
  sift.max_features = 2000;
  for (IndexT k = 0; k < 2; ++k) features[k] = ExtractSift(RenderRoom(cameras[k]), sift);
  ASSERT_GE(features[0].size(), 1000u);
  const PairwiseMatches matches = MatchDescriptors(features, {{0, 1}}, {});
  ASSERT_EQ(matches.count({0, 1}), 1u);
  ASSERT_GE(matches.at({0, 1}).size(), 300u);

  const CameraIntrinsics intrinsics = CameraIntrinsics::Pinhole(480, 360, cameras[0].focal, 239.5, 179.5);
  const TwoViewGeometry geometry =
      EstimateTwoViewGeometry(features[0], intrinsics, features[1], intrinsics, matches.at({0, 1}));
  ASSERT_TRUE(geometry.success) << geometry.reason;
  EXPECT_GE(geometry.inlier_ratio, 0.8);
  const Pose& p0 = cameras[0].pose;
  const Pose& p1 = cameras[1].pose;
  const Eigen::Matrix3d R01 = p1.rotation * p0.rotation.transpose();
  const Eigen::Vector3d t01 = (p1.translation() - R01 * p0.translation()).normalized();
  EXPECT_LT(AngleDeg(geometry.relative_pose.rotation.transpose() * R01), 0.1);
  const double t_angle =
      std::acos(std::clamp(geometry.relative_pose.translation.normalized().dot(t01), -1.0, 1.0)) * 180.0 / M_PI;
  EXPECT_LT(t_angle, 1.0);
}

}  // namespace
}  // namespace sfm_pruning::testing
