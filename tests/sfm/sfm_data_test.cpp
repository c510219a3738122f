#include "sfm_pruning/sfm/sfm_data.hpp"

#include <gtest/gtest.h>

#include <limits>
#include <string>
#include <utility>
#include <vector>

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

TEST(SfmData, ValidationRejectsAViewOfAMissingIntrinsic) {
  SfmData data = TwoViewScene();
  data.views[1].id_intrinsic = 3;
  EXPECT_THROW(ValidateSfmData(data, "scene"), Error);
  data.views[1].id_intrinsic = kUndefinedIndex;  // unknown calibration is allowed
  EXPECT_NO_THROW(ValidateSfmData(data, "scene"));
}

// The message of ValidateSfmDataValues on `data`, empty when it passes.
std::string ValueProblem(const SfmData& data) {
  try {
    ValidateSfmDataValues(data, "scene.json");
  } catch (const Error& e) {
    return e.what();
  }
  return {};
}

TEST(SfmData, ValidationRejectsNumbersNoCameraOrPointHas) {
  EXPECT_EQ(ValueProblem(TwoViewScene()), "");
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const double inf = std::numeric_limits<double>::infinity();
  const std::vector<std::pair<CameraIntrinsics, std::string>> cameras = {
      {CameraIntrinsics::Pinhole(640, 480, nan, 320, 240), "intrinsic 0: a parameter is not a finite number (nan)"},
      {CameraIntrinsics::Pinhole(640, 480, inf, 320, 240), "intrinsic 0: a parameter is not a finite number (inf)"},
      {CameraIntrinsics::Pinhole(640, 480, 0, 320, 240), "intrinsic 0: focal length must be positive, got 0"},
      {CameraIntrinsics::Pinhole(640, 480, -500, 320, 240), "intrinsic 0: focal length must be positive, got -500"},
      {CameraIntrinsics::Pinhole(640, 480, 1e308, 320, 240), "intrinsic 0: focal length 1e+308 px is over 1000"},
      {CameraIntrinsics::Pinhole(640, 480, 500, nan, 240), "intrinsic 0: a parameter is not a finite number (nan)"},
      {CameraIntrinsics::Pinhole(0, 480, 500, 320, 240), "intrinsic 0: image size 0x480 is not a real image's"},
      {CameraIntrinsics::Pinhole(640, 480, 500, 1e308, 240),
       "intrinsic 0: principal point (1e+308, 240) is over 1000 image sides from the image"},
  };
  for (const auto& [intrinsics, message] : cameras) {
    SfmData data = TwoViewScene();
    data.intrinsics[0] = intrinsics;
    EXPECT_EQ(ValueProblem(data).rfind("scene.json: " + message, 0), 0u) << ValueProblem(data);
  }
  // A 50x telephoto (a 1.1 degree field of view) is a real lens.
  SfmData telephoto = TwoViewScene();
  telephoto.intrinsics[0] = CameraIntrinsics::Pinhole(640, 480, 32000, 320, 240);
  EXPECT_EQ(ValueProblem(telephoto), "");

  SfmData nan_rotation = TwoViewScene();
  nan_rotation.poses[0].rotation(1, 1) = nan;
  EXPECT_EQ(ValueProblem(nan_rotation), "scene.json: pose 0: the rotation is not finite");
  SfmData scaled_rotation = TwoViewScene();
  scaled_rotation.poses[0].rotation *= 2.0;
  EXPECT_EQ(ValueProblem(scaled_rotation),
            "scene.json: pose 0: the rotation is not a rotation matrix (orthonormal, determinant 1)");
  SfmData reflection = TwoViewScene();
  reflection.poses[0].rotation(2, 2) = -1.0;
  EXPECT_NE(ValueProblem(reflection), "");
  // A principal point off the image (a crop of a larger frame) is a real camera.
  SfmData cropped = TwoViewScene();
  cropped.intrinsics[0] = CameraIntrinsics::Pinhole(640, 480, 500, 2000, -900);
  EXPECT_EQ(ValueProblem(cropped), "");
  for (const double far : {inf, 1e308, -2e12}) {
    SfmData far_centre = TwoViewScene();
    far_centre.poses[0].center.x() = far;
    EXPECT_EQ(ValueProblem(far_centre), "scene.json: pose 0: the centre is not finite or beyond ±1e+12");
    SfmData far_point = TwoViewScene();
    far_point.structure[0].X.z() = far;
    EXPECT_EQ(ValueProblem(far_point), "scene.json: landmark 0: the position is not finite or beyond ±1e+12");
  }
  // Geocentric (ECEF) coordinates in metres are a real scene.
  SfmData geocentric = TwoViewScene();
  for (auto& [id, pose] : geocentric.poses) pose.center += Eigen::Vector3d(4.2e6, 0.7e6, 4.7e6);
  for (auto& [id, landmark] : geocentric.structure) landmark.X += Eigen::Vector3d(4.2e6, 0.7e6, 4.7e6);
  EXPECT_EQ(ValueProblem(geocentric), "");
  SfmData nan_point = TwoViewScene();
  nan_point.structure[0].X.z() = nan;
  EXPECT_EQ(ValueProblem(nan_point), "scene.json: landmark 0: the position is not finite or beyond ±1e+12");
  for (const double far : {nan, 1e308}) {
    SfmData far_pixel = TwoViewScene();
    far_pixel.structure[0].observations[0].x.x() = far;
    EXPECT_EQ(ValueProblem(far_pixel),
              "scene.json: landmark 0: its observation in view 0 is not finite or beyond ±1e+09 pixels");
  }
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
