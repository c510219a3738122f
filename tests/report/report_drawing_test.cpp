// Layout, SVG helpers and data URIs: deterministic, and the drawings carry what they claim.
#include <gtest/gtest.h>

#include "report_test_run.hpp"
#include "sfm_pruning/report/data_uri.hpp"
#include "sfm_pruning/report/graph_layout.hpp"
#include "sfm_pruning/report/removal_summary.hpp"
#include "sfm_pruning/report/svg_builder.hpp"
#include "sfm_pruning/report/timings_drawing.hpp"
#include "sfm_pruning/report/top_view.hpp"
#include "sfm_pruning/report/view_graph_drawing.hpp"

namespace sfm_pruning::testing {
namespace {

size_t Count(const std::string& text, const std::string& needle) {
  size_t count = 0;
  for (size_t at = text.find(needle); at != std::string::npos; at = text.find(needle, at + 1)) ++count;
  return count;
}

TEST(ReportDrawing, Base64MatchesRfc4648Vectors) {
  const auto encode = [](const std::string& text) { return Base64Encode({text.begin(), text.end()}); };
  EXPECT_EQ(encode(""), "");
  EXPECT_EQ(encode("f"), "Zg==");
  EXPECT_EQ(encode("fo"), "Zm8=");
  EXPECT_EQ(encode("foo"), "Zm9v");
  EXPECT_EQ(encode("foobar"), "Zm9vYmFy");
  EXPECT_EQ(DataUri("image/png", {0xff, 0x00}), "data:image/png;base64,/wA=");
}

TEST(ReportDrawing, NumbersAndTextAreStableAndEscaped) {
  EXPECT_EQ(FormatNumber(12.50, 2), "12.5");
  EXPECT_EQ(FormatNumber(-0.0001, 1), "0");
  EXPECT_EQ(FormatNumber(3.0, 1), "3");
  EXPECT_EQ(EscapeXml("a<b & \"c\">"), "a&lt;b &amp; &quot;c&quot;&gt;");
}

TEST(ReportDrawing, LayoutIsSeededAndSeparatesWeaklyJoinedCliques) {
  // Two 6-cliques joined by one weak edge.
  std::vector<LayoutEdge> edges;
  for (size_t base : {0u, 6u}) {
    for (size_t a = 0; a < 6; ++a) {
      for (size_t b = a + 1; b < 6; ++b) edges.push_back({base + a, base + b, 1.0});
    }
  }
  edges.push_back({0, 6, 0.05});
  GraphLayoutOptions options;
  options.seed = 3;
  const auto layout = ForceDirectedLayout(12, edges, options);
  EXPECT_EQ(layout, ForceDirectedLayout(12, edges, options));
  options.seed = 4;
  EXPECT_NE(layout, ForceDirectedLayout(12, edges, options));
  double inside = 0.0, between = 0.0;
  for (size_t a = 0; a < 12; ++a) {
    EXPECT_GE(layout[a].minCoeff(), -1e-12);
    EXPECT_LE(layout[a].maxCoeff(), 1.0 + 1e-12);
    for (size_t b = a + 1; b < 12; ++b) {
      ((a < 6) == (b < 6) ? inside : between) += (layout[a] - layout[b]).norm() / ((a < 6) == (b < 6) ? 30.0 : 36.0);
    }
  }
  EXPECT_LT(inside, 0.6 * between) << "mean distance inside a clique vs between cliques";
}

TEST(ReportDrawing, GraphPanelsMarkEveryRemovedEdge) {
  const SfmData scene = RingScene(12);
  const RunViewGraph graph = TwoSubgraphGraph(scene);
  ASSERT_EQ(graph.NumRemovedEdges(), 6u);  // the ring crosses between the halves twice, 3 edges each
  const auto layout = LayoutRunViewGraph(graph, 0);
  const std::string before = DrawViewGraphSvg(graph, layout, ViewGraphPanel::kBeforePruning);
  const std::string after = DrawViewGraphSvg(graph, layout, ViewGraphPanel::kAfterPruning);
  EXPECT_EQ(Count(before, "<line"), graph.edges.size());
  EXPECT_EQ(Count(before, "stroke-dasharray"), 0u);
  // The removed edges all join subgraphs 1 and 2: one bundle.
  EXPECT_EQ(Count(after, "stroke-dasharray"), 1u);
  EXPECT_EQ(Count(after, "<circle"), 12u);
  EXPECT_NE(after.find("subgraph 1 - subgraph 2: 6 edges removed, 0 kept; all because they disagree with the "
                       "alignment of their two subgraphs that the inter-subgraph RANSAC chose (median 12.5\u00b0 off, "
                       "allowed 5\u00b0)"),
            std::string::npos);
  // Before pruning, each edge's tooltip gives its cut in words.
  EXPECT_NE(before.find("removed because they disagree with the alignment of their two subgraphs that the "
                        "inter-subgraph RANSAC chose (12.5\u00b0, bound 5\u00b0)"),
            std::string::npos);
  EXPECT_NE(after.find(SubgraphColor(1).Hex()), std::string::npos);
  EXPECT_EQ(after, DrawViewGraphSvg(graph, LayoutRunViewGraph(graph, 0), ViewGraphPanel::kAfterPruning));
}

TEST(ReportDrawing, RemovalSummaryGroupsCutsByReasonAndSubgraphPair) {
  RunViewGraph graph = TwoSubgraphGraph(RingScene(12));
  // One cut by the model audit instead, and one removed edge inside subgraph 1.
  for (RunGraphEdge& edge : graph.edges) {
    if (edge.removed) {
      edge = {edge.i, edge.j, edge.inliers, true, "model_disagreement", 0.05, 0.2, "agreeing_share", {}};
      break;
    }
  }
  RunGraphEdge& inside = graph.edges.front();
  ASSERT_FALSE(inside.removed);
  inside = {inside.i, inside.j, inside.inliers, true, "landmark_disagreement", 3, 5, "matches_left", {}};

  const RemovalSummary summary = SummariseRemovals(graph);
  EXPECT_EQ(summary.edges, graph.edges.size());
  EXPECT_EQ(summary.removed, 7u);
  ASSERT_EQ(summary.groups.size(), 3u);
  EXPECT_EQ(summary.groups[0].reason, "inter_subgraph_inconsistent");
  EXPECT_EQ(summary.groups[0].edges, 5u);
  EXPECT_EQ(summary.groups[0].subgraph_pairs, 1u);
  EXPECT_EQ(GroupMeasureInWords(summary.groups[0]), "median 12.5\u00b0 off, allowed 5\u00b0");
  // Ties in count: by reason name.
  EXPECT_EQ(summary.groups[1].reason, "landmark_disagreement");
  EXPECT_EQ(GroupMeasureInWords(summary.groups[1]), "median 3 matches left, 5 needed");
  EXPECT_EQ(summary.groups[2].reason, "model_disagreement");
  EXPECT_EQ(GroupMeasureInWords(summary.groups[2]), "median 5 % of the matches agree with the model, 20 % needed");

  // Most removed first: the pair of the two subgraphs, then the one inside subgraph 1.
  ASSERT_EQ(summary.pairs.size(), 2u);
  EXPECT_EQ(std::make_pair(summary.pairs[0].a, summary.pairs[0].b), std::make_pair(0, 1));
  EXPECT_EQ(summary.pairs[0].removed, 6u);
  EXPECT_EQ(summary.pairs[0].main.reason, "inter_subgraph_inconsistent");
  EXPECT_EQ(summary.pairs[0].main.edges, 5u);
  EXPECT_EQ(std::make_pair(summary.pairs[1].a, summary.pairs[1].b), std::make_pair(0, 0));
  EXPECT_EQ(summary.pairs[1].removed, 1u);

  // The bundle between the subgraphs, plus the removed edge inside one drawn alone.
  const std::string after =
      DrawViewGraphSvg(graph, LayoutRunViewGraph(graph, 0), ViewGraphPanel::kAfterPruning);
  EXPECT_EQ(Count(after, "stroke-dasharray"), 2u);
  EXPECT_NE(after.find("6 edges removed, 0 kept; 5 because they disagree"), std::string::npos);

  // Files from before the measure was recorded: the bare numbers.
  EXPECT_EQ(MeasureValueInWords("subgraph_loop_inconsistent", "", 1.814), "1.81");
  EXPECT_EQ(MeasureValueInWords("subgraph_loop_inconsistent", "translation_fraction", 0.5),
            "0.5 \u00d7 the loop's mean side");
  EXPECT_EQ(RemovalReasonInWords("a_future_reason"), "a_future_reason");
}

TEST(ReportDrawing, TopViewLooksDownOnTheGround) {
  const SfmData scene = RingScene(8);
  TopViewScene top;
  for (const auto& [id, view] : scene.views) top.cameras.push_back({view.filename, scene.poses.at(id), {}, {}});
  const TopViewFrame frame = TopViewFrameOf(top);
  // Cameras are upright (camera y = world -z): the view is along world z, axes in the ground plane.
  EXPECT_NEAR(frame.axis_x.cross(frame.axis_y).dot(Eigen::Vector3d::UnitZ()), 1.0, 1e-9);
  EXPECT_NEAR(frame.axis_x.z(), 0.0, 1e-9);
  const std::string svg = DrawTopViewSvg(top, frame);
  EXPECT_EQ(Count(svg, "<polygon"), 8u);
  EXPECT_EQ(Count(svg, "<polyline"), 1u);  // the trajectory; no truth

  // The same ring shot with the camera held sideways (as the Middlebury rings): the plane of the
  // centres still gives the ground, seen from above.
  const Eigen::Matrix3d roll = Eigen::AngleAxisd(M_PI / 2.0, Eigen::Vector3d::UnitZ()).toRotationMatrix();
  for (TopViewCamera& camera : top.cameras) camera.pose.rotation = roll * camera.pose.rotation;
  const TopViewFrame sideways = TopViewFrameOf(top);
  EXPECT_NEAR(sideways.axis_x.cross(sideways.axis_y).dot(Eigen::Vector3d::UnitZ()), 1.0, 1e-9);
}

TEST(ReportDrawing, TimingBarsCoverTheUnionOfStages) {
  const std::string svg = DrawTimingsSvg({{"A", {{"verification", 2.0}, {"bundle adjustment", 1.0}}},
                                          {"B", {{"verification", 1.0}, {"subgraph partition", 3.0}}}});
  EXPECT_EQ(Count(svg, "<rect"), 6u);  // 3 stages x 2 runs, missing ones drawn empty
  EXPECT_NE(svg.find("A: 3 s"), std::string::npos);
  EXPECT_NE(svg.find("B: 4 s"), std::string::npos);
  EXPECT_NE(svg.find("B: subgraph partition 3 s"), std::string::npos);
}

TEST(ReportDrawing, RepeatedStagesAreSummedInTheOrderTheyFirstAppear) {
  const std::vector<StageTotal> totals =
      TotalsByStage({{"partition", 2.0}, {"solve", 1.5}, {"check", 0.25}, {"solve", 2.5}, {"check", 0.25},
                     {"adjustment", 1.0}});
  ASSERT_EQ(totals.size(), 4u);
  EXPECT_EQ(totals[1].stage, "solve");
  EXPECT_DOUBLE_EQ(totals[1].seconds, 4.0);
  EXPECT_EQ(totals[1].runs, 2);
  EXPECT_EQ(totals[2].stage, "check");
  EXPECT_EQ(totals[3].stage, "adjustment");
  EXPECT_EQ(totals[3].runs, 1);
  // The timing bars draw each stage once, with its total.
  const std::string svg = DrawTimingsSvg({{"A", {{"solve", 1.5}, {"check", 0.25}, {"solve", 2.5}}}});
  EXPECT_EQ(Count(svg, "<rect"), 2u);
  EXPECT_NE(svg.find("A: solve 4 s"), std::string::npos);
}

}  // namespace
}  // namespace sfm_pruning::testing
