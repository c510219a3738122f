#include "sfm_pruning/view_graph/view_graph.hpp"

#include <gtest/gtest.h>

#include <stdexcept>

#include "view_graph/graph_builders.hpp"

namespace sfm_pruning {
namespace {

// Rotation and translation direction equal to `tol`: view graphs store |t| = 1.
void ExpectSameRelativeDirection(const RelativePose& actual, const RelativePose& expected, double tol) {
  EXPECT_LT((actual.rotation - expected.rotation).norm(), tol);
  EXPECT_LT((actual.translation.normalized() - expected.translation.normalized()).norm(), tol);
}

TEST(ViewGraph, AddEdgeStoresPairOrientationAndInlierWeight) {
  const std::map<IndexT, Pose> poses = testing::RandomPoses(2, 7);
  // Given from 1 to 0: the graph must store it as (0, 1), inverted and with swapped matches.
  RelativePose pose_1_to_0 = RelativePoseBetween(poses.at(1), poses.at(0));
  pose_1_to_0.translation.normalize();
  ViewGraph graph;
  graph.AddEdge(1, 0, {{10, 20}, {11, 21}, {12, 22}}, pose_1_to_0);

  ASSERT_EQ(graph.Edges().size(), 1u);
  const auto& [pair, edge] = *graph.Edges().begin();
  EXPECT_EQ(pair, ViewPair(0, 1));
  EXPECT_DOUBLE_EQ(edge.weight, 3.0);
  EXPECT_TRUE(edge.is_valid);
  EXPECT_EQ(edge.invalidation.reason, EdgeInvalidReason::kNone);
  EXPECT_EQ(edge.matches[0], (FeatureMatch{20, 10}));
  EXPECT_EQ(edge.matches[2], (FeatureMatch{22, 12}));
  ExpectSameRelativeDirection(edge.relative_pose, RelativePoseBetween(poses.at(0), poses.at(1)), 1e-12);
  EXPECT_NEAR(edge.relative_pose.translation.norm(), 1.0, 1e-12);
  EXPECT_EQ(graph.OrientedMatches(1, 0)[1], (FeatureMatch{11, 21}));
  EXPECT_EQ(graph.OrientedMatches(0, 1)[1], (FeatureMatch{21, 11}));
}

TEST(ViewGraph, OrientedRelativePoseMatchesPoseHelpersBothWays) {
  const std::map<IndexT, Pose> poses = testing::RandomPoses(4, 11);
  ViewGraph graph;
  testing::AddEdgesFromPoses(&graph, poses, {{0, 3}, {2, 1}, {1, 3}});
  for (const auto& [a, b] : std::vector<ViewPair>{{0, 3}, {3, 0}, {1, 2}, {2, 1}, {3, 1}, {1, 3}}) {
    SCOPED_TRACE(::testing::Message() << a << " -> " << b);
    const RelativePose oriented = graph.OrientedRelativePose(a, b);
    ExpectSameRelativeDirection(oriented, RelativePoseBetween(poses.at(a), poses.at(b)), 1e-12);
    // Composing with camera a's pose must land on camera b's rotation.
    const Pose composed = ComposePose(poses.at(a), oriented);
    EXPECT_LT((composed.rotation - poses.at(b).rotation).norm(), 1e-12);
  }
  EXPECT_THROW(graph.OrientedRelativePose(0, 1), std::out_of_range);
}

TEST(ViewGraph, InvalidEdgesStayButAreSkippedByValidQueries) {
  ViewGraph graph;
  testing::AddWeightedEdges(&graph, {{0, 1, 5}, {1, 2, 7}, {0, 2, 9}, {2, 3, 1}});
  graph.AddNode(9);
  EXPECT_EQ(graph.NumValidEdges(), 4u);
  EXPECT_DOUBLE_EQ(graph.WeightedDegree(2), 17.0);

  EXPECT_TRUE(graph.InvalidateEdge(2, 0, {EdgeInvalidReason::kRotationResidual, 12.5, 10.0}));
  // A second cut keeps the first reason: that is the stage which removed the edge.
  EXPECT_FALSE(graph.InvalidateEdge(0, 2, {EdgeInvalidReason::kOther, 1.0, 0.0}));
  const ViewGraphEdge* cut = graph.FindEdge(0, 2);
  ASSERT_NE(cut, nullptr);
  EXPECT_FALSE(cut->is_valid);
  EXPECT_EQ(cut->invalidation.reason, EdgeInvalidReason::kRotationResidual);
  EXPECT_DOUBLE_EQ(cut->invalidation.value, 12.5);
  EXPECT_DOUBLE_EQ(cut->invalidation.threshold, 10.0);
  EXPECT_EQ(EdgeInvalidReasonName(cut->invalidation.reason), "rotation_residual");
  // Unnamed, the measure is the reason's own; a producer can name another.
  EXPECT_EQ(cut->invalidation.Measure(), EdgeMeasure::kDegrees);
  EXPECT_EQ(EdgeMeasureName(cut->invalidation.Measure()), "degrees");
  const EdgeInvalidation by_scale{EdgeInvalidReason::kSubgraphLoopInconsistent, 2.5, 2.0, EdgeMeasure::kScaleRatio};
  EXPECT_EQ(EdgeMeasureName(by_scale.Measure()), "scale_ratio");
  EXPECT_EQ(DefaultEdgeMeasure(EdgeInvalidReason::kSubgraphLoopInconsistent), EdgeMeasure::kBrokenLoops);
  EXPECT_EQ(DefaultEdgeMeasure(EdgeInvalidReason::kModelDisagreement), EdgeMeasure::kAgreeingShare);

  EXPECT_EQ(graph.NumEdges(), 4u);
  EXPECT_EQ(graph.NumValidEdges(), 3u);
  EXPECT_FALSE(graph.HasValidEdge(0, 2));
  EXPECT_TRUE(graph.HasValidEdge(2, 1));
  EXPECT_EQ(graph.ValidEdgePairs(), (std::vector<ViewPair>{{0, 1}, {1, 2}, {2, 3}}));
  EXPECT_EQ(graph.ValidNeighbors(2), (std::vector<IndexT>{1, 3}));
  EXPECT_TRUE(graph.ValidNeighbors(9).empty());
  EXPECT_TRUE(graph.ValidNeighbors(42).empty());
  EXPECT_DOUBLE_EQ(graph.WeightedDegree(2), 8.0);

  const auto adjacency = graph.ValidAdjacency();
  EXPECT_EQ(adjacency.size(), 5u);
  EXPECT_EQ(adjacency.at(1), (std::vector<IndexT>{0, 2}));
  EXPECT_TRUE(adjacency.at(9).empty());

  std::vector<ViewPair> visited;
  graph.ForEachValidEdge([&](const ViewPair& pair, const ViewGraphEdge&) { visited.push_back(pair); });
  EXPECT_EQ(visited, graph.ValidEdgePairs());
}

TEST(ViewGraph, InducedSubgraphKeepsEdgesAndFlagsInside) {
  ViewGraph graph;
  testing::AddWeightedEdges(&graph, {{0, 1, 5}, {1, 2, 7}, {0, 2, 9}, {2, 3, 1}});
  graph.InvalidateEdge(1, 2, {EdgeInvalidReason::kInterSubgraphInconsistent, 6.0, 5.0});

  const ViewGraph sub = graph.InducedSubgraph({0, 1, 2, 77});  // 77 is not a node: ignored
  EXPECT_EQ(sub.Nodes(), (std::set<IndexT>{0, 1, 2}));
  EXPECT_EQ(sub.NumEdges(), 3u);
  EXPECT_EQ(sub.NumValidEdges(), 2u);
  EXPECT_EQ(sub.FindEdge(1, 2)->invalidation.reason, EdgeInvalidReason::kInterSubgraphInconsistent);
  EXPECT_DOUBLE_EQ(sub.FindEdge(0, 2)->weight, 9.0);
  EXPECT_EQ(sub.FindEdge(2, 3), nullptr);

  const ViewGraph pair_only = graph.InducedSubgraph({3, 0});
  EXPECT_EQ(pair_only.NumNodes(), 2u);
  EXPECT_EQ(pair_only.NumEdges(), 0u);
}

TEST(ViewGraph, RemoveNodesDropsTheirEdges) {
  ViewGraph graph;
  testing::AddWeightedEdges(&graph, {{0, 1, 5}, {1, 2, 7}, {2, 3, 1}});
  graph.RemoveNodes({1, 42});
  EXPECT_EQ(graph.Nodes(), (std::set<IndexT>{0, 2, 3}));
  EXPECT_EQ(graph.ValidEdgePairs(), (std::vector<ViewPair>{{2, 3}}));
  EXPECT_TRUE(graph.ValidNeighbors(0).empty());
}

TEST(ViewGraph, RejectsSelfLoopsAndUnorderedPairs) {
  ViewGraph graph;
  EXPECT_THROW(graph.AddEdge(3, 3, {}, RelativePose()), std::invalid_argument);
  EXPECT_THROW(graph.AddEdge(ViewPair{4, 2}, ViewGraphEdge()), std::invalid_argument);
  EXPECT_THROW(graph.InvalidateEdge(0, 1, {}), std::out_of_range);
  EXPECT_EQ(graph.NumNodes(), 0u);
}

}  // namespace
}  // namespace sfm_pruning
