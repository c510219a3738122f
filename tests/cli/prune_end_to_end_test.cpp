// prunesfm prune end to end on a 20-view symmetric orbit (the front and back of the object look
// alike, so about a third of the pairs match twin copies): the pruned COLMAP database lacks
// exactly the pairs the report removes, its kept pairs lose only the matches the landmark check
// dropped, and nothing else changes; the OpenMVG match file likewise; the same seed gives the same
// bytes; the removed pairs are mostly the spurious ones, and they are the pairs GLOBAL_PRUNED
// removes from the same database.
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <map>
#include <set>
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

// The scene, and a copy of its database with every putative pair stored as a two-view geometry
// without pose, as COLMAP 3.8's matcher leaves it (the inliers here still hold the injected
// outliers: prune re-estimates every pose from them).
// `num_views`: 20 for the tests that compare removals with the synthetic truth; 12 for those that
// only read the partition's records (a third of the pairs to verify).
const fs::path& OrbitProject(int num_views = 20) {
  static std::map<int, fs::path> made;  // one scene per size and process
  const auto known = made.find(num_views);
  if (known != made.end()) return known->second;
  const std::string test_name = ::testing::UnitTest::GetInstance()->current_test_info()->name();
  const fs::path out = ScratchDir("cli_prune_orbit" + std::to_string(num_views) + "_" + test_name) / "orbit";
  const CommandResult result =
      RunPrunesfm({"synth", "--scene", "orbit_symmetric", "--seed", "3", "--num_views", std::to_string(num_views),
                   "--output", out.string()});
  EXPECT_EQ(result.exit_code, 0) << result.err;
  ColmapDatabase database = ReadColmapDatabase(out / "database.db");
  for (const auto& [pair, matches] : database.putative) {
    database.verified[pair].inliers = matches;
    database.verified[pair].config = static_cast<int>(ColmapTwoViewConfig::kCalibrated);
  }
  WriteColmapDatabase(database, out / "verified.db");
  return made.emplace(num_views, out).first->second;
}

std::set<ViewPair> RemovedPairs(const fs::path& report_path) {
  const nlohmann::json report = nlohmann::json::parse(std::ifstream(report_path));
  std::set<ViewPair> removed;
  for (const nlohmann::json& edge : report.at("removed_edges")) {
    const IndexT a = edge.at("pair")[0].get<IndexT>();
    const IndexT b = edge.at("pair")[1].get<IndexT>();
    removed.insert({std::min(a, b), std::max(a, b)});
  }
  EXPECT_EQ(report.at("filter").at("removed_pairs").get<size_t>(), removed.size());
  return removed;
}

// Pairs whose matches are mostly between twin copies (the synthetic truth).
std::set<ViewPair> SpuriousPairs() {
  const nlohmann::json scene =
      nlohmann::json::parse(std::ifstream(OrbitProject() / "ground_truth" / "synthetic_scene.json"));
  std::set<ViewPair> spurious;
  for (const nlohmann::json& pair : scene.at("pairs")) {
    if (pair.at("twin").get<int>() > pair.at("true").get<int>()) {
      const IndexT a = pair.at("i").get<IndexT>();
      const IndexT b = pair.at("j").get<IndexT>();
      spurious.insert({std::min(a, b), std::max(a, b)});
    }
  }
  return spurious;
}

