// Epipolar curves pass through the true correspondence; the choice of checks is deterministic.
#include <gtest/gtest.h>

#include "report_test_run.hpp"
#include "sfm_pruning/report/epipolar_check.hpp"
#include "sfm_pruning/report/epipolar_image.hpp"
#include "sfm_pruning/util/error.hpp"

namespace sfm_pruning::testing {
namespace {

void ExpectCurvesThroughObservations(const SfmData& scene, double tolerance_px) {
  size_t checked = 0;
  for (const auto& [id, landmark] : scene.structure) {
    if (id % 10 != 0) continue;
    const auto& [view_a, obs_a] = *landmark.observations.begin();
    for (const auto& [view_b, obs_b] : landmark.observations) {
      if (view_b == view_a) continue;
      const auto curve = EpipolarCurve(scene.intrinsics.at(0), scene.poses.at(view_a), scene.intrinsics.at(0),
                                       scene.poses.at(view_b), obs_a.x);
      ASSERT_FALSE(curve.empty());
      EXPECT_LT(DistanceToCurve(curve, obs_b.x), tolerance_px) << "landmark " << id << " views " << view_a << "-" << view_b;
      ++checked;
    }
  }
  EXPECT_GT(checked, 20u);
}

TEST(ReportEpipolar, PinholeLinePassesThroughTheCorrespondence) { ExpectCurvesThroughObservations(RingScene(12), 1e-3); }

TEST(ReportEpipolar, DistortedCurveBendsThroughTheCorrespondence) {
  // 240 samples of a curve bent by k1 = -0.2: the polyline stays within a tenth of a pixel.
  ExpectCurvesThroughObservations(RingScene(12, -0.2), 0.1);
}

TEST(ReportEpipolar, ChecksAreChosenFromTracksAndNeighbours) {
  const SfmData scene = RingScene(12);
  const std::vector<std::string> images = ChooseCheckImages(scene, 2);
  EXPECT_EQ(images, (std::vector<std::string>{"img_003.jpg", "img_009.jpg"}));
  const Eigen::Vector2d point = ChooseCheckPoint(scene, "img_003.jpg");
  const std::vector<std::string> others = ImagesSeeingRegion(scene, "img_003.jpg", point);
  ASSERT_EQ(others.size(), 3u);
  for (const std::string& other : others) EXPECT_NE(other, "img_003.jpg");
  const EpipolarCheck check = ComputeEpipolarCheck(scene, "img_003.jpg", point, others, &scene);
  ASSERT_EQ(check.others.size(), 3u);
  for (const EpipolarPanel& panel : check.others) {
    EXPECT_TRUE(panel.registered);
    ASSERT_TRUE(panel.matched_feature.has_value()) << "the chosen point is a feature whose track reaches " << panel.image;
    EXPECT_LT(DistanceToCurve(panel.estimated, *panel.matched_feature), 1e-3);
    EXPECT_LT(DistanceToCurve(panel.truth, *panel.matched_feature), 1e-3);
  }
  const std::vector<uint8_t> png = RenderEpipolarCheck(check, scene, {}, ".png");
  ASSERT_GT(png.size(), 8u);
  EXPECT_EQ(png[1], 'P');
  EXPECT_EQ(png[2], 'N');
  EXPECT_EQ(png, RenderEpipolarCheck(check, scene, {}, ".png"));
}

TEST(ReportEpipolar, BadRequestsAreOneLineErrors) {
  SfmData scene = RingScene(6);
  EXPECT_THROW(ComputeEpipolarCheck(scene, "missing.jpg", {10, 10}, {"img_001.jpg"}), Error);
  EXPECT_THROW(ComputeEpipolarCheck(scene, "img_000.jpg", {900, 10}, {"img_001.jpg"}), Error);
  EXPECT_THROW(ComputeEpipolarCheck(scene, "img_000.jpg", {10, 10}, {"nope.jpg"}), Error);
  scene.poses.erase(1);
  const EpipolarCheck check = ComputeEpipolarCheck(scene, "img_000.jpg", {10, 10}, {"img_001.jpg"});
  EXPECT_FALSE(check.others.at(0).registered);
  EXPECT_TRUE(check.others.at(0).estimated.empty());
  EpipolarImageOptions options;
  options.images_dir = std::filesystem::path("/nonexistent-image-folder");
  try {
    RenderEpipolarCheck(check, scene, options, ".png");
    FAIL() << "a missing image must be an error";
  } catch (const Error& e) {
    EXPECT_EQ(std::string(e.what()), "/nonexistent-image-folder/img_000.jpg: no such image file");
  }
}

}  // namespace
}  // namespace sfm_pruning::testing
