// prunesfm reconstruct / run end to end on a small synthetic project: outputs, accuracy through
// prunesfm evaluate, and the one-line errors.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "run_prunesfm.hpp"
#include "sfm_pruning/io/colmap_database.hpp"
#include "sfm_pruning/io/openmvg_matches.hpp"
#include "support/test_data.hpp"

namespace sfm_pruning::testing {
namespace {
namespace fs = std::filesystem;

// A 12-view clean scene written once per process. ctest runs every test in its own process, in
// parallel, so the folder is named after the first test that asks for it: two processes never
// write the same folder.
const fs::path& CleanProject() {
  static const fs::path dir = []() {
    const std::string test_name = ::testing::UnitTest::GetInstance()->current_test_info()->name();
    const fs::path out = ScratchDir("cli_reconstruct_scene_" + test_name) / "clean";
    const CommandResult result =
        RunPrunesfm({"synth", "--scene", "clean", "--seed", "4", "--num_views", "12", "--output", out.string()});
    EXPECT_EQ(result.exit_code, 0) << result.err;
    return out;
  }();
  return dir;
}

double Auc3(const fs::path& estimate, const fs::path& scratch) {
  const fs::path json_path = scratch / "evaluation.json";
  const CommandResult result = RunPrunesfm({"evaluate", "--estimate", estimate.string(), "--ground_truth",
                                            (CleanProject() / "ground_truth" / "gt_cameras.txt").string(), "--json",
                                            json_path.string()});
  EXPECT_EQ(result.exit_code, 0) << result.err;
  const nlohmann::json json = nlohmann::json::parse(std::ifstream(json_path));
  EXPECT_EQ(json.at("num_registered_images"), 12);
  return json.at("auc")[0].at("auc_percent").get<double>();
}

TEST(CliReconstruct, OpenMvgProjectIsReconstructedAccurately) {
  const fs::path scratch = ScratchDir("cli_reconstruct_openmvg");
  const fs::path out = scratch / "out";
  const CommandResult result =
      RunPrunesfm({"reconstruct", "--engine", "GLOBAL", "--sfm_data", (CleanProject() / "sfm_data.json").string(),
                   "--matches_dir", (CleanProject() / "matches").string(), "--output", out.string()});
  ASSERT_EQ(result.exit_code, 0) << result.err;
  for (const char* file : {"sfm_data.json", "sparse/0/cameras.bin", "sparse/0/images.bin", "sparse/0/points3D.bin",
                           "cloud_and_poses.ply", "timings.json"}) {
    EXPECT_TRUE(fs::exists(out / file)) << file;
  }
  const nlohmann::json timings = nlohmann::json::parse(std::ifstream(out / "timings.json"));
  EXPECT_EQ(timings.at("counts").at("registered_views"), 12);
  EXPECT_GE(timings.at("stages").size(), 6u);
  EXPECT_GE(Auc3(out / "sparse" / "0", scratch), 97.0);
  EXPECT_GE(Auc3(out / "sfm_data.json", scratch), 97.0);
}

TEST(CliReconstruct, RunFromColmapDatabase) {
  const fs::path scratch = ScratchDir("cli_reconstruct_run");
  const fs::path out = scratch / "out";
  const CommandResult result =
      RunPrunesfm({"run", "--database", (CleanProject() / "database.db").string(), "--image_path",
                   (scratch / "images").string(), "--output_path", out.string(), "--engine", "GLOBAL"});
  ASSERT_EQ(result.exit_code, 0) << result.err;
  EXPECT_GE(Auc3(out / "sparse" / "0", scratch), 97.0);
  // The generated scene has no lens distortion: the evidence test holds it (docs/global.md).
  const nlohmann::json timings = nlohmann::json::parse(std::ifstream(out / "timings.json"));
  ASSERT_TRUE(timings.contains("distortion_evidence")) << timings.dump();
  EXPECT_FALSE(timings.at("distortion_evidence").at("kept").get<bool>());
  EXPECT_LT(timings.at("distortion_evidence").at("statistic").get<double>(),
            timings.at("distortion_evidence").at("threshold").get<double>());
  EXPECT_NE(result.err.find("lens distortion held"), std::string::npos) << result.err;
}

std::string FileText(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

// --num_threads (default: every core) drives only the stages whose result does not depend on it,
// and Ceres runs on --solver_threads (default 1): the model is bitwise the same for any count.
TEST(CliReconstruct, ModelDoesNotDependOnTheThreadCount) {
  const fs::path scratch = ScratchDir("cli_reconstruct_threads");
  std::vector<std::string> models;
  for (const char* threads : {"1", "3", ""}) {
    const fs::path out = scratch / (std::string("threads_") + (*threads ? threads : "default"));
    std::vector<std::string> args = {"reconstruct", "--database", (CleanProject() / "database.db").string(),
                                     "--output_path", out.string(), "--engine", "GLOBAL_PRUNED"};
    if (*threads) args.insert(args.end(), {"--num_threads", threads});
    const CommandResult result = RunPrunesfm(args);
    ASSERT_EQ(result.exit_code, 0) << result.err;
    models.push_back(FileText(out / "sfm_data.json") + FileText(out / "sparse" / "0" / "images.bin") +
                     FileText(out / "sparse" / "0" / "points3D.bin"));
  }
  EXPECT_GT(models[0].size(), 1000u);
  EXPECT_EQ(models[1], models[0]) << "--num_threads 3";
  EXPECT_EQ(models[2], models[0]) << "default threads";
}

TEST(CliReconstruct, DatabaseGeometriesWithoutPosesAreReestimated) {
  const fs::path scratch = ScratchDir("cli_reconstruct_verified");
  ColmapDatabase database = ReadColmapDatabase(CleanProject() / "database.db");
  for (const auto& [pair, matches] : database.putative) {  // as COLMAP 3.8 stores them: no pose
    database.verified[pair].inliers = matches;
    database.verified[pair].config = static_cast<int>(ColmapTwoViewConfig::kCalibrated);
  }
  WriteColmapDatabase(database, scratch / "verified.db");
  const fs::path out = scratch / "out";
  const CommandResult result = RunPrunesfm(
      {"reconstruct", "--database", (scratch / "verified.db").string(), "--output", out.string()});
  ASSERT_EQ(result.exit_code, 0) << result.err;
  EXPECT_GE(Auc3(out / "sparse" / "0", scratch), 97.0);
}

size_t VerifiedInliers(const fs::path& view_graph_json) {
  std::ifstream in(view_graph_json);
  const nlohmann::json graph = nlohmann::json::parse(in);
  size_t inliers = 0;
  for (const nlohmann::json& edge : graph.at("edges")) inliers += edge.at("inliers").get<size_t>();
  return inliers;
}

TEST(CliReconstruct, EpipolarThresholdReachesTheVerification) {
  // The synthetic features carry 1 px of noise at a 1229 px focal (about 0.05 deg): 0.1 deg keeps
  // most of the inliers 0.25 deg keeps, not all, and the model stays as accurate.
  const fs::path scratch = ScratchDir("cli_reconstruct_epipolar");
  size_t inliers[2] = {0, 0};
  const char* thresholds[2] = {"0.25", "0.1"};
  for (int k = 0; k < 2; ++k) {
    const fs::path out = scratch / thresholds[k];
    const CommandResult result = RunPrunesfm({"run", "--database", (CleanProject() / "database.db").string(),
                                              "--image_path", (scratch / "images").string(), "--output_path",
                                              out.string(), "--max_epipolar_error_deg", thresholds[k]});
    ASSERT_EQ(result.exit_code, 0) << result.err;
    inliers[k] = VerifiedInliers(out / "view_graph.json");
    EXPECT_GE(Auc3(out / "sparse" / "0", scratch), 97.0) << thresholds[k];
  }
  EXPECT_LT(inliers[1], inliers[0]);
  EXPECT_GT(inliers[1], inliers[0] * 7 / 10);
  const CommandResult zero = RunPrunesfm({"run", "--database", (CleanProject() / "database.db").string(),
                                          "--image_path", (scratch / "images").string(), "--output_path",
                                          (scratch / "zero").string(), "--max_epipolar_error_deg", "0"});
  EXPECT_NE(zero.exit_code, 0);
}

TEST(CliReconstruct, ModelAuditAndLandmarkCheckLeaveACleanSceneAlone) {
  // Every edge of a clean scene is true: the audit measures the edges between the subgraphs, finds
  // that the first model transfers nearly all their matches, and changes nothing; the subgraphs'
  // landmarks contradict almost no match.
  const fs::path scratch = ScratchDir("cli_reconstruct_audit");
  const fs::path out = scratch / "out";
  const CommandResult result = RunPrunesfm(
      {"run", "--database", (CleanProject() / "database.db").string(), "--image_path", (scratch / "images").string(),
       "--output_path", out.string(), "--engine", "GLOBAL_PRUNED",
       "--prune_audit_enabled", "true", "--prune_landmark_check_max_angle_deg", "5"});
  ASSERT_EQ(result.exit_code, 0) << result.err;
  EXPECT_GE(Auc3(out / "sparse" / "0", scratch), 97.0);
  const nlohmann::json timings = nlohmann::json::parse(std::ifstream(out / "timings.json"));
  EXPECT_TRUE(timings.at("prune_audit_enabled").get<bool>());
  EXPECT_EQ(timings.at("prune_landmark_check_max_angle_deg").get<double>(), 5.0);
  const nlohmann::json report = nlohmann::json::parse(std::ifstream(out / "pruning_report.json"));
  const nlohmann::json& check = report.at("landmark_check");
  EXPECT_GT(check.at("edges").get<int>(), 0);
  EXPECT_GT(check.at("tested").get<double>(), 0.5 * check.at("matches").get<double>());
  EXPECT_LT(check.at("dropped").get<double>(), 0.02 * check.at("matches").get<double>()) << check.dump();
  EXPECT_EQ(check.at("edges_removed").get<int>(), 0);
  const nlohmann::json& audit = report.at("model_audit");
  EXPECT_EQ(audit.at("readmitted").get<int>(), 0);
  EXPECT_EQ(audit.at("removed").get<int>(), 0);
  ASSERT_FALSE(audit.at("edges").empty());
  for (const nlohmann::json& edge : audit.at("edges")) {
    EXPECT_GE(edge.at("agreeing").get<double>(), 0.9 * edge.at("transferred").get<double>()) << edge.dump();
  }
}

TEST(CliReconstruct, PruningRansacTriesEverySampleOfASmallPairOnce) {
  // By default a pair whose pool has at most 1000 distinct samples of 2 edges tries each once (the
  // first candidate's pool is every voting edge); with 0 every pair draws the paper's 30 rounds.
  const fs::path scratch = ScratchDir("cli_reconstruct_enumerate");
  for (const char* bound : {"1000", "0"}) {
    const fs::path out = scratch / bound;
    std::vector<std::string> args = {"run", "--database", (CleanProject() / "database.db").string(), "--image_path",
                                     (scratch / "images").string(), "--output_path", out.string(), "--engine",
                                     "GLOBAL_PRUNED"};
    if (std::string(bound) == "0") args.insert(args.end(), {"--prune_max_enumerated_samples", "0"});
    const CommandResult result = RunPrunesfm(args);
    ASSERT_EQ(result.exit_code, 0) << result.err;
    EXPECT_GE(Auc3(out / "sparse" / "0", scratch), 97.0) << bound;
    const nlohmann::json timings = nlohmann::json::parse(std::ifstream(out / "timings.json"));
    EXPECT_EQ(timings.at("prune_max_enumerated_samples").get<size_t>(), std::stoul(bound));
    const nlohmann::json report = nlohmann::json::parse(std::ifstream(out / "pruning_report.json"));
    int judged = 0;
    for (const nlohmann::json& pair : report.at("subgraph_pairs")) {
      if (pair.at("hypotheses").empty()) continue;
      const nlohmann::json& first = pair.at("hypotheses").at(0);
      const int voting = pair.at("voting_edges").get<int>();
      ++judged;
      if (std::string(bound) == "0") {
        EXPECT_FALSE(first.at("enumerated").get<bool>()) << pair.dump();
        EXPECT_EQ(first.at("samples").get<int>(), 30) << pair.dump();
      } else if (voting <= 45) {
        EXPECT_TRUE(first.at("enumerated").get<bool>()) << pair.dump();
        EXPECT_EQ(first.at("samples").get<int>(), voting * (voting - 1) / 2) << pair.dump();
      }
    }
    EXPECT_GT(judged, 0) << bound;
  }
}

TEST(CliReconstruct, MatchVerifiesWithTheGivenEpipolarThreshold) {
  // `prunesfm match` on the project's features: a tighter threshold keeps fewer verified inliers.
  const fs::path scratch = ScratchDir("cli_match_epipolar");
  size_t inliers[2] = {0, 0};
  const char* thresholds[2] = {"0.25", "0.1"};
  for (int k = 0; k < 2; ++k) {
    const fs::path matches_dir = scratch / thresholds[k];
    fs::create_directories(matches_dir);
    for (const fs::directory_entry& entry : fs::directory_iterator(CleanProject() / "matches")) {
      const std::string extension = entry.path().extension().string();
      if (extension == ".feat" || extension == ".desc" || extension == ".json") {
        fs::copy_file(entry.path(), matches_dir / entry.path().filename());
      }
    }
    const CommandResult result =
        RunPrunesfm({"match", "--sfm_data", (CleanProject() / "sfm_data.json").string(), "--matches_dir",
                     matches_dir.string(), "--num_threads", "1", "--max_epipolar_error_deg", thresholds[k]});
    ASSERT_EQ(result.exit_code, 0) << result.err;
    for (const auto& [pair, matches] : ReadOpenMvgMatches(matches_dir / "matches.e.bin")) inliers[k] += matches.size();
  }
  EXPECT_GT(inliers[1], 0u);
  EXPECT_LT(inliers[1], inliers[0]);
}

TEST(CliReconstruct, MissingDatabaseIsOneLine) {
  const CommandResult result = RunPrunesfm(
      {"reconstruct", "--database", "/nonexistent/database.db", "--output", ScratchDir("cli_rec_missing").string()});
  EXPECT_EQ(result.exit_code, 1);
  EXPECT_EQ(CountLines(result.err), 1) << result.err;
  EXPECT_NE(result.err.find("/nonexistent/database.db"), std::string::npos) << result.err;
}

TEST(CliReconstruct, ImagePathGoesWithADatabase) {
  const fs::path out = ScratchDir("cli_rec_image_path") / "out";
  const CommandResult result =
      RunPrunesfm({"reconstruct", "--sfm_data", (CleanProject() / "sfm_data.json").string(), "--matches_dir",
                   (CleanProject() / "matches").string(), "--image_path", "images", "--output_path", out.string()});
  EXPECT_EQ(result.exit_code, 1);
  EXPECT_EQ(CountLines(result.err), 1) << result.err;
  EXPECT_NE(result.err.find("--image_path goes with --database"), std::string::npos) << result.err;
  EXPECT_FALSE(fs::exists(out));
}

TEST(CliReconstruct, DatabaseWithoutGeometriesOrMatchesHasNoEdges) {
  const fs::path scratch = ScratchDir("cli_reconstruct_empty");
  ColmapDatabase database = ReadColmapDatabase(CleanProject() / "database.db");
  database.putative.clear();
  database.verified.clear();
  WriteColmapDatabase(database, scratch / "empty.db");
  const CommandResult result = RunPrunesfm(
      {"reconstruct", "--database", (scratch / "empty.db").string(), "--output", (scratch / "out").string()});
  EXPECT_EQ(result.exit_code, 1);
  EXPECT_EQ(CountLines(result.err), 1) << result.err;
  EXPECT_NE(result.err.find("no two images match"), std::string::npos) << result.err;
  EXPECT_FALSE(fs::exists(scratch / "out" / "sfm_data.json"));
}

TEST(CliReconstruct, DisconnectedGraphUsesTheLargestComponentAndReportsDroppedViews) {
  const fs::path scratch = ScratchDir("cli_reconstruct_cut");
  const PairwiseMatches all = ReadOpenMvgMatches(CleanProject() / "matches" / "matches.putative.bin");
  PairwiseMatches cut;  // views 0 and 1 only match each other
  for (const auto& [pair, matches] : all) {
    if ((pair.first < 2) == (pair.second < 2)) cut.emplace(pair, matches);
  }
  WriteOpenMvgMatches(scratch / "matches.cut.bin", cut);
  const fs::path out = scratch / "out";
  const CommandResult result = RunPrunesfm(
      {"reconstruct", "--sfm_data", (CleanProject() / "sfm_data.json").string(), "--matches_dir",
       (CleanProject() / "matches").string(), "--match_file", (scratch / "matches.cut.bin").string(), "--output",
       out.string()});
  ASSERT_EQ(result.exit_code, 0) << result.err;
  EXPECT_NE(result.err.find("dropped view 0"), std::string::npos) << result.err;
  EXPECT_NE(result.err.find("outside the largest component"), std::string::npos) << result.err;
  const nlohmann::json timings = nlohmann::json::parse(std::ifstream(out / "timings.json"));
  EXPECT_EQ(timings.at("counts").at("registered_views"), 10);
  EXPECT_EQ(timings.at("dropped_views").size(), 2u);
}

TEST(CliReconstruct, PrunedEngineReconstructsAndWritesThePruningReport) {
  const fs::path scratch = ScratchDir("cli_rec_pruned");
  const fs::path out = scratch / "out";
  const CommandResult result =
      RunPrunesfm({"run", "--database", (CleanProject() / "database.db").string(), "--image_path",
                   (scratch / "images").string(), "--output_path", out.string(), "--engine", "GLOBAL_PRUNED"});
  ASSERT_EQ(result.exit_code, 0) << result.err;
  EXPECT_NE(result.err.find("pruning: "), std::string::npos) << result.err;
  const nlohmann::json report = nlohmann::json::parse(std::ifstream(out / "pruning_report.json"));
  EXPECT_GE(report.at("tree").size(), 1u);
  // The pruning's phases (the scene is a sequential capture; the model audit is off by default), then
  // the missing-correspondence check: on a clean scene one round that removes nothing.
  std::vector<std::string> phases;
  for (const nlohmann::json& phase : report.at("phases")) phases.push_back(phase.at("stage").get<std::string>());
  EXPECT_EQ(phases, (std::vector<std::string>{"capture path", "subgraph partition", "inter-subgraph pruning",
                                              "landmark check of matches", "solve for the missing-correspondence check",
                                              "missing-correspondence check"}));
  EXPECT_TRUE(report.at("removed_edges").is_array());
  ASSERT_EQ(report.at("missing_correspondences").size(), 1u);
  EXPECT_TRUE(report.at("missing_correspondences")[0].at("removed").empty());
  const nlohmann::json timings = nlohmann::json::parse(std::ifstream(out / "timings.json"));
  EXPECT_EQ(timings.at("engine"), "GLOBAL_PRUNED");
  EXPECT_GE(Auc3(out / "sparse" / "0", scratch), 97.0);
}

}  // namespace
}  // namespace sfm_pruning::testing