std::string FileBytes(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  return std::string(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
}

TEST(CliPruneEndToEnd, DatabaseLosesExactlyWhatGlobalPrunedRemovesAndRunsAreReproducible) {
  const fs::path scratch = ScratchDir("cli_prune_database");
  const fs::path input = OrbitProject() / "verified.db";
  for (const char* name : {"a.db", "b.db"}) {
    const CommandResult result = RunPrunesfm({"prune", "--database", input.string(), "--output",
                                              (scratch / name).string(), "--seed", "5"});
    ASSERT_EQ(result.exit_code, 0) << result.err;
    EXPECT_NE(result.err.find("pruning: "), std::string::npos) << result.err;
  }
  const std::set<ViewPair> removed = RemovedPairs(scratch / "a.pruning_report.json");
  EXPECT_EQ(removed, RemovedPairs(scratch / "b.pruning_report.json"));
  EXPECT_EQ(FileBytes(scratch / "a.db"), FileBytes(scratch / "b.db"));

  const ColmapDatabase before = ReadColmapDatabase(input);
  const ColmapDatabase after = ReadColmapDatabase(scratch / "a.db");
  ASSERT_FALSE(removed.empty());
  EXPECT_EQ(after.verified.size(), before.verified.size() - removed.size());
  size_t dropped = 0;
  for (const auto& [pair, geometry] : before.verified) {
    const auto it = after.verified.find(pair);
    if (removed.count(pair) != 0) {
      EXPECT_EQ(it, after.verified.end()) << pair.first << "-" << pair.second;
    } else {
      ASSERT_NE(it, after.verified.end()) << pair.first << "-" << pair.second;
      // A kept pair keeps its inliers but those the landmark check dropped, in their order.
      ASSERT_LE(it->second.inliers.size(), geometry.inliers.size());
      dropped += geometry.inliers.size() - it->second.inliers.size();
      auto next = geometry.inliers.begin();
      for (const FeatureMatch& match : it->second.inliers) {
        next = std::find_if(next, geometry.inliers.end(),
                            [&](const FeatureMatch& m) { return m.i == match.i && m.j == match.j; });
        ASSERT_NE(next, geometry.inliers.end()) << pair.first << "-" << pair.second;
      }
    }
  }
  const nlohmann::json report = nlohmann::json::parse(std::ifstream(scratch / "a.pruning_report.json"));
  EXPECT_EQ(report.at("filter").at("matches_dropped").get<size_t>(), dropped);
  EXPECT_GT(dropped, 0u);  // twin matches inside true pairs
  // The matches, features and images are copied as they are.
  EXPECT_EQ(after.putative.size(), before.putative.size());
  EXPECT_EQ(after.sfm_data.views.size(), before.sfm_data.views.size());
  EXPECT_EQ(after.features.size(), before.features.size());

  // Random removal would hit spurious pairs at their share of all pairs (about 0.3 here).
  const std::set<ViewPair> spurious = SpuriousPairs();
  size_t hits = 0;
  for (const ViewPair& pair : removed) hits += spurious.count(pair);
  const double spurious_share = static_cast<double>(spurious.size()) / static_cast<double>(before.verified.size());
  EXPECT_GE(static_cast<double>(hits) / static_cast<double>(removed.size()), 0.5)
      << hits << " of " << removed.size() << " removed pairs are spurious (share of all pairs " << spurious_share
      << ")";

  // The same pruning as GLOBAL_PRUNED's on the same database and seed (its view_graph.json).
  const CommandResult run =
      RunPrunesfm({"run", "--database", input.string(), "--image_path", (scratch / "no_images").string(),
                   "--output_path", (scratch / "run").string(), "--engine", "GLOBAL_PRUNED", "--seed", "5"});
  ASSERT_EQ(run.exit_code, 0) << run.err;
  const nlohmann::json graph = nlohmann::json::parse(std::ifstream(scratch / "run" / "view_graph.json"));
  std::set<ViewPair> removed_by_engine;
  for (const nlohmann::json& edge : graph.at("edges")) {
    if (edge.at("removed").get<bool>()) {
      removed_by_engine.insert(MakeViewPair(edge.at("i").get<IndexT>(), edge.at("j").get<IndexT>()));
    }
  }
  EXPECT_EQ(removed, removed_by_engine);
}

// `prunesfm prune` of the 12-view orbit project's verified database with `extra_args`; its pruning
// report (empty, with a test failure, when the command fails).
nlohmann::json PruneOrbitReport(const std::string& scratch_name, const std::vector<std::string>& extra_args) {
  const fs::path scratch = ScratchDir(scratch_name);
  std::vector<std::string> args = {"prune", "--database", (OrbitProject(12) / "verified.db").string(), "--output",
                                   (scratch / "pruned.db").string()};
  args.insert(args.end(), extra_args.begin(), extra_args.end());
  const CommandResult result = RunPrunesfm(args);
  EXPECT_EQ(result.exit_code, 0) << result.err;
  if (result.exit_code != 0) return nlohmann::json::object({{"tree", nlohmann::json::array()}});
  return nlohmann::json::parse(std::ifstream(scratch / "pruned.pruning_report.json"));
}

TEST(CliPruneEndToEnd, ReportListsEachViolationOfAnInconsistentCommunity) {
  // Weighted by raw inliers, Louvain groups views of the twin faces, and that community fails the
  // paper's angle tests (the baseline-ratio test, listed as factors, is the next test's).
  const nlohmann::json report = PruneOrbitReport(
      "cli_prune_violations",
      {"--seed", "5", "--prune_edge_weight", "inliers", "--prune_max_baseline_ratio_factor", "0"});
  size_t listed = 0;
  for (const nlohmann::json& node : report.at("tree")) {
    if (!node.contains("violation_list")) continue;
    size_t counted = 0;
    for (const auto& [test, count] : node.at("violations").items()) counted += count.get<size_t>();
    EXPECT_EQ(node.at("violation_list").size(), counted) << node.dump();
    const std::set<IndexT> views(node.at("view_ids").begin(), node.at("view_ids").end());
    for (const nlohmann::json& v : node.at("violation_list")) {
      ++listed;
      EXPECT_GT(v.at("value_deg").get<double>(), v.at("threshold_deg").get<double>()) << v.dump();
      for (const nlohmann::json& view : v.at(v.at("test") == "loop" ? "loop" : "edge")) {
        EXPECT_EQ(views.count(view.get<IndexT>()), 1u) << v.dump();
      }
    }
  }
  EXPECT_GT(listed, 0u);
}

TEST(CliPruneEndToEnd, ReportListsBaselineRatioViolationsAsFactorsOverThreeViews) {
  // A factor of 1.01 is below the depths' noise, so some community fails the test.
  const nlohmann::json report =
      PruneOrbitReport("cli_prune_baseline_ratio", {"--prune_max_baseline_ratio_factor", "1.01"});
  size_t listed = 0;
  for (const nlohmann::json& node : report.at("tree")) {
    if (!node.contains("violation_list")) continue;
    size_t counted = 0;
    for (const nlohmann::json& v : node.at("violation_list")) {
      if (v.at("test") != "baseline_ratio") continue;
      ++counted;
      EXPECT_GT(v.at("factor").get<double>(), 1.01) << v.dump();
      EXPECT_DOUBLE_EQ(v.at("threshold_factor").get<double>(), 1.01);
      const std::set<IndexT> views(node.at("view_ids").begin(), node.at("view_ids").end());
      ASSERT_EQ(v.at("views").size(), 3u) << v.dump();
      for (const nlohmann::json& view : v.at("views")) EXPECT_EQ(views.count(view.get<IndexT>()), 1u) << v.dump();
    }
    EXPECT_EQ(node.at("violations").at("baseline_ratio").get<size_t>(), counted) << node.dump();
    if (counted > 0) {
      EXPECT_FALSE(node.at("consistent").get<bool>());
    }
    listed += counted;
  }
  EXPECT_GT(listed, 0u);
}

TEST(CliPruneEndToEnd, OpenMvgMatchFileLosesExactlyTheRemovedPairsAndDroppedMatches) {
  const fs::path scratch = ScratchDir("cli_prune_openmvg");
  const fs::path output = scratch / "matches.pruned.txt";
  const fs::path report = scratch / "report.json";
  const CommandResult result = RunPrunesfm(
      {"prune", "--sfm_data", (OrbitProject() / "sfm_data.json").string(), "--matches_dir",
       (OrbitProject() / "matches").string(), "--output", output.string(), "--report", report.string()});
  ASSERT_EQ(result.exit_code, 0) << result.err;
  const std::set<ViewPair> removed = RemovedPairs(report);
  const PairwiseMatches before = ReadOpenMvgMatches(OrbitProject() / "matches" / "matches.putative.bin");
  const PairwiseMatches after = ReadOpenMvgMatches(output);
  ASSERT_FALSE(removed.empty());
  EXPECT_EQ(after.size(), before.size() - removed.size());
  size_t dropped = 0;
  for (const auto& [pair, matches] : after) {
    EXPECT_EQ(removed.count(pair), 0u);
    ASSERT_LE(matches.size(), before.at(pair).size());
    dropped += before.at(pair).size() - matches.size();
  }
  EXPECT_EQ(nlohmann::json::parse(std::ifstream(report)).at("filter").at("matches_dropped").get<size_t>(), dropped);
}

}  // namespace
}  // namespace sfm_pruning::testing
