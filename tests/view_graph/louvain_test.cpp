#include "sfm_pruning/view_graph/louvain.hpp"

#include <gtest/gtest.h>

#include <stdexcept>
#include <thread>

#include "sfm_pruning/view_graph/modularity.hpp"
#include "view_graph/graph_builders.hpp"

namespace sfm_pruning {
namespace {

using testing::AddWeightedEdge;

// Two 5-cliques {0..4} and {5..9}, every clique edge weighing 10 inliers, joined by the
// weight-1 bridge (4, 5).
ViewGraph TwoCliquesWithBridge() {
  ViewGraph graph;
  testing::AddClique(&graph, {0, 1, 2, 3, 4}, 10);
  testing::AddClique(&graph, {5, 6, 7, 8, 9}, 10);
  AddWeightedEdge(&graph, 4, 5, 1);
  return graph;
}

TEST(Louvain, SplitsTwoCliquesAtTheBridge) {
  const ViewGraph graph = TwoCliquesWithBridge();
  const LouvainResult result = DetectCommunitiesLouvain(graph);
  const std::vector<NodeGroup> expected = {{0, 1, 2, 3, 4}, {5, 6, 7, 8, 9}};
  EXPECT_EQ(result.communities, expected);
  // Level 1 gathers each clique; merging the two super-nodes would lower Q, so igraph stops.
  EXPECT_EQ(result.num_levels, 1);

  // Hand computation, Q = sum_c [ L_c / m - (D_c / 2m)^2 ]:
  //   m   = 2 cliques * 10 edges * 10 + 1 (bridge) = 201
  //   L_c = 10 edges * 10 = 100 inside each clique
  //   D_c = 2 * 100 (both ends of each inner edge) + 1 (the bridge end) = 201
  //   Q   = 2 * [ 100/201 - (201/402)^2 ] = 200/201 - 1/2 = 0.4950248756...
  const double hand_q = 200.0 / 201.0 - 0.5;
  EXPECT_NEAR(hand_q, 0.4950248756, 1e-10);
  EXPECT_NEAR(result.modularity, hand_q, 1e-12);
  EXPECT_NEAR(ComputeModularity(graph, expected), hand_q, 1e-12);
  // One community: L = m, D = 2m, Q = 1 - 1 = 0.
  EXPECT_NEAR(ComputeModularity(graph, {{0, 1, 2, 3, 4, 5, 6, 7, 8, 9}}), 0.0, 1e-12);
}

TEST(Louvain, ModularityAgreesWithIgraphOnRandomGraphs) {
  for (uint32_t seed = 1; seed <= 8; ++seed) {
    const ViewGraph graph = testing::RandomGraph(40, 0.12, seed);
    for (double resolution : {1.0, 0.5, 2.0}) {
      SCOPED_TRACE(::testing::Message() << "seed " << seed << " resolution " << resolution);
      LouvainOptions options;
      options.resolution = resolution;
      options.seed = seed;
      const LouvainResult result = DetectCommunitiesLouvain(graph, options);
      size_t total = 0;
      for (const NodeGroup& community : result.communities) total += community.size();
      EXPECT_EQ(total, graph.NumNodes());
      EXPECT_GT(result.communities.size(), 1u);
      EXPECT_NEAR(result.modularity, ComputeModularity(graph, result.communities, resolution), 1e-9);
    }
  }
}

TEST(Louvain, SameSeedSameCommunities) {
  const ViewGraph graph = testing::RandomGraph(60, 0.1, 42);
  LouvainOptions options;
  options.seed = 7;
  const LouvainResult first = DetectCommunitiesLouvain(graph, options);
  LouvainOptions other = options;
  other.seed = 8;
  DetectCommunitiesLouvain(graph, other);  // moves igraph's global RNG in between
  const LouvainResult second = DetectCommunitiesLouvain(graph, options);
  EXPECT_EQ(first.communities, second.communities);
  EXPECT_EQ(first.modularity, second.modularity);
  EXPECT_EQ(first.num_levels, second.num_levels);
}

TEST(Louvain, ConcurrentCallsGiveTheSequentialResults) {
  // igraph's RNG is process-wide: the mutex + re-seed must keep parallel callers independent.
  const ViewGraph graph = testing::RandomGraph(60, 0.1, 9);
  std::vector<LouvainResult> sequential;
  for (uint64_t seed = 0; seed < 4; ++seed)
    sequential.push_back(DetectCommunitiesLouvain(graph, {1.0, seed}));
  std::vector<LouvainResult> parallel(4);
  std::vector<std::thread> threads;
  for (uint64_t seed = 0; seed < 4; ++seed) {
    threads.emplace_back([&, seed] {
      for (int repeat = 0; repeat < 5; ++repeat)
        parallel[seed] = DetectCommunitiesLouvain(graph, {1.0, seed});
    });
  }
  for (std::thread& thread : threads) thread.join();
  for (size_t k = 0; k < 4; ++k) {
    EXPECT_EQ(parallel[k].communities, sequential[k].communities);
    EXPECT_EQ(parallel[k].modularity, sequential[k].modularity);
  }
}

TEST(Louvain, DegenerateGraphs) {
  const LouvainResult empty = DetectCommunitiesLouvain(ViewGraph());
  EXPECT_TRUE(empty.communities.empty());
  EXPECT_EQ(empty.num_levels, 0);

  ViewGraph single;
  single.AddNode(3);
  EXPECT_EQ(DetectCommunitiesLouvain(single).communities, (std::vector<NodeGroup>{{3}}));

  // No valid edge: every node alone, modularity 0 by convention.
  ViewGraph no_edges;
  AddWeightedEdge(&no_edges, 2, 5, 30);
  no_edges.InvalidateEdge(2, 5, {EdgeInvalidReason::kTooFewInliers, 30, 31});
  no_edges.AddNode(1);
  const LouvainResult isolated = DetectCommunitiesLouvain(no_edges);
  EXPECT_EQ(isolated.communities, (std::vector<NodeGroup>{{1}, {2}, {5}}));
  EXPECT_EQ(isolated.modularity, 0.0);
  EXPECT_EQ(ComputeModularity(no_edges, isolated.communities), 0.0);
}

TEST(Louvain, DisconnectedTriangles) {
  ViewGraph graph;
  testing::AddClique(&graph, {3, 4, 5}, 1);
  testing::AddClique(&graph, {0, 1, 2}, 1);
  const LouvainResult result = DetectCommunitiesLouvain(graph);
  EXPECT_EQ(result.communities, (std::vector<NodeGroup>{{0, 1, 2}, {3, 4, 5}}));
  // m = 6, L_c = 3, D_c = 6: Q = 2 * (3/6 - (6/12)^2) = 0.5.
  EXPECT_NEAR(result.modularity, 0.5, 1e-12);
}

TEST(Louvain, RejectsNegativeWeights) {
  ViewGraph graph = TwoCliquesWithBridge();
  graph.MutableEdge(0, 1)->weight = -3;
  EXPECT_THROW(DetectCommunitiesLouvain(graph), std::invalid_argument);
}

TEST(Modularity, RejectsPartitionsThatAreNotPartitions) {
  const ViewGraph graph = TwoCliquesWithBridge();
  EXPECT_THROW(ComputeModularity(graph, {{0, 1, 2, 3, 4}}), std::invalid_argument);  // misses 5..9
  EXPECT_THROW(ComputeModularity(graph, {{0, 1, 2, 3, 4}, {4, 5, 6, 7, 8, 9}}), std::invalid_argument);
  EXPECT_THROW(ComputeModularity(graph, {{0, 1, 2, 3, 4}, {5, 6, 7, 8, 9, 10}}), std::invalid_argument);
}

}  // namespace
}  // namespace sfm_pruning
