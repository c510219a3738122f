#include "sfm_pruning/sfm/sfm_data.hpp"

#include <gtest/gtest.h>

#include "sfm_pruning/util/error.hpp"

namespace sfm_pruning {
namespace {

SfmData TwoViewScene() {
  SfmData data;
  for (IndexT id : {0u, 1u}) {
    View v;
    v.id_view = id;
    v.id_intrinsic = 0;
    v.id_pose = id;
    v.filename = "img_" + std::to_string(id) + ".jpg";
    v.width = 640;
    v.height = 480;
    data.views[id] = v;
  }
  data.intrinsics[0] = CameraIntrinsics::Pinhole(640, 480, 500, 320, 240);
  data.poses[0] = Pose();
  Landmark point;
  point.X = {0, 0, 5};
  point.observations[0] = {Eigen::Vector2d(320, 240), 3};
  data.structure[0] = point;
  return data;
}

TEST(SfmData, PosedViews) {
  const SfmData data = TwoViewScene();
  EXPECT_TRUE(data.IsPosed(0));
  EXPECT_FALSE(data.IsPosed(1));  // its pose id 1 is not in poses
  EXPECT_FALSE(data.IsPosed(7));  // no such view
  EXPECT_EQ(data.PosedViewIds(), std::vector<IndexT>{0});
}

TEST(SfmData, ValidationAcceptsConsistentData) { EXPECT_NO_THROW(ValidateSfmData(TwoViewScene(), "scene")); }

TEST(SfmData, ValidationRejectsDanglingReferences) {
  SfmData orphan_pose = TwoViewScene();
  orphan_pose.poses[9] = Pose();
  EXPECT_THROW(ValidateSfmData(orphan_pose, "scene"), Error);

  SfmData orphan_intrinsic = TwoViewScene();
  orphan_intrinsic.intrinsics[4] = CameraIntrinsics::Pinhole(1, 1, 1, 0, 0);
  EXPECT_THROW(ValidateSfmData(orphan_intrinsic, "scene"), Error);

  SfmData bad_observation = TwoViewScene();
  bad_observation.structure[0].observations[42] = Observation();
  try {
    ValidateSfmData(bad_observation, "scene.json");
    FAIL() << "expected an error";
  } catch (const Error& e) {
    EXPECT_EQ(std::string(e.what()), "scene.json: landmark 0 is observed in view 42, which does not exist");
  }

  SfmData wrong_key = TwoViewScene();
  wrong_key.views[5] = wrong_key.views[0];
  EXPECT_THROW(ValidateSfmData(wrong_key, "scene"), Error);
}

TEST(View, RelativeImagePath) {
  View v;
  v.filename = "a.jpg";
  EXPECT_EQ(v.RelativeImagePath(), "a.jpg");
  v.local_path = "sub";
  EXPECT_EQ(v.RelativeImagePath(), "sub/a.jpg");
  v.local_path = "sub/";
  EXPECT_EQ(v.RelativeImagePath(), "sub/a.jpg");
}

}  // namespace
}  // namespace sfm_pruning
