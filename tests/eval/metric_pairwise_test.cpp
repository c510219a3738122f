// Pairwise relative pose errors and the AUC of whole models, on scenes where every pair's
// error is known in closed form.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <string>

#include "sfm_pruning/eval/model_evaluation.hpp"
#include "sfm_pruning/eval/relative_pose_error.hpp"
#include "sfm_pruning/util/error.hpp"

namespace sfm_pruning {
namespace {

constexpr double kRadius = 2.0;
constexpr int kNumCameras = 5;
// RotationAngleBetween takes acos of (trace - 1) / 2, which near identity resolves angles only
// to ~3e-8 rad (2e-6 deg); AUCs of exact models therefore reach 100 only to ~1e-5.
constexpr double kZeroAngleToleranceDeg = 1e-5;
constexpr double kAucTolerance = 1e-4;

Eigen::Matrix3d RotationAbout(const Eigen::Vector3d& axis, double angle_deg) {
  return Eigen::AngleAxisd(DegToRad(angle_deg), axis.normalized()).toRotationMatrix();
}

// Camera "img0.jpg" at the origin, cameras img1..img4 on a circle of radius kRadius in the plane
// z = 0 around it, each with an arbitrary but distinct orientation.
SfmData RingScene() {
  SfmData data;
  for (int k = 0; k < kNumCameras; ++k) {
    const IndexT id = static_cast<IndexT>(k);
    View view;
    view.id_view = view.id_intrinsic = view.id_pose = id;
    view.filename = "img" + std::to_string(k) + ".jpg";
    data.views[id] = view;
    data.intrinsics[id] = CameraIntrinsics::Pinhole(640, 480, 500.0, 320.0, 240.0);
    const double angle = 2.0 * M_PI * (k - 1) / (kNumCameras - 1);
    const Eigen::Vector3d center =
        k == 0 ? Eigen::Vector3d::Zero() : Eigen::Vector3d(kRadius * std::cos(angle), kRadius * std::sin(angle), 0.0);
    data.poses[id] = Pose(RotationAbout(Eigen::Vector3d(1.0, 2.0 * k, 3.0 - k), 20.0 * k + 7.0), center);
  }
  return data;
}

// The ring seen in another frame: scaled, rotated and shifted, as a real estimate would be.
SfmData InAnotherFrame(const SfmData& data) {
  Similarity3 frame;
  frame.scale = 0.37;
  frame.rotation = RotationAbout(Eigen::Vector3d(-1.0, 0.5, 2.0), 131.0);
  frame.translation = Eigen::Vector3d(10.0, -4.0, 2.5);
  SfmData moved = data;
  for (auto& [id, pose] : moved.poses) pose = frame.Apply(pose);
  return moved;
}

TEST(PairwisePoseError, GroundTruthAgainstItselfGivesHundred) {
  const SfmData truth = RingScene();
  const EvaluationReport report = EvaluateModel(InAnotherFrame(truth), truth);
  EXPECT_EQ(report.num_ground_truth_images, 5u);
  EXPECT_EQ(report.num_registered_images, 5u);
  EXPECT_EQ(report.num_pairs, 10u);
  EXPECT_EQ(report.num_failed_pairs, 0u);
  ASSERT_EQ(report.auc.size(), 3u);
  for (const AucAtThreshold& auc : report.auc) EXPECT_NEAR(auc.auc_percent, 100.0, kAucTolerance) << auc.threshold_deg;
  ASSERT_TRUE(report.alignment.has_value());
  EXPECT_EQ(report.alignment->num_inliers, 5u);
  EXPECT_LT(report.alignment->median_position_error, 1e-9);
  EXPECT_LT(report.alignment->mean_rotation_error_deg, kZeroAngleToleranceDeg);
}

// Camera 0 turned by 2 degrees about its own optical axis and lifted along z so that it sees each
// ring camera 4 degrees off: every pair (0, j) has rotation error exactly 2 (R_0j changes by the
// turn) and translation error exactly 4 (t_0j = R_j (c_0 - c_j), the angle between c_0 - c_j
// and c_0' - c_j with the lift perpendicular to the ring). Pairs without camera 0 are exact.
SfmData PerturbFirstCamera(const SfmData& truth) {
  SfmData estimate = truth;
  Pose& pose = estimate.poses.at(0);
  pose.rotation = RotationAbout(Eigen::Vector3d::UnitZ(), 2.0) * pose.rotation;
  pose.center += Eigen::Vector3d(0.0, 0.0, kRadius * std::tan(DegToRad(4.0)));
  return estimate;
}

TEST(PairwisePoseError, PerturbedCameraHasHandComputedErrors) {
  const SfmData truth = RingScene();
  const SfmData estimate = PerturbFirstCamera(truth);
  for (IndexT j = 1; j < kNumCameras; ++j) {
    const RelativePoseError error =
        ComputeRelativePoseError(truth.poses.at(0), truth.poses.at(j), estimate.poses.at(0), estimate.poses.at(j));
    EXPECT_NEAR(error.rotation_deg, 2.0, 1e-9) << j;
    EXPECT_NEAR(error.translation_deg, 4.0, 1e-9) << j;
    EXPECT_NEAR(error.MaxDeg(), 4.0, 1e-9) << j;
  }
  const RelativePoseError untouched =
      ComputeRelativePoseError(truth.poses.at(1), truth.poses.at(3), estimate.poses.at(1), estimate.poses.at(3));
  EXPECT_NEAR(untouched.rotation_deg, 0.0, kZeroAngleToleranceDeg);
  EXPECT_NEAR(untouched.translation_deg, 0.0, kZeroAngleToleranceDeg);

  // 10 pairs: 6 with error 0, 4 with error 4. By pose_auc.hpp's formula:
  //   t = 3:  recall 6/10 held over [0, 3]                          -> 60
  //   t = 5:  (4 - 0) (0.6 + 0.7) / 2 = 2.6, then 1.0 over [4, 5]   -> 3.6 / 5  = 72
  //   t = 10: 2.6 + 6 * 1.0                                         -> 8.6 / 10 = 86
  const EvaluationReport report = EvaluateModel(InAnotherFrame(estimate), truth);
  ASSERT_EQ(report.auc.size(), 3u);
  EXPECT_NEAR(report.auc[0].auc_percent, 60.0, kAucTolerance);
  EXPECT_NEAR(report.auc[1].auc_percent, 72.0, kAucTolerance);
  EXPECT_NEAR(report.auc[2].auc_percent, 86.0, kAucTolerance);
}

TEST(PairwisePoseError, MissingImageLowersAucByItsPairs) {
  const SfmData truth = RingScene();
  SfmData estimate = InAnotherFrame(truth);
  estimate.poses.erase(2);  // img2 not registered: its N - 1 = 4 pairs of N (N - 1) / 2 = 10 fail
  const EvaluationReport report = EvaluateModel(estimate, truth);
  EXPECT_EQ(report.num_registered_images, 4u);
  EXPECT_EQ(report.num_failed_pairs, 4u);
  const double expected = 100.0 * (1.0 - 4.0 / 10.0);
  for (const AucAtThreshold& auc : report.auc) EXPECT_NEAR(auc.auc_percent, expected, kAucTolerance) << auc.threshold_deg;
}

TEST(PairwisePoseError, MissingPairsAreInfiniteInNameOrder) {
  SfmData truth = RingScene();
  std::vector<MatchedCamera> cameras;
  for (const auto& [id, view] : truth.views) cameras.push_back({view.filename, truth.poses.at(id), truth.poses.at(id)});
  cameras[1].estimate.reset();
  const std::vector<double> errors = PairwisePoseErrorsDeg(cameras);
  ASSERT_EQ(errors.size(), 10u);
  // Order (0,1) (0,2) (0,3) (0,4) (1,2) (1,3) (1,4) (2,3) (2,4) (3,4): camera 1 is in 0, 4, 5, 6.
  for (size_t k : {0u, 4u, 5u, 6u}) EXPECT_TRUE(std::isinf(errors[k])) << k;
  for (size_t k : {1u, 2u, 3u, 7u, 8u, 9u}) EXPECT_NEAR(errors[k], 0.0, kZeroAngleToleranceDeg) << k;
}

TEST(PairwisePoseError, CoincidentCentres) {
  const Pose a(Eigen::Matrix3d::Identity(), Eigen::Vector3d(1.0, 2.0, 3.0));
  const Pose b(RotationAbout(Eigen::Vector3d::UnitY(), 30.0), Eigen::Vector3d(1.0, 2.0, 3.0));
  const Pose c(RotationAbout(Eigen::Vector3d::UnitY(), 30.0), Eigen::Vector3d(1.0, 2.0, 4.0));
  EXPECT_EQ(ComputeRelativePoseError(a, b, a, b).translation_deg, 0.0);    // both coincident
  EXPECT_EQ(ComputeRelativePoseError(a, c, a, b).translation_deg, 180.0);  // estimate lost the baseline
  EXPECT_EQ(ComputeRelativePoseError(a, b, a, c).translation_deg, 180.0);  // estimate invented one
}

TEST(ModelEvaluation, NoCommonImageNamesBothCounts) {
  const SfmData truth = RingScene();
  SfmData estimate = truth;
  for (auto& [id, view] : estimate.views) view.filename = "other_" + view.filename;
  estimate.poses.erase(4);
  try {
    EvaluateModel(estimate, truth, {}, "est.json", "gt_cameras.txt");
    FAIL() << "expected Error";
  } catch (const Error& e) {
    const std::string message = e.what();
    EXPECT_NE(message.find("est.json"), std::string::npos) << message;
    EXPECT_NE(message.find("estimate: 4"), std::string::npos) << message;
    EXPECT_NE(message.find("ground truth: 5"), std::string::npos) << message;
  }
}

TEST(ModelEvaluation, MatchesByBasename) {
  const SfmData truth = RingScene();
  SfmData estimate = InAnotherFrame(truth);
  for (auto& [id, view] : estimate.views) view.filename = "images/" + view.filename;
  estimate.views.at(3).filename = "extra.jpg";  // an image the ground truth does not know
  const CameraMatching matching = MatchCamerasByName(estimate, truth);
  EXPECT_EQ(matching.NumRegistered(), 4u);
  EXPECT_EQ(matching.num_estimate_images, 5u);
  EXPECT_EQ(matching.num_unmatched_estimate_images, 1u);
  EXPECT_FALSE(matching.cameras[3].estimate.has_value());
  EXPECT_EQ(matching.cameras[3].name, "img3.jpg");
}

}  // namespace
}  // namespace sfm_pruning
