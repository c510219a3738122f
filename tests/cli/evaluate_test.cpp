// prunesfm evaluate end to end: report, JSON output and one-line errors.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include <nlohmann/json.hpp>

#include "run_prunesfm.hpp"
#include "support/test_data.hpp"

namespace sfm_pruning::testing {
namespace {
namespace fs = std::filesystem;

constexpr const char* kTempleTruth = "datasets/middlebury/templeSparseRing/gt_cameras.txt";

TEST(CliEvaluate, ColmapModelAgainstGroundTruthWithJson) {
  PRUNESFM_REQUIRE_SHARED(kTempleTruth, truth);
  PRUNESFM_REQUIRE_SHARED("formats/colmap/colmap-3.8/sparse_bin", model);
  const fs::path json_path = ScratchDir("cli_evaluate_json") / "report.json";
  const CommandResult result = RunPrunesfm({"evaluate", "--estimate", model.string(), "--ground_truth",
                                            truth.string(), "--thresholds", "3,5,10,20", "--json", json_path.string()});
  ASSERT_EQ(result.exit_code, 0) << result.err;
  EXPECT_NE(result.out.find("registered:    13 / 16"), std::string::npos) << result.out;
  EXPECT_NE(result.out.find("AUC@3 deg:  49.53"), std::string::npos) << result.out;
  EXPECT_NE(result.out.find("AUC@20 deg:"), std::string::npos) << result.out;

  const nlohmann::json json = nlohmann::json::parse(std::ifstream(json_path));
  EXPECT_EQ(json.at("num_registered_images"), 13);
  EXPECT_EQ(json.at("num_failed_pairs"), 42);
  ASSERT_EQ(json.at("auc").size(), 4u);
  EXPECT_EQ(json.at("auc")[1].at("threshold_deg"), 5.0);
  EXPECT_NEAR(json.at("auc")[1].at("auc_percent").get<double>(), 55.4, 0.1);
  EXPECT_EQ(json.at("alignment").at("num_inliers"), 13);
}

TEST(CliEvaluate, MissingEstimateGivesOneLineAndNoJson) {
  PRUNESFM_REQUIRE_SHARED(kTempleTruth, truth);
  const fs::path json_path = ScratchDir("cli_evaluate_missing") / "report.json";
  const CommandResult result = RunPrunesfm({"evaluate", "-e", "/nonexistent/sparse", "-g", truth.string(), "--json",
                                            json_path.string()});
  EXPECT_EQ(result.exit_code, 1);
  EXPECT_EQ(CountLines(result.err), 1) << result.err;
  EXPECT_NE(result.err.find("/nonexistent/sparse"), std::string::npos) << result.err;
  EXPECT_FALSE(fs::exists(json_path));
}

TEST(CliEvaluate, NoCommonImagesSaysHowManyEachSideHad) {
  PRUNESFM_REQUIRE_SHARED(kTempleTruth, truth);
  PRUNESFM_REQUIRE_SHARED("datasets/strecha/fountain-P11/gt_cameras.txt", fountain);
  const CommandResult result = RunPrunesfm({"evaluate", "-e", fountain.string(), "-g", truth.string()});
  EXPECT_EQ(result.exit_code, 1);
  EXPECT_EQ(CountLines(result.err), 1) << result.err;
  EXPECT_NE(result.err.find("estimate: 11"), std::string::npos) << result.err;
  EXPECT_NE(result.err.find("ground truth: 16"), std::string::npos) << result.err;
}

TEST(CliEvaluate, RejectsNonPositiveThreshold) {
  PRUNESFM_REQUIRE_SHARED(kTempleTruth, truth);
  const CommandResult result =
      RunPrunesfm({"evaluate", "-e", truth.string(), "-g", truth.string(), "--thresholds", "5,0"});
  EXPECT_EQ(result.exit_code, 1);
  EXPECT_EQ(CountLines(result.err), 1) << result.err;
}

}  // namespace
}  // namespace sfm_pruning::testing
