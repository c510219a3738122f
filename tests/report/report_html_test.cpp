// The run folder record and the HTML page: round trips, one-line errors, determinism, content.
#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <cmath>
#include <fstream>
#include <regex>

#include "report_test_run.hpp"
#include "sfm_pruning/report/html_report.hpp"
#include "sfm_pruning/util/error.hpp"
#include "support/test_data.hpp"

namespace sfm_pruning::testing {
namespace {
namespace fs = std::filesystem;

std::string ErrorOf(const std::function<void()>& call) {
  try {
    call();
  } catch (const Error& e) {
    return e.what();
  }
  return "";
}

TEST(ReportHtml, ViewGraphRecordRoundTrips) {
  const fs::path dir = ScratchDir("report_view_graph_round_trip");
  RunViewGraph graph = TwoSubgraphGraph(RingScene(10));
  graph.edges.front().relative_pose = {Eigen::AngleAxisd(0.3, Eigen::Vector3d(1, 2, 3).normalized()).toRotationMatrix(),
                                       Eigen::Vector3d(0.6, 0.0, -0.8)};
  graph.edges.front().rotation_std_deg = 0.37;  // the others were not estimated: infinite, not written
  WriteRunViewGraph(graph, dir / "view_graph.json");
  const RunViewGraph read = ReadRunViewGraph(dir / "view_graph.json");
  ASSERT_EQ(read.views.size(), 10u);
  ASSERT_EQ(read.edges.size(), graph.edges.size());
  EXPECT_EQ(read.num_subgraphs, 2);
  EXPECT_EQ(read.NumRemovedEdges(), graph.NumRemovedEdges());
  for (size_t k = 0; k < graph.edges.size(); ++k) {
    EXPECT_EQ(read.edges[k].i, graph.edges[k].i);
    EXPECT_EQ(read.edges[k].j, graph.edges[k].j);
    EXPECT_EQ(read.edges[k].inliers, graph.edges[k].inliers);
    EXPECT_EQ(read.edges[k].reason, graph.edges[k].reason);
    EXPECT_EQ(read.edges[k].value, graph.edges[k].value);
    EXPECT_EQ(read.edges[k].measure, graph.edges[k].measure);
    EXPECT_LT((read.edges[k].relative_pose.rotation - graph.edges[k].relative_pose.rotation).norm(), 1e-12);
    EXPECT_LT((read.edges[k].relative_pose.translation - graph.edges[k].relative_pose.translation).norm(), 1e-12);
    EXPECT_EQ(read.edges[k].rotation_std_deg, graph.edges[k].rotation_std_deg);
  }
  EXPECT_TRUE(std::isinf(read.edges.back().rotation_std_deg));
}

TEST(ReportHtml, CorruptRunFilesAreOneLineErrors) {
  const fs::path dir = ScratchDir("report_corrupt_run");
  const std::string path = (dir / "view_graph.json").string();
  std::ofstream(dir / "view_graph.json") << "{\"engine\": \"GLOBAL\", \"num_subgraphs\": 0, \"views\": [";
  EXPECT_EQ(ErrorOf([&]() { ReadRunViewGraph(dir / "view_graph.json"); }), path + ": not valid JSON");
  std::ofstream(dir / "view_graph.json")
      << R"({"engine": "GLOBAL", "num_subgraphs": 0, "views": [{"view_id": 0, "image": "a", "subgraph": -1}],)"
         R"( "edges": [{"i": 0, "j": 5, "inliers": 3, "removed": false}]})";
  EXPECT_EQ(ErrorOf([&]() { ReadRunViewGraph(dir / "view_graph.json"); }),
            path + ": edge 0-5 does not join two listed views");
  std::ofstream(dir / "view_graph.json") << R"({"engine": "GLOBAL", "num_subgraphs": 0, "views": 3, "edges": []})";
  EXPECT_NE(ErrorOf([&]() { ReadRunViewGraph(dir / "view_graph.json"); }).rfind(path + ": view graph: ", 0),
            std::string::npos);
  EXPECT_EQ(ErrorOf([&]() { ReadRunFolder(dir / "missing"); }),
            (dir / "missing").string() + ": not a run folder (no such directory)");
  EXPECT_EQ(ErrorOf([&]() { ReadRunFolder(dir); }), dir.string() + ": not a run folder: neither sfm_data.json nor sparse/0");
}

TEST(ReportHtml, ComparisonPageIsSelfContainedDeterministicAndComplete) {
  const fs::path dir = ScratchDir("report_html_compare");
  const SfmData scene = RingScene(12);
  WriteTestRun(scene, "GLOBAL_PRUNED", dir / "pruned");
  WriteTestRun(scene, "GLOBAL", dir / "folded");
  HtmlReportInput input;
  input.runs = {ReadRunFolder(dir / "pruned"), ReadRunFolder(dir / "folded")};
  ASSERT_TRUE(input.runs[0].pruning == std::nullopt);  // no pruning_report.json written
  ASSERT_TRUE(input.runs[0].view_graph.has_value());
  EXPECT_EQ(input.runs[0].engine, "GLOBAL_PRUNED");
  EXPECT_EQ(input.runs[0].stages.size(), 2u);
  input.ground_truth = scene;
  input.ground_truth_source = "truth";
  const std::string html = BuildHtmlReport(input);
  EXPECT_EQ(html, BuildHtmlReport(input));
  for (const char* id : {"summary", "graph", "topview", "epipolar", "timings"}) {
    EXPECT_NE(html.find(std::string("<section id=\"") + id + "\">"), std::string::npos) << id;
  }
  // Nothing to fetch: the only URL is the SVG namespace, every src/href is a data URI or an anchor.
  const std::string without_namespace = std::regex_replace(html, std::regex("http://www\\.w3\\.org/2000/svg"), "");
  EXPECT_FALSE(std::regex_search(without_namespace, std::regex("https?:|url\\(|@import")));
  EXPECT_FALSE(std::regex_search(html, std::regex("(src|href)=\"(?!data:|#)")));
  EXPECT_NE(html.find("src=\"data:image/jpeg;base64,"), std::string::npos);
  // 2 runs x 2 checks of JPEG pictures, graph before/after, 2 top views, timings.
  size_t pictures = 0;
  for (size_t at = html.find("data:image/jpeg"); at != std::string::npos; at = html.find("data:image/jpeg", at + 1)) {
    ++pictures;
  }
  EXPECT_EQ(pictures, 4u);
  size_t svgs = 0;
  for (size_t at = html.find("<svg "); at != std::string::npos; at = html.find("<svg ", at + 1)) ++svgs;
  EXPECT_EQ(svgs, 5u);
  // The estimate is the truth: every AUC card reads 100.
  EXPECT_NE(html.find("AUC@3\u00b0</div><div class=\"v\">100 <small>%</small>"), std::string::npos);
  EXPECT_NE(html.find("After pruning: 18 edges kept, 6 removed"), std::string::npos);
  // The summary leads the graph section, in words with units.
  EXPECT_NE(html.find("The pruning removed 6 of 24 verified edges."), std::string::npos);
  EXPECT_NE(html.find("<tr><td>6</td><td>they disagree with the alignment of their two subgraphs that the "
                      "inter-subgraph RANSAC chose <small><code>inter_subgraph_inconsistent</code></small></td>"
                      "<td>1</td><td>median 12.5\u00b0 off, allowed 5\u00b0</td></tr>"),
            std::string::npos);
}

}  // namespace
}  // namespace sfm_pruning::testing
