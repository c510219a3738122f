#include <algorithm>
#include <cmath>
#include <numeric>
#include <random>
#include <stdexcept>
#include <vector>

#include <Eigen/Geometry>
#include <gtest/gtest.h>

#include "sfm_pruning/pruning/capture_order.hpp"
#include "sfm_pruning/sfm/pose.hpp"

namespace sfm_pruning {
namespace {

constexpr double kStepDeg = 6.0;  // turn between consecutive views of the orbits below

// A view graph of `num_views` views taken along an orbit (view k turned by k * kStepDeg about z),
// with an edge between the path positions a and b whenever keep(a, b); the view at path position
// k gets the id ids[k].
template <typename Keep>
ViewGraph OrbitGraph(const std::vector<IndexT>& ids, Keep keep) {
  ViewGraph graph;
  for (const IndexT id : ids) graph.AddNode(id);
  for (size_t a = 0; a < ids.size(); ++a) {
    for (size_t b = a + 1; b < ids.size(); ++b) {
      if (!keep(a, b)) continue;
      const double angle = DegToRad(kStepDeg * static_cast<double>(b - a));
      const RelativePose pose(Eigen::AngleAxisd(angle, Eigen::Vector3d::UnitZ()).toRotationMatrix(),
                              Eigen::Vector3d::UnitX());
      graph.AddEdge(ids[a], ids[b], {}, pose);
    }
  }
  return graph;
}

std::vector<IndexT> InOrder(size_t n) {
  std::vector<IndexT> ids(n);
  std::iota(ids.begin(), ids.end(), IndexT{0});
  return ids;
}

std::vector<IndexT> Shuffled(size_t n, uint32_t seed) {
  std::vector<IndexT> ids = InOrder(n);
  std::shuffle(ids.begin(), ids.end(), std::mt19937(seed));
  return ids;
}

// Neighbours up to three places apart on the path, and every seventh pair besides (a sparse
// graph, as from sequential plus retrieval matching).
bool SparseKeep(size_t a, size_t b) { return b - a <= 3 || (a * 31 + b * 17) % 7 == 0; }
bool EveryPair(size_t, size_t) { return true; }

TEST(CaptureOrder, ConsecutiveViewsVerifiedFarMoreOftenThanOtherPairsShowTheOrder) {
  const CaptureOrderEvidence evidence = MeasureCaptureOrder(OrbitGraph(InOrder(40), SparseKeep));
  EXPECT_EQ(evidence.num_views, 40u);
  EXPECT_DOUBLE_EQ(evidence.consecutive_edge_share, 1.0);
  EXPECT_LT(evidence.edge_density, 0.3);
  EXPECT_TRUE(evidence.by_edges);
  EXPECT_TRUE(evidence.informative);
}

TEST(CaptureOrder, ShuffledIdsShowNoOrder) {
  for (uint32_t seed = 0; seed < 5; ++seed) {
    const CaptureOrderEvidence sparse = MeasureCaptureOrder(OrbitGraph(Shuffled(40, seed), SparseKeep));
    EXPECT_FALSE(sparse.informative) << "seed " << seed << ": share " << sparse.consecutive_edge_share;
    const CaptureOrderEvidence dense = MeasureCaptureOrder(OrbitGraph(Shuffled(40, seed), EveryPair));
    EXPECT_FALSE(dense.informative) << "seed " << seed << ": rotation ratio " << dense.consecutive_rotation_ratio;
  }
}

TEST(CaptureOrder, InADenseGraphTheOrderShowsInTheRotations) {
  // Every pair verified: the edges say nothing, but consecutive views turn by one step while the
  // median pair of 40 views turns by about twelve steps.
  const CaptureOrderEvidence evidence = MeasureCaptureOrder(OrbitGraph(InOrder(40), EveryPair));
  EXPECT_DOUBLE_EQ(evidence.edge_density, 1.0);
  EXPECT_FALSE(evidence.by_edges);
  EXPECT_NEAR(evidence.consecutive_rotation_ratio, 1.0 / 12.0, 0.02);
  EXPECT_TRUE(evidence.by_rotations);
  EXPECT_TRUE(evidence.informative);
}

TEST(CaptureOrder, AFewViewsSayNothing) {
  EXPECT_FALSE(MeasureCaptureOrder(OrbitGraph(InOrder(6), EveryPair)).informative);
  EXPECT_FALSE(MeasureCaptureOrder(ViewGraph()).informative);
}

TEST(CaptureOrder, NeighboursAreCountedInIdOrderWithinTheWindow) {
  // Ids with gaps (a database's image ids after some images were dropped): places, not ids, count.
  std::vector<IndexT> ids;
  for (IndexT k = 0; k < 40; ++k) ids.push_back(k < 20 ? 2 * k : 2 * k + 100);
  const ViewGraph graph = OrbitGraph(ids, SparseKeep);
  const CaptureOrder order(CaptureOrderOptions(), graph);
  ASSERT_TRUE(order.Used());
  EXPECT_TRUE(order.AreNeighbours(10, 12));
  EXPECT_TRUE(order.AreNeighbours(12, 8));
  EXPECT_FALSE(order.AreNeighbours(10, 16));   // three places apart
  EXPECT_TRUE(order.AreNeighbours(38, 140));   // consecutive places across the gap in the ids
  EXPECT_FALSE(order.AreNeighbours(10, 10));
  EXPECT_FALSE(order.AreNeighbours(10, 11));   // not in the graph
  EXPECT_DOUBLE_EQ(order.PartitionWeightFactor(), 10.0);
}

TEST(CaptureOrder, ThePathGraphKeepsTheEdgesWithinItsWindowInPlaces) {
  std::vector<IndexT> ids;
  for (IndexT k = 0; k < 40; ++k) ids.push_back(k < 20 ? 2 * k : 2 * k + 100);
  ViewGraph graph = OrbitGraph(ids, SparseKeep);
  graph.MutableEdge(10, 12)->is_valid = false;  // an invalid edge stays out
  const CaptureOrder order(CaptureOrderOptions(), graph);
  const ViewGraph path = order.PathGraph(graph, 3);
  EXPECT_EQ(path.NumNodes(), graph.NumNodes());
  size_t expected = 0;
  graph.ForEachValidEdge([&](const ViewPair& pair, const ViewGraphEdge&) {
    const size_t apart = order.PlacesApart(pair.first, pair.second);
    if (apart <= 3) ++expected;
    EXPECT_EQ(path.HasValidEdge(pair.first, pair.second), apart <= 3) << pair.first << "-" << pair.second;
  });
  EXPECT_EQ(path.NumValidEdges(), expected);
  EXPECT_TRUE(path.HasValidEdge(38, 140));  // consecutive places across the gap in the ids
  EXPECT_FALSE(path.HasValidEdge(10, 12));

  CaptureOrderOptions unordered;
  unordered.use = CaptureOrderOptions::Use::kUnordered;
  EXPECT_EQ(CaptureOrder(unordered, graph).PathGraph(graph, 3).NumValidEdges(), 0u);
}

TEST(CaptureOrder, TheUserCanOverrideTheEvidence) {
  const ViewGraph ordered = OrbitGraph(InOrder(40), SparseKeep);
  const ViewGraph shuffled = OrbitGraph(Shuffled(40, 3), SparseKeep);
  CaptureOrderOptions options;
  options.use = CaptureOrderOptions::Use::kUnordered;
  const CaptureOrder off(options, ordered);
  EXPECT_FALSE(off.Used());
  EXPECT_TRUE(off.Evidence().informative);  // measured and reported all the same
  EXPECT_FALSE(off.AreNeighbours(0, 1));
  options.use = CaptureOrderOptions::Use::kSequential;
  options.neighbour_window_views = 1;
  const CaptureOrder on(options, shuffled);
  EXPECT_TRUE(on.Used());
  EXPECT_FALSE(on.Evidence().informative);
  EXPECT_TRUE(on.AreNeighbours(4, 5));
  EXPECT_FALSE(on.AreNeighbours(4, 6));
  EXPECT_FALSE(CaptureOrder().Used());
}

TEST(CaptureOrder, CheckRejectsOutOfRangeOptions) {
  EXPECT_NO_THROW(CaptureOrderOptions().Check());
  CaptureOrderOptions options;
  options.neighbour_window_views = 0;
  EXPECT_THROW(options.Check(), std::invalid_argument);
  options = CaptureOrderOptions();
  options.partition_weight_factor = 0.5;
  EXPECT_THROW(options.Check(), std::invalid_argument);
  options.partition_weight_factor = std::nan("");
  EXPECT_THROW(options.Check(), std::invalid_argument);
  options = CaptureOrderOptions();
  options.path_window_views = 0;
  EXPECT_THROW(options.Check(), std::invalid_argument);
  options = CaptureOrderOptions();
  options.path_max_deviation_deg = 200.0;
  EXPECT_THROW(options.Check(), std::invalid_argument);
  options.path_max_deviation_deg = 0.0;  // off
  EXPECT_NO_THROW(options.Check());
  options = CaptureOrderOptions();
  options.path_max_direction_deviation_deg = -1.0;
  EXPECT_THROW(options.Check(), std::invalid_argument);
  options.path_max_direction_deviation_deg = std::nan("");
  EXPECT_THROW(options.Check(), std::invalid_argument);
  options.path_max_direction_deviation_deg = 0.0;  // off
  EXPECT_NO_THROW(options.Check());
  options = CaptureOrderOptions();
  options.partition_weight_factor = std::nan("");
  EXPECT_THROW(CaptureOrder(options, ViewGraph()), std::invalid_argument);
  EXPECT_STREQ(CaptureOrderUseName(CaptureOrderOptions::Use::kSequential), "sequential");
}

}  // namespace
}  // namespace sfm_pruning
