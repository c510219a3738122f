// Unverified subgraph pairs judged against a rotation averaging of the rest of the graph
// (unverified_pair_rotations.hpp), on exact rotations: a ring of cameras looking outward, as on a
// loop of streets, where a false loop closure between the two sides turns by 180°.
#include <gtest/gtest.h>

#include <cmath>

#include "sfm_pruning/geometry/so3.hpp"
#include "sfm_pruning/pruning/unverified_pair_rotations.hpp"

namespace sfm_pruning {
namespace {

constexpr int kNumViews = 16;

// World-to-camera rotation of view i: heading 360°·i/16 about the vertical, with a small tilt.
Eigen::Matrix3d RotationOfView(int i) {
  const double heading = 2.0 * M_PI * i / kNumViews;
  return ExpSO3(Eigen::Vector3d(0.05, 0.0, 0.0)) * ExpSO3(Eigen::Vector3d(0.0, heading, 0.0));
}

void AddEdge(ViewGraph* graph, int i, int j, const Eigen::Matrix3d& relative_rotation) {
  ViewGraphEdge edge;
  edge.relative_pose.rotation = relative_rotation;
  edge.relative_pose.translation = Eigen::Vector3d::UnitX();
  edge.weight = 100.0;
  graph->AddEdge({static_cast<IndexT>(i), static_cast<IndexT>(j)}, edge);
}

// The ring (i, i+1) and (i, i+2): every view's rotation is known without the extra pairs.
ViewGraph RingGraph() {
  ViewGraph graph;
  for (int i = 0; i < kNumViews; ++i) graph.AddNode(static_cast<IndexT>(i));
  for (int i = 0; i < kNumViews; ++i) {
    for (const int step : {1, 2}) {
      const int a = std::min(i, (i + step) % kNumViews);
      const int b = std::max(i, (i + step) % kNumViews);
      AddEdge(&graph, a, b, RotationOfView(b) * RotationOfView(a).transpose());
    }
  }
  return graph;
}

TEST(UnverifiedPairRotations, AFalseLoopAcrossTheRingTurnsByHalfATurnAndATrueOneByNothing) {
  ViewGraph graph = RingGraph();
  // A true loop closure (0, 8) and (1, 9) with the right rotations; a false one (4, 12) and (5, 13)
  // that takes the other side for this one (the relative rotation of a view with itself).
  AddEdge(&graph, 0, 8, RotationOfView(8) * RotationOfView(0).transpose());
  AddEdge(&graph, 1, 9, RotationOfView(9) * RotationOfView(1).transpose());
  AddEdge(&graph, 4, 12, Eigen::Matrix3d::Identity());
  AddEdge(&graph, 5, 13, Eigen::Matrix3d::Identity());
  const std::vector<std::vector<ViewPair>> groups{{{0, 8}, {1, 9}}, {{4, 12}, {5, 13}}};

  const std::vector<double> errors = MedianRotationErrorsAgainstTheRest(graph, groups, {});

  ASSERT_EQ(errors.size(), 2u);
  EXPECT_NEAR(errors[0], 0.0, 1e-3);
  EXPECT_NEAR(errors[1], 180.0, 1e-3);
}

TEST(UnverifiedPairRotations, AGroupWithoutEstimatedViewsIsNotMeasured) {
  ViewGraph graph = RingGraph();
  graph.AddNode(100);
  graph.AddNode(101);
  AddEdge(&graph, 100, 101, Eigen::Matrix3d::Identity());  // outside the ring's component
  const std::vector<double> errors = MedianRotationErrorsAgainstTheRest(graph, {{{100, 101}}}, {});
  ASSERT_EQ(errors.size(), 1u);
  EXPECT_EQ(errors[0], -1.0);
}

}  // namespace
}  // namespace sfm_pruning
