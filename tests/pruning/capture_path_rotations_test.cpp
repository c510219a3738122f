#include <cmath>
#include <set>
#include <vector>

#include <Eigen/Geometry>
#include <gtest/gtest.h>

#include "sfm_pruning/pruning/capture_order.hpp"
#include "sfm_pruning/pruning/capture_path_rotations.hpp"
#include "sfm_pruning/sfm/pose.hpp"

namespace sfm_pruning {
namespace {

constexpr size_t kViews = 48;
constexpr double kStepDeg = 7.5;  // a full orbit

Eigen::Matrix3d TurnDeg(double deg, const Eigen::Vector3d& axis) {
  return Eigen::AngleAxisd(DegToRad(deg), axis.normalized()).toRotationMatrix();
}

// A dense orbit round an object whose four sides print alike: every pair verified; a pair whose
// views are at least `min_twin_gap` places apart and whose (a + b) is odd matched the copy a
// quarter turn on, so its rotation is off by 90 degrees; true rotations carry a small
// deterministic error (up to about 0.5 degrees). `twin_neighbour` also makes the pair (20, 21) a
// twin: one neighbour pair must be outvoted by the others. The twin pairs go to *twins.
ViewGraph FoldedOrbit(size_t min_twin_gap, bool twin_neighbour, std::set<ViewPair>* twins) {
  ViewGraph graph;
  for (IndexT id = 0; id < kViews; ++id) graph.AddNode(id);
  for (IndexT a = 0; a < kViews; ++a) {
    for (IndexT b = a + 1; b < kViews; ++b) {
      const Eigen::Matrix3d truth = TurnDeg(kStepDeg * static_cast<double>(b - a), Eigen::Vector3d::UnitZ());
      const Eigen::Matrix3d error = TurnDeg(0.5 * std::sin(static_cast<double>(a * 7 + b * 3)), Eigen::Vector3d(1, 2, 0));
      const bool twin = (b - a >= min_twin_gap && (a + b) % 2 == 1) || (twin_neighbour && a == 20 && b == 21);
      const Eigen::Matrix3d rotation = twin ? TurnDeg(90.0, Eigen::Vector3d::UnitZ()) * truth : error * truth;
      if (twin) twins->insert(MakeViewPair(a, b));
      graph.AddEdge(a, b, {}, RelativePose(rotation, Eigen::Vector3d::UnitX())).weight = 100.0;
    }
  }
  return graph;
}

CaptureOrderOptions Sequential() {
  CaptureOrderOptions options;
  options.use = CaptureOrderOptions::Use::kSequential;
  return options;
}

TEST(CapturePathRotations, PairsTurnedByTheSymmetryAreRemovedAndTruePairsKept) {
  std::set<ViewPair> twins;
  const ViewGraph graph = FoldedOrbit(6, /*twin_neighbour=*/true, &twins);
  const CaptureOrderOptions options = Sequential();
  const CapturePathRotationCheck check = CheckAgainstCapturePath(options, CaptureOrder(options, graph), graph);
  ASSERT_TRUE(check.applied);
  EXPECT_EQ(check.num_path_views, kViews);
  EXPECT_EQ(check.num_path_pieces, 1u);
  EXPECT_EQ(check.num_path_edges, kViews * 3 - 6);  // 47 + 46 + 45
  EXPECT_LT(check.path_residual_deg, 1.0);
  std::set<ViewPair> removed;
  for (const CapturePathDeviation& deviation : check.removed) {
    removed.insert(deviation.pair);
    EXPECT_NEAR(deviation.deviation_deg, 90.0, 5.0);
    EXPECT_GE(deviation.bound_deg, options.path_max_deviation_deg);
  }
  EXPECT_EQ(removed, twins);  // the neighbour twin (20, 21) too: its neighbours outvote it
}

TEST(CapturePathRotations, EachPieceOfABrokenPathIsJudgedInItsOwnFrame) {
  std::set<ViewPair> twins;
  ViewGraph graph = FoldedOrbit(6, false, &twins);
  // No pair within the window across the place between views 23 and 24: two pieces of 24 views.
  for (IndexT a = 21; a <= 23; ++a) {
    for (IndexT b = 24; b <= a + 3; ++b) graph.InvalidateEdge(a, b, {EdgeInvalidReason::kOther, 0.0, 0.0});
  }
  const CaptureOrderOptions options = Sequential();
  const CapturePathRotationCheck check = CheckAgainstCapturePath(options, CaptureOrder(options, graph), graph);
  ASSERT_TRUE(check.applied);
  EXPECT_EQ(check.num_path_pieces, 2u);
  EXPECT_EQ(check.num_path_views, kViews);
  std::set<ViewPair> within_pieces;
  for (const ViewPair& twin : twins) {
    if ((twin.first < 24) == (twin.second < 24)) within_pieces.insert(twin);
  }
  std::set<ViewPair> removed;
  for (const CapturePathDeviation& deviation : check.removed) removed.insert(deviation.pair);
  EXPECT_EQ(removed, within_pieces);  // the twins across the break have no common frame: not judged
}

TEST(CapturePathRotations, NothingIsJudgedWithoutTheOrderOrWhenOff) {
  std::set<ViewPair> twins;
  const ViewGraph graph = FoldedOrbit(6, false, &twins);
  CaptureOrderOptions unordered;
  unordered.use = CaptureOrderOptions::Use::kUnordered;
  EXPECT_FALSE(CheckAgainstCapturePath(unordered, CaptureOrder(unordered, graph), graph).applied);
  CaptureOrderOptions off = Sequential();
  off.path_max_deviation_deg = 0.0;
  const CapturePathRotationCheck check = CheckAgainstCapturePath(off, CaptureOrder(off, graph), graph);
  EXPECT_FALSE(check.applied);
  EXPECT_TRUE(check.removed.empty());
}

TEST(CapturePathRotations, TheBoundGrowsWithTheDriftOverThePlacesApart) {
  std::set<ViewPair> twins;
  const ViewGraph graph = FoldedOrbit(6, false, &twins);
  CaptureOrderOptions options = Sequential();
  options.path_max_deviation_deg = 1.0;  // below the drift: the drift term decides
  const CapturePathRotationCheck check = CheckAgainstCapturePath(options, CaptureOrder(options, graph), graph);
  ASSERT_TRUE(check.applied);
  for (const CapturePathDeviation& deviation : check.removed) {
    const double drift = 3.0 * check.path_residual_deg * std::sqrt(static_cast<double>(deviation.places_apart));
    EXPECT_NEAR(deviation.bound_deg, std::max(1.0, drift), 1e-12);
  }
}

}  // namespace
}  // namespace sfm_pruning
