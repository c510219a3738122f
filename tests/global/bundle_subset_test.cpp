#include "sfm_pruning/global/subset_bundle_adjustment.hpp"

#include <cmath>

#include <gtest/gtest.h>

#include "bundle_test_scene.hpp"

namespace sfm_pruning {
namespace {

using bundle_test::InlierRmsPx;
using bundle_test::Scene;

SfmData PerturbedScene(const Scene& scene) {
  SfmData data = scene.truth;
  bundle_test::PerturbPoses(1.0, 0.01, scene.radius, 11, &data);
  bundle_test::PerturbPoints(0.01, scene.radius, 12, &data);
  return data;
}

TEST(SubsetBundleAdjustment, AdjustsOnASubsetAndRetriangulatesTheOtherLandmarks) {
  const Scene scene = bundle_test::MakeScene(bundle_test::NoisySceneOptions(1000));
  SfmData data = PerturbedScene(scene);
  ASSERT_GT(InlierRmsPx(data, scene), 10.0);

  // About 900 landmarks per view; 150 per view on a 4 x 4 grid.
  const BundleAdjustmentResult result = AdjustBundleOnSubset({}, {150, 4}, {}, &data);
  ASSERT_TRUE(result.success) << result.message;
  EXPECT_GE(result.num_landmarks, 150u);
  EXPECT_LT(result.num_landmarks, 600u);
  EXPECT_GT(result.seconds, 0.0);
  EXPECT_EQ(data.structure.size(), 1000u);  // every landmark kept, the others re-triangulated
  EXPECT_LT(InlierRmsPx(data, scene), 1.6);  // DLT points and 1 px noise

  bundle_test::AlignToTruth(scene.truth, &data);
  for (const auto& [id, pose] : data.poses) {
    EXPECT_LT(RadToDeg(RotationAngleBetween(pose.rotation, scene.truth.poses.at(id).rotation)), 0.1) << id;
    EXPECT_LT((pose.center - scene.truth.poses.at(id).center).norm(), 0.005 * scene.radius) << id;
  }
}

TEST(SubsetBundleAdjustment, WithoutACapItIsThePlainAdjustment) {
  const Scene scene = bundle_test::MakeScene(bundle_test::NoisySceneOptions(200));
  SfmData subset = PerturbedScene(scene);
  SfmData plain = subset;
  const BundleAdjustmentResult from_subset = AdjustBundleOnSubset({}, {0, 8}, {}, &subset);
  const BundleAdjustmentResult from_plain = AdjustBundle({}, &plain);
  ASSERT_TRUE(from_subset.success);
  EXPECT_EQ(from_subset.final_cost, from_plain.final_cost);
  EXPECT_TRUE(subset == plain);
}

TEST(SubsetBundleAdjustment, FailureLeavesTheSceneUntouched) {
  SfmData data = bundle_test::MakeScene({}).truth;
  data.poses.clear();
  const SfmData before = data;
  EXPECT_FALSE(AdjustBundleOnSubset({}, {10, 4}, {}, &data).success);
  EXPECT_TRUE(data == before);
}

}  // namespace
}  // namespace sfm_pruning
