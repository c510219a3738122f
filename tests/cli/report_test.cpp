// prunesfm run writes view_graph.json; prunesfm report and prunesfm epipolar end to end on a
// small synthetic scene, and their one-line errors.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include <nlohmann/json.hpp>

#include "run_prunesfm.hpp"
#include "support/test_data.hpp"

namespace sfm_pruning::testing {
namespace {
namespace fs = std::filesystem;

// A 10-view clean scene reconstructed once per process with GLOBAL_PRUNED (ctest runs each test
// in its own process: the folder is named after the first test that asks for it).
const fs::path& PrunedRun() {
  static const fs::path dir = []() {
    const std::string test_name = ::testing::UnitTest::GetInstance()->current_test_info()->name();
    const fs::path scratch = ScratchDir("cli_report_" + test_name);
    const CommandResult synth =
        RunPrunesfm({"synth", "--scene", "clean", "--seed", "4", "--num_views", "10", "--output", (scratch / "scene").string()});
    EXPECT_EQ(synth.exit_code, 0) << synth.err;
    const CommandResult run = RunPrunesfm({"run", "--database", (scratch / "scene" / "database.db").string(),
                                           "--image_path", (scratch / "scene" / "images").string(), "--output_path",
                                           (scratch / "pruned").string(), "--engine", "GLOBAL_PRUNED"});
    EXPECT_EQ(run.exit_code, 0) << run.err;
    return scratch;
  }();
  return dir;
}

TEST(CliReport, RunRecordsTheViewGraphAndReportAndEpipolarDrawIt) {
  const nlohmann::json graph = nlohmann::json::parse(std::ifstream(PrunedRun() / "pruned" / "view_graph.json"));
  EXPECT_EQ(graph.at("engine"), "GLOBAL_PRUNED");
  EXPECT_EQ(graph.at("views").size(), 10u);
  EXPECT_GE(graph.at("num_subgraphs").get<int>(), 1);
  const nlohmann::json pruning = nlohmann::json::parse(std::ifstream(PrunedRun() / "pruned" / "pruning_report.json"));
  EXPECT_EQ(graph.at("edges").size(), pruning.at("edges_in").get<size_t>());
  size_t removed = 0;
  for (const auto& edge : graph.at("edges")) {
    if (!edge.at("removed").get<bool>()) continue;
    ++removed;
    EXPECT_NE(edge.at("measure").get<std::string>(), "unspecified") << edge.dump();
  }
  EXPECT_EQ(removed, pruning.at("removed_edges").size());

  const fs::path scratch = ScratchDir("cli_report_outputs");
  // A second run folder without the view graph (as written before the report existed).
  fs::create_directories(scratch / "older");
  fs::copy_file(PrunedRun() / "pruned" / "sfm_data.json", scratch / "older" / "sfm_data.json");
  const std::string gt = (PrunedRun() / "scene" / "ground_truth" / "gt_cameras.txt").string();
  const CommandResult report =
      RunPrunesfm({"report", "--run", (PrunedRun() / "pruned").string(), "--compare", (scratch / "older").string(),
                   "--ground_truth", gt, "--check", "view_00002.jpg:500,380", "--output", (scratch / "r.html").string()});
  ASSERT_EQ(report.exit_code, 0) << report.err;
  std::ifstream in(scratch / "r.html");
  const std::string html((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  EXPECT_NE(html.find("view_00002.jpg at (500, 380)"), std::string::npos);
  EXPECT_NE(html.find("View graph before and after pruning"), std::string::npos);
  EXPECT_NE(html.find(removed == 0 ? std::string("The pruning removed no edge.")
                                   : "The pruning removed " + std::to_string(removed) + " of " +
                                         std::to_string(graph.at("edges").size()) + " verified edges."),
            std::string::npos);

  const CommandResult epipolar =
      RunPrunesfm({"epipolar", "--model", (PrunedRun() / "pruned" / "sfm_data.json").string(), "--image",
                   "view_00002.jpg", "--point", "500,380", "--ground_truth", gt, "--output", (scratch / "e.png").string()});
  ASSERT_EQ(epipolar.exit_code, 0) << epipolar.err;
  EXPECT_GT(fs::file_size(scratch / "e.png"), 1000u);
}

TEST(CliReport, BadInputGivesOneLineNamingIt) {
  const fs::path scratch = ScratchDir("cli_report_errors");
  // No engine needed: the synthetic truth is a model like any run's.
  const CommandResult synth =
      RunPrunesfm({"synth", "--scene", "clean", "--seed", "4", "--num_views", "6", "--output", (scratch / "scene").string()});
  ASSERT_EQ(synth.exit_code, 0) << synth.err;
  fs::create_directories(scratch / "run");
  fs::copy_file(scratch / "scene" / "ground_truth" / "sfm_data.json", scratch / "run" / "sfm_data.json");
  const std::string run = (scratch / "run").string();
  const auto expect_error = [](const CommandResult& result, const std::string& needle) {
    EXPECT_EQ(result.exit_code, 1);
    EXPECT_EQ(CountLines(result.err), 1) << result.err;
    EXPECT_NE(result.err.find(needle), std::string::npos) << result.err;
  };
  expect_error(RunPrunesfm({"report", "--run", "/nonexistent/run", "--output", (scratch / "r.html").string()}),
               "/nonexistent/run: not a run folder");
  expect_error(RunPrunesfm({"report", "--run", run, "--check", "view_00002.jpg:12", "--output",
                            (scratch / "r.html").string()}),
               "--check: expected a pixel as x,y");
  expect_error(RunPrunesfm({"report", "--run", run, "--check", "nope.jpg:1,2", "--output", (scratch / "r.html").string()}),
               "image nope.jpg is not in the model");
  expect_error(RunPrunesfm({"report", "--run", run, "--images", (scratch / "no_images").string(), "--output",
                            (scratch / "r.html").string()}),
               "no_images: no such image folder");
  fs::create_directories(scratch / "corrupt");
  fs::copy_file(scratch / "run" / "sfm_data.json", scratch / "corrupt" / "sfm_data.json");
  std::ofstream(scratch / "corrupt" / "timings.json") << "{\"engine\": ";
  expect_error(RunPrunesfm({"report", "--run", (scratch / "corrupt").string(), "--output", (scratch / "r.html").string()}),
               "timings.json: not valid JSON");
  expect_error(RunPrunesfm({"epipolar", "--model", run + "/sfm_data.json", "--image", "view_00002.jpg", "--point",
                            "5000,1", "--output", (scratch / "e.png").string()}),
               "is outside image view_00002.jpg");
  expect_error(RunPrunesfm({"epipolar", "--model", run + "/sfm_data.json", "--image", "view_00002.jpg", "--output",
                            (scratch / "e.gif").string()}),
               "must end in .png or .jpg");
  EXPECT_FALSE(fs::exists(scratch / "r.html"));
}

}  // namespace
}  // namespace sfm_pruning::testing
