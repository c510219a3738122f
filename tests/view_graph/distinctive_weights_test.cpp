#include <gtest/gtest.h>

#include "sfm_pruning/view_graph/distinctive_weights.hpp"

namespace sfm_pruning {
namespace {

// Feature 0 of view 0 is matched by three edges (a repeated structure every view sees); the
// others by one each.
ViewGraph StarGraph() {
  ViewGraph graph;
  graph.AddEdge(0, 1, {{0, 0}, {1, 1}}, RelativePose());
  graph.AddEdge(0, 2, {{0, 0}}, RelativePose());
  graph.AddEdge(3, 0, {{5, 0}}, RelativePose());  // stored as (0, 3) with (0, 5)
  return graph;
}

TEST(DistinctiveWeights, AFeatureWeighsTheInverseOfTheEdgesMatchingIt) {
  const FeatureDistinctiveness distinctiveness(StarGraph());
  EXPECT_DOUBLE_EQ(distinctiveness.Weight(0, 0), 1.0 / 3.0);
  EXPECT_DOUBLE_EQ(distinctiveness.Weight(0, 1), 1.0);
  EXPECT_DOUBLE_EQ(distinctiveness.Weight(3, 5), 1.0);
  EXPECT_DOUBLE_EQ(distinctiveness.Weight(7, 7), 1.0);  // never matched: nothing says it repeats
}

TEST(DistinctiveWeights, AnEdgeWeighsTheMeanOfItsTwoFeaturesPerMatch) {
  const ViewGraph graph = StarGraph();
  const std::map<ViewPair, double> weights = DistinctiveMatchWeights(graph, FeatureDistinctiveness(graph));
  ASSERT_EQ(weights.size(), 3u);
  EXPECT_DOUBLE_EQ(weights.at({0, 1}), 0.5 * (1.0 / 3.0 + 1.0) + 1.0);
  EXPECT_DOUBLE_EQ(weights.at({0, 2}), 0.5 * (1.0 / 3.0 + 1.0));
  EXPECT_DOUBLE_EQ(weights.at({0, 3}), 0.5 * (1.0 / 3.0 + 1.0));
}

TEST(DistinctiveWeights, InvalidEdgesNeitherCountNorWeigh) {
  ViewGraph graph = StarGraph();
  graph.InvalidateEdge(0, 2, {EdgeInvalidReason::kOther, 0.0, 0.0});
  const FeatureDistinctiveness distinctiveness(graph);
  EXPECT_DOUBLE_EQ(distinctiveness.Weight(0, 0), 0.5);
  const std::map<ViewPair, double> weights = DistinctiveMatchWeights(graph, distinctiveness);
  EXPECT_EQ(weights.count({0, 2}), 0u);
  EXPECT_DOUBLE_EQ(weights.at({0, 1}), 0.5 * (0.5 + 1.0) + 1.0);
}

TEST(DistinctiveWeights, UniqueTextureOutweighsARepeatedFacade) {
  // Views 0 and 1 stand at one place; views 2, 3, 4 each stand before another copy of the same
  // facade. Every view matches the facade features (10 .. 29) of every other; only 0 and 1 also
  // share ground features (0 .. 4). By inliers the true edge 0-1 (25) barely beats the twin edge
  // 0-2 (20); by distinctiveness it weighs twice as much.
  ViewGraph graph;
  std::vector<FeatureMatch> facade;
  for (IndexT f = 10; f < 30; ++f) facade.push_back({f, f});
  for (IndexT a = 0; a < 5; ++a) {
    for (IndexT b = a + 1; b < 5; ++b) {
      std::vector<FeatureMatch> matches = facade;
      if (a == 0 && b == 1) {
        for (IndexT f = 0; f < 5; ++f) matches.push_back({f, f});
      }
      graph.AddEdge(a, b, matches, RelativePose());
    }
  }
  const std::map<ViewPair, double> weights = DistinctiveMatchWeights(graph, FeatureDistinctiveness(graph));
  EXPECT_DOUBLE_EQ(weights.at({0, 2}), 20.0 * 0.25);  // a facade feature is matched by 4 edges
  EXPECT_DOUBLE_EQ(weights.at({0, 1}), 20.0 * 0.25 + 5.0);
  EXPECT_DOUBLE_EQ(weights.at({0, 1}) / weights.at({0, 2}), 2.0);
}

}  // namespace
}  // namespace sfm_pruning
