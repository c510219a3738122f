#include "sfm_pruning/view_graph/components.hpp"

#include <gtest/gtest.h>

#include "view_graph/graph_builders.hpp"

namespace sfm_pruning {
namespace {

// Components {1,2,3}, {5,6,7}, {8,9}, {0}, {4}: 4 reaches 3 only through an invalid edge.
ViewGraph FiveComponents() {
  ViewGraph graph;
  for (IndexT id = 0; id < 10; ++id) graph.AddNode(id);
  testing::AddWeightedEdges(&graph, {{6, 7, 1}, {5, 6, 1}, {8, 9, 100}, {2, 3, 1}, {1, 2, 1}, {3, 4, 50}});
  graph.InvalidateEdge(3, 4, {EdgeInvalidReason::kTooFewInliers, 12, 30});
  return graph;
}

TEST(Components, SortedBySizeThenSmallestId) {
  const std::vector<NodeGroup> components = ConnectedComponents(FiveComponents());
  const std::vector<NodeGroup> expected = {{1, 2, 3}, {5, 6, 7}, {8, 9}, {0}, {4}};
  EXPECT_EQ(components, expected);
  EXPECT_EQ(LargestComponent(FiveComponents()), (NodeGroup{1, 2, 3}));
}

TEST(Components, EmptyGraph) {
  EXPECT_TRUE(ConnectedComponents(ViewGraph()).empty());
  EXPECT_TRUE(LargestComponent(ViewGraph()).empty());
}

TEST(Components, KeepLargestComponentReportsDroppedViews) {
  ViewGraph graph = FiveComponents();
  const LargestComponentSelection selection = KeepLargestComponent(&graph);
  EXPECT_EQ(selection.kept, (NodeGroup{1, 2, 3}));
  EXPECT_EQ(selection.dropped, (NodeGroup{0, 4, 5, 6, 7, 8, 9}));
  EXPECT_EQ(graph.Nodes(), (std::set<IndexT>{1, 2, 3}));
  // The invalid edge 3-4 went with view 4; the component's own edges remain.
  EXPECT_EQ(graph.NumEdges(), 2u);
  EXPECT_EQ(graph.ValidEdgePairs(), (std::vector<ViewPair>{{1, 2}, {2, 3}}));
  EXPECT_EQ(ConnectedComponents(graph).size(), 1u);
}

TEST(Components, ConnectedGraphDropsNothing) {
  ViewGraph graph;
  testing::AddClique(&graph, {4, 7, 9}, 3);
  const LargestComponentSelection selection = KeepLargestComponent(&graph);
  EXPECT_EQ(selection.kept, (NodeGroup{4, 7, 9}));
  EXPECT_TRUE(selection.dropped.empty());
  EXPECT_EQ(graph.NumValidEdges(), 3u);
}

}  // namespace
}  // namespace sfm_pruning
