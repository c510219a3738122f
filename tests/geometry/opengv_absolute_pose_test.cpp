#include "sfm_pruning/geometry/opengv_absolute_pose.hpp"

#include <algorithm>
#include <atomic>
#include <cmath>
#include <string>
#include <thread>
#include <vector>

#include <gtest/gtest.h>

#include "geometry/synthetic_scene.hpp"
#include "sfm_pruning/geometry/so3.hpp"

namespace sfm_pruning {
namespace {

double RotationError(const Pose& a, const Pose& b) { return LogSO3(a.rotation.transpose() * b.rotation).norm(); }

// Distance from the camera to the scene centre: the scale of "1 % of scene depth".
double SceneDepth(const Pose& pose) { return pose.center.norm(); }

// Runs both solvers on five scenes and checks the pose error against the tolerances: rotation
// in radians, centre relative to the scene depth; also the recall of the true inliers.
void ExpectPoseRecovered(const testing::SyntheticViewOptions& scene_options, double max_rotation_error_rad,
                         double max_relative_center_error) {
  for (const auto solver : {AbsolutePoseOptions::Solver::kEpnp, AbsolutePoseOptions::Solver::kP3pKneip}) {
    for (uint32_t seed = 1; seed <= 5; ++seed) {
      testing::SyntheticViewOptions seeded = scene_options;
      seeded.seed = seed;
      const testing::SyntheticScene scene = testing::MakeSyntheticScene(1, seeded);
      AbsolutePoseOptions options;
      options.solver = solver;
      const AbsolutePoseResult result = EstimateAbsolutePose(scene.bearings[0], scene.points, options);
      const std::string label = "solver " + std::to_string(static_cast<int>(solver)) + " seed " + std::to_string(seed);
      ASSERT_TRUE(result.success) << label << ": " << result.reason;
      const Pose& truth = scene.poses[0];
      EXPECT_LT(RotationError(result.pose, truth), max_rotation_error_rad) << label;
      EXPECT_LT((result.pose.center - truth.center).norm(), max_relative_center_error * SceneDepth(truth)) << label;
      int true_inliers_found = 0;
      int true_inliers = 0;
      for (size_t k = 0; k < scene.is_outlier.size(); ++k) {
        if (scene.is_outlier[k]) continue;
        ++true_inliers;
        true_inliers_found += std::binary_search(result.inliers.begin(), result.inliers.end(), static_cast<int>(k));
      }
      EXPECT_GE(true_inliers_found, 0.95 * true_inliers) << label;
    }
  }
}

TEST(OpenGVAbsolutePose, NoiseFreeRecoversThePose) {
  // {points, pixel noise, outlier ratio, distortion, seed}
  ExpectPoseRecovered({100, 0.0, 0.0, true, 1}, 1e-6, 1e-6);
}

TEST(OpenGVAbsolutePose, NoisyWithOutliers) {
  // 0.5 px noise, 20 % outliers: < 0.5 deg and < 1 % of the scene depth.
  ExpectPoseRecovered({200, 0.5, 0.2, true, 1}, DegToRad(0.5), 0.01);
}

TEST(OpenGVAbsolutePose, PixelThresholdBecomesAnAngle) {
  AbsolutePoseOptions options;
  EXPECT_DOUBLE_EQ(AbsolutePoseThresholdRad(options), DegToRad(options.max_angular_error_deg));
  options.max_reprojection_error_px = 4.0;
  options.focal_length_px = 1000.0;
  EXPECT_DOUBLE_EQ(AbsolutePoseThresholdRad(options), std::atan(0.004));
}

TEST(OpenGVAbsolutePose, SameSeedSameOutput) {
  // {points, pixel noise, outlier ratio, distortion, seed}
  const testing::SyntheticScene scene = testing::MakeSyntheticScene(1, {200, 1.0, 0.3, true, 1});
  AbsolutePoseOptions options;
  options.ransac.seed = 7;
  const AbsolutePoseResult a = EstimateAbsolutePose(scene.bearings[0], scene.points, options);
  const AbsolutePoseResult b = EstimateAbsolutePose(scene.bearings[0], scene.points, options);
  ASSERT_TRUE(a.success);
  EXPECT_EQ(a.pose.rotation, b.pose.rotation);
  EXPECT_EQ(a.pose.center, b.pose.center);
  EXPECT_EQ(a.inliers, b.inliers);
}

// OpenGV's EPnP keeps its QR work buffers in function-static storage (Epnp::qr_solve), so two
// threads solving at once share them: results changed in the last digits and, on the first call,
// one thread could write through a null buffer (a segfault of GLOBAL_PRUNED with 2 threads).
// EstimateAbsolutePose serialises the EPnP solve; concurrent calls must equal sequential ones.
TEST(OpenGVAbsolutePose, ConcurrentCallsGiveTheSequentialResults) {
  std::vector<testing::SyntheticScene> scenes;
  std::vector<AbsolutePoseResult> sequential;
  AbsolutePoseOptions options;
  for (uint32_t seed = 1; seed <= 6; ++seed) {
    scenes.push_back(testing::MakeSyntheticScene(1, {150, 1.0, 0.3, true, seed}));
    sequential.push_back(EstimateAbsolutePose(scenes.back().bearings[0], scenes.back().points, options));
    ASSERT_TRUE(sequential.back().success);
  }
  std::atomic<int> mismatches{0};
  std::vector<std::thread> workers;
  for (int t = 0; t < 4; ++t) {
    workers.emplace_back([&]() {
      for (int round = 0; round < 15; ++round) {
        for (size_t k = 0; k < scenes.size(); ++k) {
          const AbsolutePoseResult result = EstimateAbsolutePose(scenes[k].bearings[0], scenes[k].points, options);
          const bool same = result.success && result.pose.rotation == sequential[k].pose.rotation &&
                            result.pose.center == sequential[k].pose.center && result.inliers == sequential[k].inliers;
          if (!same) ++mismatches;
        }
      }
    });
  }
  for (std::thread& worker : workers) worker.join();
  EXPECT_EQ(mismatches.load(), 0);
}

TEST(OpenGVAbsolutePose, FailsWithAReasonOnTooFewCorrespondences) {
  const std::vector<Eigen::Vector3d> bearings(5, Eigen::Vector3d(0, 0, 1));
  const std::vector<Eigen::Vector3d> points(5, Eigen::Vector3d(0, 0, 3));
  const AbsolutePoseResult result = EstimateAbsolutePose(bearings, points);
  EXPECT_FALSE(result.success);
  EXPECT_NE(result.reason.find("too few correspondences"), std::string::npos) << result.reason;
}

}  // namespace
}  // namespace sfm_pruning
