// Model format detection and dispatch (io/model_io.hpp).
#include <gtest/gtest.h>

#include <fstream>
#include <string>

#include "sfm_pruning/io/model_io.hpp"
#include "sfm_pruning/util/error.hpp"
#include "support/test_data.hpp"

namespace sfm_pruning {
namespace {
namespace fs = std::filesystem;

void Touch(const fs::path& path, const std::string& text = "") { std::ofstream(path) << text; }

TEST(ModelIo, DetectsFormatFromPath) {
  const fs::path dir = testing::ScratchDir("model_io_detect");
  fs::create_directories(dir / "sparse_bin");
  Touch(dir / "sparse_bin" / "cameras.bin");
  fs::create_directories(dir / "sparse_txt");
  Touch(dir / "sparse_txt" / "cameras.txt");
  Touch(dir / "sfm_data.json");
  Touch(dir / "sfm_data.bin");
  Touch(dir / "gt_cameras.txt");
  EXPECT_EQ(DetectModelFormat(dir / "sparse_bin"), ModelFormat::kColmapModel);
  EXPECT_EQ(DetectModelFormat(dir / "sparse_txt"), ModelFormat::kColmapModel);
  EXPECT_EQ(DetectModelFormat(dir / "sfm_data.json"), ModelFormat::kSfmData);
  EXPECT_EQ(DetectModelFormat(dir / "sfm_data.bin"), ModelFormat::kSfmData);
  EXPECT_EQ(DetectModelFormat(dir / "gt_cameras.txt"), ModelFormat::kGroundTruthCameras);
  Touch(dir / "cloud.ply");
  EXPECT_EQ(DetectModelFormat(dir / "cloud.ply"), ModelFormat::kPly);
  Touch(dir / "scene.mvs");
  EXPECT_EQ(DetectModelFormat(dir / "scene.mvs"), ModelFormat::kOpenMvsScene);
}

TEST(ModelIo, OutputFormatFollowsThePath) {
  EXPECT_EQ(OutputModelFormat("out/sfm_data.json"), ModelFormat::kSfmData);
  EXPECT_EQ(OutputModelFormat("out/sfm_data.bin"), ModelFormat::kSfmData);
  EXPECT_EQ(OutputModelFormat("out/points.ply"), ModelFormat::kPly);
  EXPECT_EQ(OutputModelFormat("out/gt_cameras.txt"), ModelFormat::kGroundTruthCameras);
  EXPECT_EQ(OutputModelFormat("out/scene.mvs"), ModelFormat::kOpenMvsScene);
  EXPECT_EQ(OutputModelFormat("out/sparse/0"), ModelFormat::kColmapModel);
}

TEST(ModelIo, RejectsMissingAndUnknownPaths) {
  const fs::path dir = testing::ScratchDir("model_io_reject");
  Touch(dir / "cloud.xyz");
  EXPECT_THROW(DetectModelFormat(dir / "missing.json"), Error);
  EXPECT_THROW(DetectModelFormat(dir / "cloud.xyz"), Error);
  EXPECT_THROW(DetectModelFormat(dir), Error);  // a folder without cameras.*
  try {
    ReadModel(dir / "missing.json");
    FAIL() << "expected Error";
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("missing.json"), std::string::npos) << e.what();
  }
}

TEST(ModelIo, ReadsGroundTruthCameras) {
  const fs::path path = testing::ScratchDir("model_io_gt") / "gt_cameras.txt";
  Touch(path, "a.png 640 480 500 500 320 240 0 1 0 0 0 1 0 0 0 1 0 0 1\n");
  const SfmData data = ReadModel(path);
  ASSERT_EQ(data.poses.size(), 1u);
  EXPECT_EQ(data.poses.at(0).center, Eigen::Vector3d(0, 0, -1));
}

// An OpenMVS scene reads as a model whose root path is the scene's folder (OpenMVS resolves image
// names against it), and writes back with the same cameras and poses.
TEST(ModelIo, ReadsAndWritesOpenMvsScenes) {
  PRUNESFM_REQUIRE_SHARED("formats/openmvs/scene.mvs", sample);
  const SfmData data = ReadModel(sample);
  EXPECT_EQ(data.root_path, sample.parent_path().string());
  EXPECT_EQ(data.PosedViewIds().size(), 11u);
  EXPECT_EQ(data.views.at(0).RelativeImagePath(), "images/00000.jpg");
  const fs::path out = testing::ScratchDir("model_io_mvs") / "copy.mvs";
  SfmData relative = data;
  relative.root_path.clear();  // image names stay relative
  WriteModel(relative, out);
  const SfmData back = ReadModel(out);
  EXPECT_EQ(back.views.at(0).RelativeImagePath(), "images/00000.jpg");
  EXPECT_EQ(back.intrinsics, data.intrinsics);
  for (const auto& [id, pose] : data.poses) {
    EXPECT_EQ(back.poses.at(id).rotation, pose.rotation);
    EXPECT_EQ(back.poses.at(id).center, pose.center);
  }
  EXPECT_EQ(back.structure.size(), data.structure.size());
}

}  // namespace
}  // namespace sfm_pruning
