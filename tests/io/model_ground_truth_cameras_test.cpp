// gt_cameras.txt reader: a hand-made file, malformed lines, and the real benchmark files.
#include <gtest/gtest.h>

#include <fstream>
#include <string>

#include "sfm_pruning/io/ground_truth_cameras.hpp"
#include "sfm_pruning/util/error.hpp"
#include "support/test_data.hpp"

namespace sfm_pruning {
namespace {
namespace fs = std::filesystem;

constexpr const char* kHeader = "# image_name width height fx fy cx cy skew r00 r01 r02 r10 r11 r12 r20 r21 r22 tx ty tz\n";
// R = rotation of 90 degrees about z (x -> y), t = (1, 2, 3): centre -R^T t = (-2, 1, -3).
constexpr const char* kRotatedCamera = "b.jpg 640 480 500 500 319.5 239.5 0 0 -1 0 1 0 0 0 0 1 1 2 3\n";

fs::path WriteText(const std::string& name, const std::string& text) {
  const fs::path path = testing::ScratchDir("gt_cameras_" + name) / "gt_cameras.txt";
  std::ofstream(path) << text;
  return path;
}

TEST(GroundTruthCameras, ReadsHandMadeFile) {
  const fs::path path = WriteText("hand", std::string(kHeader) +
                                              "a.jpg 3072 2048 2759.48 2764.16 1520.69 1006.81 0 "
                                              "1 0 0 0 1 0 0 0 1 0 0 0\n\n" +
                                              kRotatedCamera);
  const SfmData data = ReadGroundTruthCameras(path);
  ASSERT_EQ(data.views.size(), 2u);
  ASSERT_EQ(data.poses.size(), 2u);
  const View& a = data.views.at(0);
  EXPECT_EQ(a.filename, "a.jpg");
  EXPECT_EQ(a.width, 3072u);
  EXPECT_EQ(a.height, 2048u);
  EXPECT_TRUE(data.IsPosed(a));
  const CameraIntrinsics& K_a = data.IntrinsicsOf(a);
  EXPECT_EQ(K_a.model(), CameraModel::kPinholeFxFy);
  EXPECT_EQ(K_a.FocalX(), 2759.48);
  EXPECT_EQ(K_a.FocalY(), 2764.16);
  EXPECT_EQ(K_a.PrincipalPoint(), Eigen::Vector2d(1520.69, 1006.81));
  EXPECT_EQ(data.PoseOf(a).center, Eigen::Vector3d::Zero());

  const View& b = data.views.at(1);
  EXPECT_EQ(b.filename, "b.jpg");
  EXPECT_EQ(data.IntrinsicsOf(b).model(), CameraModel::kPinhole);
  const Pose& pose_b = data.PoseOf(b);
  EXPECT_LT((pose_b.center - Eigen::Vector3d(-2, 1, -3)).norm(), 1e-12);
  EXPECT_LT((pose_b.translation() - Eigen::Vector3d(1, 2, 3)).norm(), 1e-12);
  EXPECT_LT((pose_b.ToCamera(Eigen::Vector3d(1, 0, 0)) - Eigen::Vector3d(1, 3, 3)).norm(), 1e-12);
}

void ExpectErrorMentioning(const std::string& name, const std::string& text, const std::string& expected) {
  const fs::path path = WriteText(name, text);
  try {
    ReadGroundTruthCameras(path);
    FAIL() << "expected Error for " << name;
  } catch (const Error& e) {
    const std::string message = e.what();
    EXPECT_EQ(message.find('\n'), std::string::npos) << message;
    EXPECT_NE(message.find(path.string()), std::string::npos) << message;
    EXPECT_NE(message.find(expected), std::string::npos) << message;
  }
}

TEST(GroundTruthCameras, RejectsMalformedFilesWithOneLineNamingTheLine) {
  ExpectErrorMentioning("fields", std::string(kHeader) + "a.jpg 640 480 500 500 320 240 0 1 0 0\n", "line 2");
  ExpectErrorMentioning("number", std::string(kHeader) + "a.jpg 640 480 5x0 500 320 240 0 1 0 0 0 1 0 0 0 1 0 0 0\n",
                        "'5x0' is not a number");
  ExpectErrorMentioning("size", "a.jpg 640.5 480 500 500 320 240 0 1 0 0 0 1 0 0 0 1 0 0 0\n", "line 1");
  ExpectErrorMentioning("skew", "a.jpg 640 480 500 500 320 240 2 1 0 0 0 1 0 0 0 1 0 0 0\n", "skew");
  ExpectErrorMentioning("focal", "a.jpg 640 480 -500 500 320 240 0 1 0 0 0 1 0 0 0 1 0 0 0\n", "focal");
  ExpectErrorMentioning("rotation", "a.jpg 640 480 500 500 320 240 0 1 0 0 0 2 0 0 0 1 0 0 0\n", "rotation");
  ExpectErrorMentioning("reflection", "a.jpg 640 480 500 500 320 240 0 -1 0 0 0 1 0 0 0 1 0 0 0\n", "rotation");
  ExpectErrorMentioning("twice", std::string(kRotatedCamera) + kRotatedCamera, "listed twice");
  ExpectErrorMentioning("empty", kHeader, "no camera");
}

TEST(GroundTruthCameras, MissingFileNamesIt) {
  const fs::path missing = testing::ScratchDir("gt_cameras_missing") / "gt_cameras.txt";
  try {
    ReadGroundTruthCameras(missing);
    FAIL() << "expected Error";
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find(missing.string()), std::string::npos) << e.what();
  }
}

TEST(GroundTruthCameras, ReadsStrechaFountain) {
  PRUNESFM_REQUIRE_SHARED("datasets/strecha/fountain-P11/gt_cameras.txt", path);
  const SfmData data = ReadGroundTruthCameras(path);
  ASSERT_EQ(data.views.size(), 11u);
  EXPECT_EQ(data.views.at(0).filename, "0000.jpg");
  EXPECT_EQ(data.views.at(10).filename, "0010.jpg");
  // First line: R row 0 = (0.450927 -0.892535 0.00679989), t = (-3.48..., -1.19..., -9.84...).
  const Pose& pose = data.poses.at(0);
  EXPECT_NEAR(pose.rotation(0, 1), -0.892535, 1e-5);  // snapped to a rotation: within rounding
  EXPECT_LT((pose.translation() - Eigen::Vector3d(-3.48046703877, -1.19648323093, -9.84483520681)).norm(), 1e-4);
  EXPECT_NEAR(data.intrinsics.at(0).FocalX(), 2759.48, 1e-9);
  for (const auto& [id, pose_k] : data.poses) {
    EXPECT_LT((pose_k.rotation * pose_k.rotation.transpose() - Eigen::Matrix3d::Identity()).norm(), 1e-12);
  }
}

TEST(GroundTruthCameras, ReadsMiddleburyTemple) {
  PRUNESFM_REQUIRE_SHARED("datasets/middlebury/templeSparseRing/gt_cameras.txt", path);
  const SfmData data = ReadGroundTruthCameras(path);
  ASSERT_EQ(data.views.size(), 16u);
  EXPECT_EQ(data.views.at(0).filename, "templeSR0001.png");
  EXPECT_EQ(data.views.at(0).width, 640u);
  EXPECT_EQ(data.intrinsics.at(0).model(), CameraModel::kPinholeFxFy);
  EXPECT_NEAR(data.intrinsics.at(0).PrincipalPoint().x(), 302.32, 1e-12);
}

}  // namespace
}  // namespace sfm_pruning
