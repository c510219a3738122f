#include "sfm_pruning/global/distortion_evidence.hpp"

#include <cmath>

#include <gtest/gtest.h>

#include "bundle_test_scene.hpp"

namespace sfm_pruning {
namespace {

// The scene adjusted with every distortion coefficient at zero and held (focal and principal
// point free), as the engine's schedule leaves it before the test.
SfmData AdjustedWithDistortionHeld(const bundle_test::Scene& scene) {
  SfmData data = scene.truth;
  for (auto& [id, intrinsics] : data.intrinsics) {
    std::vector<double>& params = intrinsics.mutable_params();
    for (size_t k = camera_models::kFirstDistortionParam; k < params.size(); ++k) params[k] = 0.0;
  }
  BundleAdjustmentOptions held;
  held.refine_focal = true;
  EXPECT_TRUE(AdjustBundle(held, &data).success);
  return data;
}

BundleAdjustmentOptions FreeDistortion() {
  BundleAdjustmentOptions options;
  options.refine_focal = true;
  options.refine_distortion = true;
  return options;
}

TEST(BundleDistortionEvidence, CountsTheFreeCoefficientsOfTheCamerasInUse) {
  const bundle_test::Scene scene = bundle_test::MakeScene(bundle_test::NoisySceneOptions(100));
  EXPECT_EQ(NumFreeDistortionParameters(FreeDistortion(), scene.truth), 3u);  // pinhole: none; radial K3: 3
  BundleAdjustmentOptions held_camera = FreeDistortion();
  held_camera.constant_intrinsics.insert(1);
  EXPECT_EQ(NumFreeDistortionParameters(held_camera, scene.truth), 0u);
  EXPECT_EQ(NumFreeDistortionParameters(BundleAdjustmentOptions{}, scene.truth), 0u);
}

TEST(BundleDistortionEvidence, ARealLensDistortionPaysForItself) {
  const bundle_test::Scene scene = bundle_test::MakeScene(bundle_test::NoisySceneOptions(1000));
  SfmData data = AdjustedWithDistortionHeld(scene);
  const DistortionEvidence evidence = SelectDistortionByEvidence(FreeDistortion(), &data);
  ASSERT_TRUE(evidence.tested);
  EXPECT_TRUE(evidence.kept);
  EXPECT_EQ(evidence.num_parameters, 3u);
  EXPECT_NEAR(evidence.threshold, 3.0 * std::log(static_cast<double>(evidence.num_residuals)), 1e-9);
  EXPECT_GT(evidence.statistic, 10.0 * evidence.threshold);  // k1 = -0.08: tens of px at the corners (54x here)
  EXPECT_NEAR(data.intrinsics.at(1).DistortionParams()[0], -0.08, 0.01);
}

TEST(BundleDistortionEvidence, NoDistortionLeavesTheHeldModelUntouched) {
  bundle_test::SceneOptions options = bundle_test::NoisySceneOptions(1000);
  options.radial_distortion = {0.0, 0.0, 0.0};
  const bundle_test::Scene scene = bundle_test::MakeScene(options);
  SfmData data = AdjustedWithDistortionHeld(scene);
  const SfmData held = data;
  const DistortionEvidence evidence = SelectDistortionByEvidence(FreeDistortion(), &data);
  ASSERT_TRUE(evidence.tested);
  EXPECT_FALSE(evidence.kept) << "statistic " << evidence.statistic << ", threshold " << evidence.threshold;
  EXPECT_LT(evidence.statistic, evidence.threshold);
  EXPECT_TRUE(data == held);  // bitwise the held solution
}

}  // namespace
}  // namespace sfm_pruning
