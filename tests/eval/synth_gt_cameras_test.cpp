// gt_cameras.txt written for a synthetic scene reads back as the same cameras.
#include <gtest/gtest.h>

#include "sfm_pruning/eval/synthetic_scene.hpp"
#include "sfm_pruning/io/ground_truth_cameras.hpp"
#include "sfm_pruning/util/error.hpp"
#include "support/test_data.hpp"

namespace sfm_pruning {
namespace {

TEST(SyntheticGtCameras, RoundTripsThroughTheDatasetReader) {
  SyntheticSceneOptions options;
  options.scene = "courtyard";
  options.num_views = 6;
  options.point_density_scale = 0.2;
  const SyntheticScene scene = GenerateSyntheticScene(options);
  const auto path = testing::ScratchDir("synth_gt_cameras") / "gt_cameras.txt";
  WriteGroundTruthCameras(scene.ground_truth, path);
  const SfmData read = ReadGroundTruthCameras(path);
  ASSERT_EQ(read.views.size(), scene.ground_truth.views.size());
  // The reader numbers cameras in file order, which is view id order.
  for (const auto& [id, view] : scene.ground_truth.views) {
    const View& back = read.views.at(id);
    EXPECT_EQ(back.filename, view.filename);
    EXPECT_EQ(back.width, view.width);
    const Pose& expected = scene.ground_truth.PoseOf(view);
    const Pose& actual = read.PoseOf(back);
    EXPECT_LT(RotationAngleBetween(expected.rotation, actual.rotation), 1e-12);
    EXPECT_LT((expected.center - actual.center).norm(), 1e-12);
    EXPECT_DOUBLE_EQ(read.IntrinsicsOf(back).FocalLength(), scene.ground_truth.IntrinsicsOf(view).FocalLength());
    EXPECT_EQ(read.IntrinsicsOf(back).PrincipalPoint(), scene.ground_truth.IntrinsicsOf(view).PrincipalPoint());
  }
}

TEST(SyntheticGtCameras, RefusesDistortedCameras) {
  SfmData data;
  data.intrinsics[0] = CameraIntrinsics(CameraModel::kPinholeRadialK1, 640, 480, {500.0, 320.0, 240.0, 0.1});
  View view;
  view.id_view = view.id_pose = 0;
  view.id_intrinsic = 0;
  view.filename = "a.jpg";
  data.views[0] = view;
  data.poses[0] = Pose();
  const auto path = testing::ScratchDir("synth_gt_cameras_distorted") / "gt_cameras.txt";
  EXPECT_THROW(WriteGroundTruthCameras(data, path), Error);
  EXPECT_FALSE(std::filesystem::exists(path));
}

}  // namespace
}  // namespace sfm_pruning
