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
}

TEST(ModelIo, OutputFormatFollowsThePath) {
  EXPECT_EQ(OutputModelFormat("out/sfm_data.json"), ModelFormat::kSfmData);
  EXPECT_EQ(OutputModelFormat("out/sfm_data.bin"), ModelFormat::kSfmData);
  EXPECT_EQ(OutputModelFormat("out/points.ply"), ModelFormat::kPly);
  EXPECT_EQ(OutputModelFormat("out/gt_cameras.txt"), ModelFormat::kGroundTruthCameras);
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

}  // namespace
}  // namespace sfm_pruning
