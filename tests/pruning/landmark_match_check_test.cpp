// The landmark check of the matches between two aligned subgraphs (landmark_match_check.hpp) on
// exact data: subgraphs {0, 1} and {2, 3} in frames of their own, every point a landmark of both.
#include <gtest/gtest.h>

#include <cmath>

#include "pruning/pruning_test_scene.hpp"
#include "sfm_pruning/pruning/landmark_match_check.hpp"

namespace sfm_pruning {
namespace {

using testing::MakePruningTestScene;
using testing::PruningTestScene;
using testing::RandomSimilarity;

struct TwoSubgraphs {
  PruningTestScene scene = MakePruningTestScene(4, 40, 11);
  std::vector<AcceptedSubgraph> accepted{2};
  std::vector<AlignedSubgraphs> pairs;

  TwoSubgraphs() {
    const Similarity3 frame_a = RandomSimilarity(21, 0.5);
    const Similarity3 frame_b = RandomSimilarity(22, 3.0);
    accepted[0].solution = scene.Solution({0, 1}, frame_a);
    accepted[1].solution = scene.Solution({2, 3}, frame_b);
    pairs.push_back({0, 1, frame_a.Compose(frame_b.Inverse())});  // X_a = frame_a(frame_b⁻¹(X_b))
  }

  LandmarkMatchCheckReport Check(double max_angle_deg, bool place_views_without_transform = true) {
    LandmarkMatchCheckOptions options;
    options.max_angle_deg = max_angle_deg;
    options.place_views_without_transform = place_views_without_transform;
    return CheckMatchesAgainstLandmarks(options, accepted, pairs, scene.views_and_intrinsics, scene.features,
                                        &scene.graph);
  }
};

// The copy of the points 3 m above them: about 20° off the rays of cameras 8 m away on the arc.
Similarity3 TwinShift() {
  Similarity3 twin;
  twin.translation = Eigen::Vector3d(0.0, 0.0, 3.0);
  return twin;
}

TEST(LandmarkMatchCheck, DropsExactlyTheMatchesToTheCopy) {
  TwoSubgraphs s;
  s.scene.AddExactEdge(1, 2);
  s.scene.AddTwinEdge(0, 3, TwinShift(), 10);  // 10 matches to the copy, then 30 true ones
  for (IndexT p = 10; p < 40; ++p) s.scene.graph.MutableEdge(0, 3)->matches.push_back({p, p});
  s.scene.AddExactEdge(0, 1);  // inside a subgraph: not checked
  const LandmarkMatchCheckReport report = s.Check(5.0);
  EXPECT_EQ(report.num_edges, 2u);
  EXPECT_EQ(report.num_matches, 80u);
  EXPECT_EQ(report.num_tested, 80u);
  EXPECT_EQ(report.num_dropped, 10u);
  EXPECT_TRUE(report.emptied.empty());
  EXPECT_EQ(s.scene.graph.FindEdge(1, 2)->matches.size(), 40u);
  EXPECT_EQ(s.scene.graph.FindEdge(0, 1)->matches.size(), 40u);
  const std::vector<FeatureMatch>& kept = s.scene.graph.FindEdge(0, 3)->matches;
  ASSERT_EQ(kept.size(), 30u);
  for (const FeatureMatch& match : kept) EXPECT_EQ(match.i, match.j);  // the true ones, feature = point
}

TEST(LandmarkMatchCheck, ListsAnEdgeOfOnlyCopiesAndLeavesItValid) {
  TwoSubgraphs s;
  s.scene.AddTwinEdge(1, 2, TwinShift());
  const LandmarkMatchCheckReport report = s.Check(5.0);
  EXPECT_EQ(report.num_dropped, 40u);
  ASSERT_EQ(report.emptied.size(), 1u);
  EXPECT_EQ(report.emptied[0].pair, ViewPair(1, 2));
  EXPECT_TRUE(s.scene.graph.HasValidEdge(1, 2));  // the caller removes it
}

TEST(LandmarkMatchCheck, OffAtZero) {
  TwoSubgraphs s;
  s.scene.AddTwinEdge(1, 2, TwinShift());
  EXPECT_EQ(s.Check(0.0).num_edges, 0u);
  EXPECT_EQ(s.scene.graph.FindEdge(1, 2)->matches.size(), 40u);
}

// Without the pair's transform each view is placed in the other's subgraph by the edge's own EPnP,
// whose RANSAC follows the majority: the 30 true matches.
TEST(LandmarkMatchCheck, WithoutATransformTheEdgePlacesItsViews) {
  TwoSubgraphs s;
  s.pairs.clear();
  s.scene.AddTwinEdge(0, 3, TwinShift(), 10);
  for (IndexT p = 10; p < 40; ++p) s.scene.graph.MutableEdge(0, 3)->matches.push_back({p, p});
  EXPECT_EQ(s.Check(5.0, false).num_edges, 0u);
  const LandmarkMatchCheckReport report = s.Check(5.0);
  EXPECT_EQ(report.num_edges, 1u);
  EXPECT_EQ(report.num_dropped, 10u);
  EXPECT_EQ(s.scene.graph.FindEdge(0, 3)->matches.size(), 30u);
}

TEST(LandmarkMatchCheck, RayAngleToPointIsTheAngleAtTheCamera) {
  const PruningTestScene scene = MakePruningTestScene(2, 5, 3);
  const CameraIntrinsics& intrinsics = *scene.views_and_intrinsics.FindIntrinsics(0);
  const Pose& pose = scene.poses[0];
  const Eigen::Vector2d pixel = scene.features.at(0).Position(2);
  // Features are stored in single precision: about 1e-8 rad.
  EXPECT_NEAR(RayAngleToPoint(intrinsics, pose, pixel, scene.points[2]), 0.0, 1e-6);
  // A point moved perpendicular to the ray by d at distance r is atan(d / r) off it.
  const Eigen::Vector3d ray = scene.points[2] - pose.center;
  const Eigen::Vector3d side = ray.cross(Eigen::Vector3d::UnitZ()).normalized();
  const double r = ray.norm();
  EXPECT_NEAR(RayAngleToPoint(intrinsics, pose, pixel, scene.points[2] + side * 0.5), std::atan(0.5 / r), 1e-6);
}

}  // namespace
}  // namespace sfm_pruning
