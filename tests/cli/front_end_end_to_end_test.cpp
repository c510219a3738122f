// prunesfm init / features / match / run IMAGES OUT end to end on rendered images (and a corrupt
// one): outputs, skipped images, resumability, and the one-line errors.
#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>

#include <nlohmann/json.hpp>

#include "features/rendered_scene.hpp"
#include "run_prunesfm.hpp"
#include "sfm_pruning/io/colmap_database.hpp"
#include "sfm_pruning/io/colmap_model.hpp"
#include "sfm_pruning/io/openmvg_features.hpp"
#include "sfm_pruning/io/openmvg_matches.hpp"
#include "sfm_pruning/io/openmvg_sfm_data.hpp"
#include "support/test_data.hpp"

namespace sfm_pruning::testing {
namespace {
namespace fs = std::filesystem;

fs::path RenderedFolder(const std::string& name, int num_views) {
  const fs::path dir = ScratchDir(name) / "images";
  WriteRoomImages(dir, num_views);
  std::ofstream(dir / "zz_corrupt.jpg", std::ios::binary) << "\xff\xd8\xff\xe0 truncated";
  return dir;
}

nlohmann::json ReadJson(const fs::path& path) { return nlohmann::json::parse(std::ifstream(path)); }

std::map<std::string, bool> ReusedStages(const fs::path& out) {
  std::map<std::string, bool> reused;
  const nlohmann::json timings = ReadJson(out / "timings.json");
  for (const auto& stage : timings.at("stages")) {
    if (stage.contains("reused")) reused[stage.at("stage").get<std::string>()] = stage.at("reused").get<bool>();
  }
  return reused;
}

TEST(CliFrontEnd, RunFromImagesReconstructsSkipsCorruptImagesAndResumes) {
  const fs::path images = RenderedFolder("cli_front_end_run", 5);
  const fs::path out = images.parent_path() / "out";
  CommandResult result = RunPrunesfm({"run", images.string(), out.string(), "--focal", "420", "--max_features", "3000"});
  ASSERT_EQ(result.exit_code, 0) << result.err;
  EXPECT_NE(result.err.find("skipped " + (images / "zz_corrupt.jpg").string() + ": does not decode"), std::string::npos)
      << result.err;
  for (const char* file : {"matches/sfm_data.json", "matches/camera_priors.json", "matches/view_0.feat",
                           "matches/view_0.desc", "matches/matches.putative.bin", "matches/matches.e.bin",
                           "sfm_data.json", "sparse/0/images.bin", "cloud_and_poses.ply", "timings.json",
                           "run_manifest.json"}) {
    EXPECT_TRUE(fs::exists(out / file)) << file;
  }
  const nlohmann::json timings = ReadJson(out / "timings.json");
  EXPECT_EQ(timings.at("counts").at("registered_views"), 5);
  EXPECT_EQ(ReusedStages(out), (std::map<std::string, bool>{{"init", false}, {"features", false}, {"match", false}}));
  const nlohmann::json priors = ReadJson(out / "matches" / "camera_priors.json");
  EXPECT_EQ(priors.at("cameras")[0].at("focal_source"), "user_focal");
  EXPECT_EQ(priors.at("skipped_images")[0].at("image"), "zz_corrupt.jpg");
  // The points are coloured from the images and carry their reprojection errors.
  const SfmData model = ReadColmapModel(out / "sparse" / "0");
  ASSERT_GT(model.structure.size(), 100u);
  size_t grey = 0;
  for (const auto& [id, landmark] : model.structure) {
    if (landmark.color == std::array<uint8_t, 3>{128, 128, 128}) ++grey;
    EXPECT_GE(landmark.error, 0.0) << id;
    EXPECT_LT(landmark.error, 4.0) << id;
  }
  EXPECT_LT(grey, model.structure.size() / 10);
  // Every pair of neighbours is verified.
  const PairwiseMatches verified = ReadOpenMvgMatches(out / "matches" / "matches.e.bin");
  for (IndexT k = 0; k + 1 < 5; ++k) EXPECT_EQ(verified.count({k, k + 1}), 1u) << k;

  // Same inputs and options: every stage is reused.
  result = RunPrunesfm({"run", images.string(), out.string(), "--focal", "420", "--max_features", "3000"});
  ASSERT_EQ(result.exit_code, 0) << result.err;
  EXPECT_EQ(ReusedStages(out), (std::map<std::string, bool>{{"init", true}, {"features", true}, {"match", true}}));
  // A feature option changed: features and match rerun, the listing is reused.
  result = RunPrunesfm({"run", images.string(), out.string(), "--focal", "420", "--max_features", "2500"});
  ASSERT_EQ(result.exit_code, 0) << result.err;
  EXPECT_EQ(ReusedStages(out), (std::map<std::string, bool>{{"init", true}, {"features", false}, {"match", false}}));
}

TEST(CliFrontEnd, StagesRunOneByOneWithSequentialPairs) {
  const fs::path images = RenderedFolder("cli_front_end_stages", 4);
  const fs::path matches = images.parent_path() / "matches";
  CommandResult result = RunPrunesfm({"init", "-i", images.string(), "-o", (matches / "sfm_data.json").string()});
  ASSERT_EQ(result.exit_code, 0) << result.err;
  EXPECT_NE(result.err.find("default_guess (a guess)"), std::string::npos) << result.err;
  result = RunPrunesfm({"features", "-s", (matches / "sfm_data.json").string(), "-o", matches.string(),
                        "--max_features", "1500", "--num_threads", "2"});
  ASSERT_EQ(result.exit_code, 0) << result.err;
  result = RunPrunesfm({"match", "-s", (matches / "sfm_data.json").string(), "-m", matches.string(), "--pairs",
                        "sequential", "--window", "1", "--matcher", "BRUTE_FORCE"});
  ASSERT_EQ(result.exit_code, 0) << result.err;
  const PairwiseMatches putative = ReadOpenMvgMatches(matches / "matches.putative.bin");
  EXPECT_EQ(putative.size(), 3u);
  for (const auto& [pair, list] : putative) EXPECT_EQ(pair.second, pair.first + 1);
}

// OUT/database.db holds the run's features and verified matches as COLMAP 3.8 stores them, and
// COLMAP's own mapper reconstructs from it (when /usr/bin/colmap is installed).
TEST(CliFrontEnd, RunWritesADatabaseThatColmapMapsFrom) {
  const fs::path images = RenderedFolder("cli_front_end_database", 5);
  const fs::path out = images.parent_path() / "out";
  const CommandResult result =
      RunPrunesfm({"run", images.string(), out.string(), "--focal", "420", "--max_features", "3000"});
  ASSERT_EQ(result.exit_code, 0) << result.err;
  const ColmapDatabase database = ReadColmapDatabase(out / "database.db");
  EXPECT_EQ(database.sfm_data.views.size(), 5u);
  EXPECT_TRUE(database.intrinsics_with_guessed_focal.empty());  // --focal given: trusted
  const SfmData scene =
      ReadSfmData(out / "matches" / "sfm_data.json", SfmDataParts::kViews | SfmDataParts::kIntrinsics);
  const FeaturesPerView features = ReadOpenMvgFeatures(scene, out / "matches", true);
  for (const auto& [view_id, set] : features) {
    ASSERT_EQ(database.features.count(view_id), 1u) << view_id;
    EXPECT_EQ(database.features.at(view_id).keypoints.size(), set.keypoints.size()) << view_id;
  }
  const PairwiseMatches verified = ReadOpenMvgMatches(out / "matches" / "matches.e.bin");
  ASSERT_EQ(database.verified.size(), verified.size());
  for (const auto& [pair, inliers] : verified) {
    const ColmapTwoViewGeometry& geometry = database.verified.at(pair);
    EXPECT_EQ(geometry.inliers, inliers);
    EXPECT_EQ(geometry.config, static_cast<int>(ColmapTwoViewConfig::kCalibrated));
    EXPECT_TRUE(geometry.relative_pose.has_value());
  }

  const fs::path colmap = "/usr/bin/colmap";
  if (!fs::exists(colmap)) GTEST_SKIP() << "COLMAP not installed at " << colmap << "; its mapper not tried";
  const fs::path sparse = out.parent_path() / "colmap_sparse";
  fs::create_directories(sparse);
  const std::string command = "QT_QPA_PLATFORM=offscreen " + colmap.string() + " mapper --database_path " +
                              (out / "database.db").string() + " --image_path " + images.string() +
                              " --output_path " + sparse.string() + " --Mapper.num_threads 1 > " +
                              (sparse / "mapper.log").string() + " 2>&1";
  ASSERT_EQ(std::system(command.c_str()), 0) << command;
  EXPECT_EQ(ReadColmapModel(sparse / "0").PosedViewIds().size(), 5u);
}

TEST(CliFrontEnd, BadInputIsOneLine) {
  const fs::path scratch = ScratchDir("cli_front_end_errors");
  CommandResult result = RunPrunesfm({"run", (scratch / "missing").string(), (scratch / "out").string()});
  EXPECT_EQ(result.exit_code, 1);
  EXPECT_EQ(CountLines(result.err), 1) << result.err;
  EXPECT_NE(result.err.find("missing: not a folder of images"), std::string::npos) << result.err;
  fs::create_directories(scratch / "junk");
  std::ofstream(scratch / "junk" / "a.png") << "junk";
  result = RunPrunesfm({"init", "-i", (scratch / "junk").string(), "-o", (scratch / "s.json").string()});
  EXPECT_EQ(result.exit_code, 1);
  EXPECT_NE(result.err.find("none of the 1 images decodes"), std::string::npos) << result.err;
  result = RunPrunesfm({"run", (scratch / "junk").string()});
  EXPECT_EQ(result.exit_code, 1);
  EXPECT_NE(result.err.find("needs an OUT_DIR"), std::string::npos) << result.err;
}

}  // namespace
}  // namespace sfm_pruning::testing
