// prunesfm synth: the written project reads back as the scene the library generates.
#include <gtest/gtest.h>

#include <fstream>
#include <map>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

#include "run_prunesfm.hpp"
#include "sfm_pruning/eval/synthetic_scene.hpp"
#include "sfm_pruning/io/colmap_database.hpp"
#include "sfm_pruning/io/openmvg_features.hpp"
#include "sfm_pruning/io/openmvg_matches.hpp"
#include "sfm_pruning/io/openmvg_sfm_data.hpp"
#include "sfm_pruning/util/atomic_file.hpp"
#include "support/test_data.hpp"

namespace sfm_pruning::testing {
namespace {

SyntheticSceneOptions CliOptions() {
  SyntheticSceneOptions options;
  options.scene = "street";
  options.seed = 5;
  options.num_views = 6;
  options.point_density_scale = 0.3;
  return options;
}

CommandResult RunSynth(const std::filesystem::path& out) {
  return RunPrunesfm({"synth", "--scene", "street", "--seed", "5", "--num_views", "6", "--point_density_scale", "0.3",
                      "--output", out.string()});
}

TEST(CliSynth, WritesAProjectThatReadsBackAsTheScene) {
  const std::filesystem::path dir = ScratchDir("cli_synth") / "scene";
  const CommandResult result = RunSynth(dir);
  ASSERT_EQ(result.exit_code, 0) << result.err;
  const SyntheticScene scene = GenerateSyntheticScene(CliOptions());

  const SfmData listing = ReadSfmData(dir / "sfm_data.json");
  EXPECT_EQ(listing.views, scene.ground_truth.views);
  EXPECT_TRUE(listing.poses.empty());
  const SfmData truth = ReadSfmData(dir / "ground_truth" / "sfm_data.json");
  EXPECT_EQ(truth.views.size(), scene.ground_truth.views.size());
  EXPECT_EQ(truth.structure.size(), scene.ground_truth.structure.size());
  EXPECT_TRUE(std::filesystem::exists(dir / "ground_truth" / "gt_cameras.txt"));
  EXPECT_TRUE(std::filesystem::exists(dir / "ground_truth" / "synthetic_scene.json"));

  const FeaturesPerView features = ReadOpenMvgFeatures(listing, dir / "matches", /*with_descriptors=*/true);
  ASSERT_EQ(features.size(), scene.features.size());
  for (const auto& [view, set] : scene.features) EXPECT_EQ(features.at(view).descriptors, set.descriptors);
  EXPECT_EQ(ReadOpenMvgMatches(dir / "matches" / "matches.putative.bin"), scene.putative_matches);

  const ColmapDatabase database = ReadColmapDatabase(dir / "database.db");
  EXPECT_EQ(database.putative, scene.putative_matches);
  ASSERT_EQ(database.features.size(), scene.features.size());
  for (const auto& [view, set] : scene.features) {
    ASSERT_EQ(database.features.at(view).size(), set.size());
    EXPECT_NEAR(database.features.at(view).keypoints[0].x, set.keypoints[0].x, 1e-3);
  }
}

// feature_landmarks.txt: "view_id num_features" then "landmark appearance" per feature (-1 -1: clutter).
std::map<IndexT, std::vector<std::pair<long, long>>> ReadFeatureLandmarks(const std::filesystem::path& path) {
  std::map<IndexT, std::vector<std::pair<long, long>>> result;
  std::istringstream in(ReadFileToString(path));
  std::string line;
  while (std::getline(in, line)) {
    if (line.empty() || line[0] == '#') continue;
    std::istringstream fields(line);
    IndexT view_id = 0;
    size_t count = 0;
    fields >> view_id >> count;
    auto& features = result[view_id];
    features.resize(count);
    for (auto& [landmark, appearance] : features) fields >> landmark >> appearance;
    EXPECT_TRUE(fields) << "view " << view_id;
  }
  return result;
}

TEST(CliSynth, FeatureLandmarksLabelEveryMatchAsTheSceneCountsThem) {
  const std::filesystem::path dir = ScratchDir("cli_synth_labels") / "scene";
  ASSERT_EQ(RunSynth(dir).exit_code, 0);
  const SyntheticScene scene = GenerateSyntheticScene(CliOptions());
  const auto features = ReadFeatureLandmarks(dir / "ground_truth" / "feature_landmarks.txt");
  ASSERT_EQ(features.size(), scene.features.size());
  size_t num_twin = 0;
  for (const auto& [pair, matches] : scene.putative_matches) {
    PairMatchStats counted;
    for (const FeatureMatch& match : matches) {
      const auto [landmark_a, appearance_a] = features.at(pair.first).at(match.i);
      const auto [landmark_b, appearance_b] = features.at(pair.second).at(match.j);
      if (landmark_a >= 0 && landmark_a == landmark_b) {
        ++counted.num_true;
      } else if (landmark_a >= 0 && landmark_b >= 0 && appearance_a == appearance_b) {
        ++counted.num_twin;
      } else {
        ++counted.num_random;
      }
    }
    const PairMatchStats& expected = scene.pair_stats.at(pair);
    EXPECT_EQ(counted.num_true, expected.num_true) << pair.first << "-" << pair.second;
    EXPECT_EQ(counted.num_twin, expected.num_twin) << pair.first << "-" << pair.second;
    EXPECT_EQ(counted.num_random, expected.num_random) << pair.first << "-" << pair.second;
    num_twin += counted.num_twin;
  }
  EXPECT_GT(num_twin, 0u);  // the street has twins: the labels are not all "true"
}

TEST(CliSynth, SameSeedWritesIdenticalFiles) {
  const std::filesystem::path a = ScratchDir("cli_synth_a") / "scene", b = ScratchDir("cli_synth_b") / "scene";
  ASSERT_EQ(RunSynth(a).exit_code, 0);
  ASSERT_EQ(RunSynth(b).exit_code, 0);
  for (const char* file : {"sfm_data.json", "matches/matches.putative.bin", "matches/view_00003.desc",
                           "matches/view_00003.feat", "ground_truth/sfm_data.json", "ground_truth/gt_cameras.txt",
                           "ground_truth/feature_landmarks.txt"}) {
    EXPECT_EQ(ReadFileToString(a / file), ReadFileToString(b / file)) << file;
  }
}

TEST(CliSynth, BadOptionGivesOneLineAndNoOutput) {
  const std::filesystem::path dir = ScratchDir("cli_synth_bad") / "scene";
  const CommandResult result =
      RunPrunesfm({"synth", "--scene", "clean", "--outlier_ratio", "1.5", "--output", dir.string()});
  EXPECT_NE(result.exit_code, 0);
  EXPECT_EQ(CountLines(result.err), 1) << result.err;
  EXPECT_NE(result.err.find("--outlier_ratio: must be in [0, 0.99], got 1.5"), std::string::npos) << result.err;
  EXPECT_FALSE(std::filesystem::exists(dir));
}

TEST(CliSynth, FamilySceneRecordsItsDrawsAndRefusesDrawnOptions) {
  const std::filesystem::path dir = ScratchDir("cli_synth_family");
  const CommandResult written = RunPrunesfm({"synth", "--scene", "family_object", "--seed", "3", "--num_views", "8",
                                             "--point_density_scale", "0.3", "--output", (dir / "object").string()});
  ASSERT_EQ(written.exit_code, 0) << written.err;
  std::ifstream summary(dir / "object" / "ground_truth" / "synthetic_scene.json");
  std::stringstream text;
  text << summary.rdbuf();
  EXPECT_NE(text.str().find("\"family\""), std::string::npos);
  EXPECT_NE(text.str().find("\"unique_share\""), std::string::npos);

  const CommandResult refused = RunPrunesfm({"synth", "--scene", "family_object", "--noise_px", "1", "--output",
                                             (dir / "refused").string()});
  EXPECT_NE(refused.exit_code, 0);
  EXPECT_NE(refused.err.find("--noise_px"), std::string::npos) << refused.err;
  EXPECT_EQ(CountLines(refused.err), 1) << refused.err;
  EXPECT_FALSE(std::filesystem::exists(dir / "refused"));
}

}  // namespace
}  // namespace sfm_pruning::testing
