// sfm_data.json files written by OpenMVG 2.1 itself (../shared/formats/openmvg/sceaux_castle).
#include <gtest/gtest.h>

#include <algorithm>
#include <nlohmann/json.hpp>
#include <sstream>
#include <string>
#include <vector>

#include "sfm_pruning/io/openmvg_sfm_data.hpp"
#include "sfm_pruning/util/atomic_file.hpp"
#include "support/test_data.hpp"

namespace sfm_pruning {
namespace {

namespace fs = std::filesystem;

constexpr char kImageListing[] = "formats/openmvg/sceaux_castle/matches/sfm_data.json";
constexpr char kReconstruction[] = "formats/openmvg/sceaux_castle/reconstruction_global/sfm_data.json";

// Makes two cereal documents comparable when only hash-map order differs: arrays of
// {"key", "value"} are sorted by key, and shared-pointer ids (which follow the array order) are
// dropped after checking that they are the archive's ids.
void Canonicalize(nlohmann::json* node) {
  if (node->is_object()) {
    if (node->contains("ptr_wrapper")) (*node)["ptr_wrapper"].erase("id");
    for (auto& [name, child] : node->items()) Canonicalize(&child);
  } else if (node->is_array()) {
    for (auto& child : *node) Canonicalize(&child);
    if (!node->empty() && node->front().is_object() && node->front().contains("key")) {
      std::sort(node->begin(), node->end(),
                [](const nlohmann::json& a, const nlohmann::json& b) { return a["key"] < b["key"]; });
    }
  }
}

std::vector<std::string> SortedLines(const std::string& text) {
  std::vector<std::string> lines;
  std::istringstream in(text);
  for (std::string line; std::getline(in, line);) lines.push_back(line);
  std::sort(lines.begin(), lines.end());
  return lines;
}

// Our writer's output equals OpenMVG's file up to array order: same JSON once canonicalized, and
// the same multiset of lines, which also pins down indentation and number formatting.
void ExpectSameAsOpenMvgModuloOrder(const fs::path& real, const std::string& name) {
  const fs::path ours = testing::ScratchDir("openmvg_sfm_data_real_" + name) / "sfm_data.json";
  WriteSfmData(ReadSfmData(real), ours);
  const std::string real_text = ReadFileToString(real);
  const std::string our_text = ReadFileToString(ours);
  EXPECT_EQ(SortedLines(our_text), SortedLines(real_text));
  nlohmann::json real_json = nlohmann::json::parse(real_text);
  nlohmann::json our_json = nlohmann::json::parse(our_text);
  Canonicalize(&real_json);
  Canonicalize(&our_json);
  EXPECT_TRUE(real_json == our_json);
  // Read back, our file gives the same scene.
  EXPECT_TRUE(ReadSfmData(ours) == ReadSfmData(real));
}

TEST(OpenMvgSfmDataRealFiles, ImageListingLoads) {
  PRUNESFM_REQUIRE_SHARED(kImageListing, path);
  const SfmData data = ReadSfmData(path);
  EXPECT_EQ(data.root_path, "../../../datasets/sceaux_castle/images");
  ASSERT_EQ(data.views.size(), 11u);
  EXPECT_EQ(data.views.at(0).filename, "100_7100.JPG");
  EXPECT_EQ(data.views.at(10).filename, "100_7110.JPG");
  EXPECT_EQ(data.views.at(10).width, 2832u);
  EXPECT_EQ(data.views.at(10).height, 2128u);
  EXPECT_EQ(data.views.at(10).id_pose, 10u);
  ASSERT_EQ(data.intrinsics.size(), 1u);
  const CameraIntrinsics& camera = data.intrinsics.at(0);
  EXPECT_EQ(camera.model(), CameraModel::kPinholeRadialK3);
  EXPECT_NEAR(camera.FocalLength(), 2884.26, 0.01);
  EXPECT_EQ(camera.FocalLength(), 2884.2617914205145);
  EXPECT_EQ(camera.PrincipalPoint(), Eigen::Vector2d(1416.0, 1064.0));
  EXPECT_TRUE(data.poses.empty());
  EXPECT_TRUE(data.structure.empty());
}

TEST(OpenMvgSfmDataRealFiles, GlobalReconstructionLoads) {
  PRUNESFM_REQUIRE_SHARED(kReconstruction, path);
  const SfmData data = ReadSfmData(path);
  EXPECT_EQ(data.views.size(), 11u);
  EXPECT_EQ(data.poses.size(), 11u);
  EXPECT_EQ(data.PosedViewIds().size(), 11u);
  EXPECT_EQ(data.structure.size(), 2770u);
  size_t observations = 0;
  for (const auto& [id, landmark] : data.structure) observations += landmark.observations.size();
  EXPECT_EQ(observations, 13310u);
  EXPECT_EQ(data.intrinsics.at(0).FocalLength(), 2988.944788244099);
  EXPECT_EQ(data.intrinsics.at(0).DistortionParams()[0], -0.24900265824745468);
  EXPECT_EQ(data.poses.at(3).rotation(1, 2), -0.04419850304892551);  // row 1, column 2 of the file
  EXPECT_EQ(data.poses.at(3).center.z(), -0.019639631076499946);
  const Landmark& first = data.structure.begin()->second;
  EXPECT_EQ(data.structure.begin()->first, 0u);
  EXPECT_EQ(first.X.x(), -0.038523418074262315);
  EXPECT_EQ(first.observations.size(), 5u);
  EXPECT_NEAR((data.PoseOf(data.views.at(0)).rotation * data.PoseOf(data.views.at(0)).rotation.transpose() -
               Eigen::Matrix3d::Identity())
                  .norm(),
              0.0, 1e-9);
}

TEST(OpenMvgSfmDataRealFiles, WriterMatchesOpenMvgOutputModuloArrayOrder) {
  PRUNESFM_REQUIRE_SHARED(kImageListing, listing);
  PRUNESFM_REQUIRE_SHARED(kReconstruction, reconstruction);
  ExpectSameAsOpenMvgModuloOrder(listing, "listing");
  ExpectSameAsOpenMvgModuloOrder(reconstruction, "reconstruction");
}

TEST(OpenMvgSfmDataRealFiles, ReconstructionRoundTripsThroughBinary) {
  PRUNESFM_REQUIRE_SHARED(kReconstruction, path);
  const SfmData data = ReadSfmData(path);
  const fs::path bin = testing::ScratchDir("openmvg_sfm_data_real_bin") / "sfm_data.bin";
  WriteSfmData(data, bin);
  EXPECT_TRUE(ReadSfmData(bin) == data);
  // Reading only some parts of the real file.
  const SfmData views_and_intrinsics = ReadSfmData(path, SfmDataParts::kViews | SfmDataParts::kIntrinsics);
  EXPECT_EQ(views_and_intrinsics.views.size(), 11u);
  EXPECT_TRUE(views_and_intrinsics.poses.empty());
  EXPECT_TRUE(views_and_intrinsics.structure.empty());
}

}  // namespace
}  // namespace sfm_pruning
