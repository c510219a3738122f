#include "sfm_pruning/view_graph/spanning_tree.hpp"

#include <gtest/gtest.h>

#include "view_graph/graph_builders.hpp"

namespace sfm_pruning {
namespace {

// Hand-made graph (weights = inliers):
//   (0,1) 10  (1,2) 8  (2,3) 6  (2,4) 4  (3,4) 4  (0,2) 3  (1,3) 2  (0,4) 1,
//   plus (0,3) 100 flagged invalid, which must be ignored.
// Kruskal, heaviest first: take (0,1), (1,2), (2,3); (2,4) and (3,4) tie at 4 and (2,4) comes
// first in pair order, so it joins 4; everything after closes a cycle.
// Tree {(0,1), (1,2), (2,3), (2,4)}, total 10 + 8 + 6 + 4 = 28.
// Weighted degrees: 0: 14, 1: 20, 2: 21, 3: 12, 4: 9 -> root 2.
// BFS from 2, children by increasing id: 2, 1, 3, 4, then 0 (child of 1).
ViewGraph HandMadeGraph() {
  ViewGraph graph;
  testing::AddWeightedEdges(
      &graph,
      {{0, 1, 10}, {1, 2, 8}, {2, 3, 6}, {3, 4, 4}, {2, 4, 4}, {0, 2, 3}, {1, 3, 2}, {0, 4, 1}, {0, 3, 100}});
  graph.InvalidateEdge(0, 3, {EdgeInvalidReason::kRotationResidual, 40, 10});
  return graph;
}

TEST(MaximumSpanningTree, HandMadeGraph) {
  const SpanningTree tree = MaximumSpanningTree(HandMadeGraph());
  EXPECT_EQ(tree.root, 2u);
  EXPECT_EQ(tree.edges, (std::vector<ViewPair>{{0, 1}, {1, 2}, {2, 3}, {2, 4}}));
  EXPECT_DOUBLE_EQ(tree.total_weight, 28.0);
  EXPECT_EQ(tree.bfs_order, (std::vector<IndexT>{2, 1, 3, 4, 0}));
  const std::map<IndexT, IndexT> expected_parent = {{0, 1}, {1, 2}, {2, 2}, {3, 2}, {4, 2}};
  EXPECT_EQ(tree.parent, expected_parent);
}

TEST(MaximumSpanningTree, EqualDegreesPickSmallestIdRoot) {
  ViewGraph graph;
  testing::AddClique(&graph, {3, 5, 8}, 7);
  const SpanningTree tree = MaximumSpanningTree(graph);
  EXPECT_EQ(tree.root, 3u);
  // All weights tie: pair order takes (3,5) and (3,8); (5,8) would close the cycle.
  EXPECT_EQ(tree.edges, (std::vector<ViewPair>{{3, 5}, {3, 8}}));
  EXPECT_DOUBLE_EQ(tree.total_weight, 14.0);
}

TEST(MaximumSpanningTree, DisconnectedGraphSpansTheRootComponent) {
  ViewGraph graph;
  testing::AddWeightedEdges(&graph, {{0, 1, 1}, {5, 6, 9}, {6, 7, 9}});
  graph.AddNode(3);
  const SpanningTree tree = MaximumSpanningTree(graph);
  EXPECT_EQ(tree.root, 6u);
  EXPECT_EQ(tree.bfs_order, (std::vector<IndexT>{6, 5, 7}));
  EXPECT_EQ(tree.parent.count(0), 0u);
  EXPECT_DOUBLE_EQ(tree.total_weight, 18.0);
}

TEST(MaximumSpanningTree, EmptyAndSingleNode) {
  const SpanningTree empty = MaximumSpanningTree(ViewGraph());
  EXPECT_EQ(empty.root, kUndefinedIndex);
  EXPECT_TRUE(empty.bfs_order.empty());

  ViewGraph single;
  single.AddNode(4);
  const SpanningTree tree = MaximumSpanningTree(single);
  EXPECT_EQ(tree.root, 4u);
  EXPECT_EQ(tree.bfs_order, (std::vector<IndexT>{4}));
  EXPECT_TRUE(tree.edges.empty());
}

TEST(MaximumSpanningTree, WeightIsMaximalOnRandomGraphs) {
  // Cycle property, which characterises maximum spanning trees: every valid edge weighs at most
  // as much as each tree edge on the tree path between its endpoints.
  for (uint32_t seed = 1; seed <= 5; ++seed) {
    const ViewGraph graph = testing::RandomGraph(12, 0.6, seed);
    const SpanningTree tree = MaximumSpanningTree(graph);
    ASSERT_EQ(tree.bfs_order.size(), 12u) << "random graph should be connected, seed " << seed;
    EXPECT_EQ(tree.edges.size(), 11u);
    auto path_to_root = [&](IndexT node) {
      std::vector<IndexT> path = {node};
      while (tree.parent.at(node) != node) path.push_back(node = tree.parent.at(node));
      return path;
    };
    graph.ForEachValidEdge([&](const ViewPair& pair, const ViewGraphEdge& edge) {
      // Tree path between the endpoints: up from each to their lowest common ancestor.
      std::vector<IndexT> up_a = path_to_root(pair.first);
      std::vector<IndexT> up_b = path_to_root(pair.second);
      while (up_a.size() > 1 && up_b.size() > 1 && up_a[up_a.size() - 2] == up_b[up_b.size() - 2]) {
        up_a.pop_back();
        up_b.pop_back();
      }
      for (const auto* up : {&up_a, &up_b}) {
        for (size_t k = 0; k + 1 < up->size(); ++k) {
          EXPECT_GE(graph.FindEdge((*up)[k], (*up)[k + 1])->weight, edge.weight);
        }
      }
    });
  }
}

}  // namespace
}  // namespace sfm_pruning
