// prunesfm prune: the one-line errors and a database of matches only (fast; the end-to-end runs on
// a twin scene are in prune_end_to_end_test.cpp).
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include <nlohmann/json.hpp>

#include "run_prunesfm.hpp"
#include "sfm_pruning/io/colmap_database.hpp"
#include "support/test_data.hpp"

namespace sfm_pruning::testing {
namespace {
namespace fs = std::filesystem;

// An 8-view clean scene: its database holds putative matches only, no two-view geometries.
const fs::path& SmallProject() {
  static const fs::path dir = []() {
    const std::string test_name = ::testing::UnitTest::GetInstance()->current_test_info()->name();
    const fs::path out = ScratchDir("cli_prune_scene_" + test_name) / "clean";
    const CommandResult result =
        RunPrunesfm({"synth", "--scene", "clean", "--seed", "2", "--num_views", "8", "--output", out.string()});
    EXPECT_EQ(result.exit_code, 0) << result.err;
    return out;
  }();
  return dir;
}

void ExpectOneLineError(const CommandResult& result, const std::string& expected) {
  EXPECT_EQ(result.exit_code, 1);
  EXPECT_EQ(CountLines(result.err), 1) << result.err;
  EXPECT_NE(result.err.find(expected), std::string::npos) << result.err;
}

TEST(CliPrune, MissingDatabaseIsOneLine) {
  const fs::path scratch = ScratchDir("cli_prune_missing");
  ExpectOneLineError(RunPrunesfm({"prune", "--database", "/nonexistent/database.db", "--output",
                                  (scratch / "pruned.db").string()}),
                     "/nonexistent/database.db");
  EXPECT_FALSE(fs::exists(scratch / "pruned.db"));
}

TEST(CliPrune, DatabaseOfMatchesOnlyGetsItsPairsVerifiedHere) {
  // No other tool verified the matches: prune verifies them as `run` does and writes the kept
  // pairs' two-view geometries (inliers, E, pose), the rest of the database as it was.
  const fs::path scratch = ScratchDir("cli_prune_unverified");
  const fs::path database = SmallProject() / "database.db";
  const CommandResult result =
      RunPrunesfm({"prune", "--database", database.string(), "--output", (scratch / "pruned.db").string()});
  ASSERT_EQ(result.exit_code, 0) << result.err;
  const ColmapDatabase before = ReadColmapDatabase(database);
  const ColmapDatabase after = ReadColmapDatabase(scratch / "pruned.db");
  ASSERT_TRUE(before.verified.empty());
  const nlohmann::json report = nlohmann::json::parse(std::ifstream(scratch / "pruned.pruning_report.json"));
  EXPECT_TRUE(report.at("filter").at("verified_here").get<bool>());
  EXPECT_EQ(after.verified.size(), static_cast<size_t>(report.at("edges_out").get<int>()));
  EXPECT_GT(after.verified.size(), before.putative.size() / 2);  // a clean scene: most pairs stay
  for (const auto& [pair, geometry] : after.verified) {
    ASSERT_EQ(before.putative.count(pair), 1u);
    EXPECT_GE(geometry.inliers.size(), 30u);  // the verification's minimum
    EXPECT_LE(geometry.inliers.size(), before.putative.at(pair).size());
    EXPECT_EQ(geometry.config, static_cast<int>(ColmapTwoViewConfig::kCalibrated));
    EXPECT_TRUE(geometry.relative_pose.has_value());
  }
  EXPECT_EQ(after.putative.size(), before.putative.size());
  EXPECT_EQ(after.sfm_data.views.size(), before.sfm_data.views.size());
}

TEST(CliPrune, PaperPresetIsEveryAdditionOffAndFlagsStillApply) {
  const fs::path scratch = ScratchDir("cli_prune_preset");
  const std::string database = (SmallProject() / "database.db").string();
  const auto prune = [&](const std::string& name, std::vector<std::string> extra) {
    std::vector<std::string> args = {"prune", "--database", database, "--output", (scratch / (name + ".db")).string()};
    args.insert(args.end(), extra.begin(), extra.end());
    const CommandResult result = RunPrunesfm(args);
    EXPECT_EQ(result.exit_code, 0) << result.err;
    return nlohmann::json::parse(std::ifstream(scratch / (name + ".pruning_report.json")));
  };
  const nlohmann::json preset = prune("preset", {"--prune_preset", "paper"});
  const nlohmann::json flags = prune(
      "flags", {"--prune_edge_weight", "inliers", "--prune_bisect_unsplittable", "false",
                "--prune_max_baseline_ratio_factor", "0", "--prune_max_sample_size", "0",
                "--prune_max_enumerated_samples", "0", "--prune_hypothesis_selection", "largest_consensus",
                "--prune_rotation_only_fallback", "false", "--prune_subgraph_loops_enabled", "false",
                "--prune_trust_prior_edges", "0", "--prune_landmark_check_max_angle_deg", "0",
                "--prune_audit_enabled", "false", "--prune_capture_order_use", "unordered"});
  // The same pruning (the tree differs only in its timings).
  EXPECT_EQ(preset.at("removed_edges"), flags.at("removed_edges"));
  EXPECT_EQ(preset.at("tree").size(), flags.at("tree").size());
  EXPECT_FALSE(preset.at("capture_order").at("used").get<bool>());
  const auto bytes = [](const fs::path& path) {
    std::ifstream in(path, std::ios::binary);
    return std::string(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
  };
  EXPECT_EQ(bytes(scratch / "preset.db"), bytes(scratch / "flags.db"));
  const auto stages = [](const nlohmann::json& report) {
    std::vector<std::string> names;
    for (const nlohmann::json& phase : report.at("phases")) names.push_back(phase.at("stage").get<std::string>());
    return names;
  };
  EXPECT_EQ(stages(preset), (std::vector<std::string>{"subgraph partition", "inter-subgraph pruning"}));
  // A flag given with the preset wins, before or after it on the command line.
  const nlohmann::json audited = prune("audited", {"--prune_audit_enabled", "true", "--prune_preset", "paper"});
  EXPECT_EQ(stages(audited).back(), "model audit");
  const CommandResult unknown = RunPrunesfm(
      {"prune", "--database", database, "--output", (scratch / "x.db").string(), "--prune_preset", "mine"});
  EXPECT_EQ(unknown.exit_code, 105);  // CLI11's validation error
  EXPECT_EQ(CountLines(unknown.err), 1) << unknown.err;
  EXPECT_NE(unknown.err.find("--prune_preset"), std::string::npos) << unknown.err;
}

TEST(CliPrune, InputMustBeExactlyOneOfDatabaseAndOpenMvg) {
  const fs::path scratch = ScratchDir("cli_prune_inputs");
  const std::string out = (scratch / "out.db").string();
  ExpectOneLineError(RunPrunesfm({"prune", "--output", out}), "give either --database");
  ExpectOneLineError(RunPrunesfm({"prune", "--database", (SmallProject() / "database.db").string(), "--sfm_data",
                                  (SmallProject() / "sfm_data.json").string(), "--output", out}),
                     "give either --database");
  ExpectOneLineError(RunPrunesfm({"prune", "--sfm_data", (SmallProject() / "sfm_data.json").string(), "--output",
                                  out}),
                     "--sfm_data needs --matches_dir");
}

TEST(CliPrune, ReportMustNotOverwriteTheOutput) {
  const fs::path scratch = ScratchDir("cli_prune_report_clash");
  const std::string out = (scratch / "pruned.txt").string();
  ExpectOneLineError(RunPrunesfm({"prune", "--sfm_data", (SmallProject() / "sfm_data.json").string(),
                                  "--matches_dir", (SmallProject() / "matches").string(), "--output", out,
                                  "--report", out}),
                     "--report must differ from --output");
}

}  // namespace
}  // namespace sfm_pruning::testing
