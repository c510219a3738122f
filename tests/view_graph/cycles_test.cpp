#include "sfm_pruning/view_graph/cycles.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <set>
#include <stdexcept>

#include "view_graph/graph_builders.hpp"

namespace sfm_pruning {
namespace {

using testing::AddWeightedEdge;

// The loop first -> first + 1 -> ... -> first + num_nodes - 1 -> first.
void AddRing(ViewGraph* graph, IndexT first, IndexT num_nodes) {
  for (IndexT k = 0; k < num_nodes; ++k) AddWeightedEdge(graph, first + k, first + (k + 1) % num_nodes, 1);
}

ViewGraph Ring(IndexT num_nodes) {
  ViewGraph graph;
  AddRing(&graph, 0, num_nodes);
  return graph;
}

// True when the loop walks the edge {a, b} (in either direction).
bool LoopUsesEdge(const ViewCycle& cycle, IndexT a, IndexT b) {
  for (size_t k = 0; k < cycle.size(); ++k) {
    if (MakeViewPair(cycle[k], cycle[(k + 1) % cycle.size()]) == MakeViewPair(a, b)) return true;
  }
  return false;
}

// Every loop is a closed walk of distinct views over valid edges, in canonical form.
void ExpectWellFormed(const ViewGraph& graph, const std::vector<ViewCycle>& cycles, size_t max_length) {
  std::set<ViewCycle> distinct(cycles.begin(), cycles.end());
  EXPECT_EQ(distinct.size(), cycles.size());
  for (const ViewCycle& cycle : cycles) {
    ASSERT_GE(cycle.size(), 3u);
    EXPECT_LE(cycle.size(), max_length);
    EXPECT_EQ(std::set<IndexT>(cycle.begin(), cycle.end()).size(), cycle.size());
    EXPECT_EQ(*std::min_element(cycle.begin(), cycle.end()), cycle.front());
    EXPECT_LT(cycle[1], cycle.back());
    for (size_t k = 0; k < cycle.size(); ++k) {
      EXPECT_TRUE(graph.HasValidEdge(cycle[k], cycle[(k + 1) % cycle.size()]));
    }
  }
}

TEST(Cycles, TrianglesOfK4) {
  ViewGraph graph;
  testing::AddClique(&graph, {0, 1, 2, 3}, 1);
  const std::vector<ViewCycle> expected = {{0, 1, 2}, {0, 1, 3}, {0, 2, 3}, {1, 2, 3}};
  CycleSearchOptions triangles_only;
  triangles_only.include_shortest_alternatives = false;
  const CycleSearchResult triangles = FindBoundedCycles(graph, triangles_only);
  EXPECT_EQ(triangles.cycles, expected);
  EXPECT_EQ(triangles.num_triangles, 4u);
  // Every edge's shortest detour is a triangle already listed: nothing new.
  const CycleSearchResult all = FindBoundedCycles(graph);
  EXPECT_EQ(all.cycles, expected);
  EXPECT_FALSE(all.truncated);
}

TEST(Cycles, RingOfSixIsOneSixCycle) {
  const ViewGraph ring = Ring(6);
  const CycleSearchResult result = FindBoundedCycles(ring);
  EXPECT_EQ(result.cycles, (std::vector<ViewCycle>{{0, 1, 2, 3, 4, 5}}));
  EXPECT_EQ(result.num_triangles, 0u);

  CycleSearchOptions short_loops;
  short_loops.max_cycle_length = 5;
  EXPECT_TRUE(FindBoundedCycles(ring, short_loops).cycles.empty());
  // Eight cameras exceed the paper's bound of fewer than 8.
  EXPECT_TRUE(FindBoundedCycles(Ring(8)).cycles.empty());
  EXPECT_EQ(FindBoundedCycles(Ring(7)).cycles.size(), 1u);
}

TEST(Cycles, InvalidEdgesAndBridgesCloseNoLoop) {
  ViewGraph graph = Ring(6);
  AddWeightedEdge(&graph, 0, 3, 1);  // chord: loops {0,1,2,3} and {0,3,4,5}
  AddWeightedEdge(&graph, 5, 9, 1);  // bridge to a pendant view
  const CycleSearchResult result = FindBoundedCycles(graph);
  EXPECT_EQ(result.cycles, (std::vector<ViewCycle>{{0, 1, 2, 3}, {0, 3, 4, 5}}));
  graph.InvalidateEdge(0, 3, {EdgeInvalidReason::kOther, 0, 0});
  EXPECT_EQ(FindBoundedCycles(graph).cycles, (std::vector<ViewCycle>{{0, 1, 2, 3, 4, 5}}));
}

TEST(Cycles, LengthsBoundedOnRandomGraphs) {
  for (uint32_t seed = 1; seed <= 5; ++seed) {
    const ViewGraph graph = testing::RandomGraph(30, 0.08, seed);
    for (size_t max_length : {3u, 4u, 7u}) {
      CycleSearchOptions options;
      options.max_cycle_length = max_length;
      const CycleSearchResult result = FindBoundedCycles(graph, options);
      ExpectWellFormed(graph, result.cycles, max_length);
      EXPECT_FALSE(result.truncated);
      EXPECT_EQ(FindBoundedCycles(graph, options).cycles, result.cycles);  // deterministic
    }
  }
}

TEST(Cycles, CapIsRespected) {
  const ViewGraph dense = testing::RandomGraph(20, 0.7, 3);
  CycleSearchOptions options;
  options.max_num_cycles = 25;
  const CycleSearchResult capped = FindBoundedCycles(dense, options);
  EXPECT_EQ(capped.cycles.size(), 25u);
  EXPECT_TRUE(capped.truncated);
  // The capped list is a prefix of the full one: the search order does not depend on the cap.
  const CycleSearchResult full = FindBoundedCycles(dense);
  ASSERT_GT(full.cycles.size(), 25u);
  EXPECT_TRUE(std::equal(capped.cycles.begin(), capped.cycles.end(), full.cycles.begin()));
}

TEST(Cycles, EveryEdgeOnAShortLoopIsTestedBeforeTrianglesFillTheCap) {
  // K8 on 0..7 (28 edges, 56 triangles) and a 5-ring on 10..14: 33 edges, cap 40 < 56.
  ViewGraph graph;
  testing::AddClique(&graph, {0, 1, 2, 3, 4, 5, 6, 7}, 1);
  AddRing(&graph, 10, 5);
  CycleSearchOptions options;
  options.max_num_cycles = 40;
  const CycleSearchResult result = FindBoundedCycles(graph, options);
  EXPECT_EQ(result.cycles.size(), 40u);
  EXPECT_TRUE(result.truncated);
  EXPECT_EQ(result.num_triangles, 39u);
  EXPECT_NE(std::find(result.cycles.begin(), result.cycles.end(), ViewCycle{10, 11, 12, 13, 14}),
            result.cycles.end());
  for (const ViewPair& pair : graph.ValidEdgePairs()) {
    bool covered = false;
    for (const ViewCycle& cycle : result.cycles) covered |= LoopUsesEdge(cycle, pair.first, pair.second);
    EXPECT_TRUE(covered) << pair.first << "-" << pair.second;
  }
}

TEST(LoopRotationError, ZeroForConsistentRelativePoses) {
  const std::map<IndexT, Pose> poses = testing::RandomPoses(8, 21);
  ViewGraph graph;
  testing::AddEdgesFromPoses(&graph, poses, testing::AllPairs(8));
  const CycleSearchResult result = FindBoundedCycles(graph);
  ASSERT_EQ(result.num_triangles, 56u);  // C(8, 3)
  for (const ViewCycle& cycle : result.cycles) EXPECT_LT(LoopRotationErrorDeg(graph, cycle), 1e-5);
  EXPECT_LT(LoopRotationErrorDeg(graph, {7, 2, 5, 0, 3, 1, 6}), 1e-5);
}

TEST(LoopRotationError, EqualsAPlantedEdgeError) {
  const std::map<IndexT, Pose> poses = testing::RandomPoses(7, 4);
  ViewGraph graph;
  testing::AddEdgesFromPoses(&graph, poses, testing::AllPairs(7));
  // Corrupt edge (2, 3) by 7° about an arbitrary axis.
  const Eigen::Matrix3d error =
      Eigen::AngleAxisd(DegToRad(7.0), Eigen::Vector3d(1, -2, 0.5).normalized()).toRotationMatrix();
  RelativePose& corrupted = graph.MutableEdge(2, 3)->relative_pose;
  corrupted.rotation = error * corrupted.rotation;

  // The composed loop rotation is a conjugate of the error (the other edges are exact), and
  // conjugation keeps the angle: every loop through the edge shows 7°, the others 0°.
  std::vector<ViewCycle> loops = FindBoundedCycles(graph).cycles;
  ASSERT_EQ(loops.size(), 35u);  // K7: C(7, 3) triangles, every detour is a triangle
  loops.push_back({0, 1, 2, 3});
  loops.push_back({5, 3, 2, 6, 4, 1, 0});  // 7 views, walks the edge from 3 to 2
  loops.push_back({0, 1, 4, 5, 6});
  size_t through = 0;
  for (const ViewCycle& cycle : loops) {
    const bool uses_edge = LoopUsesEdge(cycle, 2, 3);
    SCOPED_TRACE(::testing::Message() << "loop of " << cycle.size() << " views, uses (2,3): " << uses_edge);
    EXPECT_NEAR(LoopRotationErrorDeg(graph, cycle), uses_edge ? 7.0 : 0.0, 1e-5);
    through += uses_edge ? 1 : 0;
  }
  EXPECT_EQ(through, 5u + 2u);  // triangles {2,3,x} for the 5 other views, two longer loops
  graph.RemoveNodes({6});
  EXPECT_THROW(LoopRotationErrorDeg(graph, {0, 6, 3}), std::out_of_range);
  EXPECT_THROW(LoopRotationErrorDeg(graph, {0}), std::invalid_argument);
}

TEST(LoopRotationError, PaperThreshold) {
  // 5° * floor((l - 1) / 2).
  EXPECT_DOUBLE_EQ(LoopRotationThresholdDeg(3), 5.0);
  EXPECT_DOUBLE_EQ(LoopRotationThresholdDeg(4), 5.0);
  EXPECT_DOUBLE_EQ(LoopRotationThresholdDeg(5), 10.0);
  EXPECT_DOUBLE_EQ(LoopRotationThresholdDeg(6), 10.0);
  EXPECT_DOUBLE_EQ(LoopRotationThresholdDeg(7), 15.0);
  EXPECT_DOUBLE_EQ(LoopRotationThresholdDeg(7, 2.0), 6.0);
}

}  // namespace
}  // namespace sfm_pruning
