// Layout, SVG helpers and data URIs: deterministic, and the drawings carry what they claim.
#include <gtest/gtest.h>

#include "report_test_run.hpp"
#include "sfm_pruning/report/data_uri.hpp"
#include "sfm_pruning/report/graph_layout.hpp"
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
  EXPECT_EQ(Count(after, "stroke-dasharray"), graph.NumRemovedEdges());
  EXPECT_EQ(Count(after, "<circle"), 12u);
  EXPECT_NE(after.find("removed (inter_subgraph_inconsistent: 12.5 &gt; 5)"), std::string::npos);
  EXPECT_NE(after.find(SubgraphColor(1).Hex()), std::string::npos);
  EXPECT_EQ(after, DrawViewGraphSvg(graph, LayoutRunViewGraph(graph, 0), ViewGraphPanel::kAfterPruning));
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

}  // namespace
}  // namespace sfm_pruning::testing
