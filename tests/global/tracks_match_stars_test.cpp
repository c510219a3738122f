#include <gtest/gtest.h>

#include "sfm_pruning/global/match_star_tracks.hpp"

namespace sfm_pruning {
namespace {

const RelativePose kAnyPose(Eigen::Matrix3d::Identity(), Eigen::Vector3d(1.0, 0.0, 0.0));

// Two landmarks of one repeated texture, each seen by three views, all pairs matched:
//   landmark A: feature 0 of views 0, 1, 2        landmark B: feature 0 of views 3, 4, 5
// plus one wrong ("twin") match between view 2's A and view 3's B.
ViewGraph MakeTwoTracksJoinedByOneWrongMatch() {
  ViewGraph graph;
  for (const auto& [a, b] : std::vector<std::pair<IndexT, IndexT>>{{0, 1}, {0, 2}, {1, 2}, {3, 4}, {3, 5}, {4, 5}}) {
    graph.AddEdge(a, b, {{0, 0}}, kAnyPose);
  }
  graph.AddEdge(2, 3, {{0, 0}}, kAnyPose);
  return graph;
}

TEST(BuildMatchStarTracks, AWrongMatchMisplacesOneObservationInsteadOfMergingTwoTracks) {
  const ViewGraph graph = MakeTwoTracksJoinedByOneWrongMatch();
  // Union-find merges both landmarks into one six-view track: the wrong match moves three views.
  const TrackBuildingResult connected = BuildTracks(graph);
  ASSERT_EQ(connected.tracks.size(), 1u);
  EXPECT_EQ(connected.tracks[0].size(), 6u);

  // Stars: views 0 and 1 see A alone; view 2's star holds A and one B observation (view 3); view
  // 3's star holds B and one A observation (view 2); views 4 and 5 see B alone.
  const std::vector<Track> stars = BuildMatchStarTracks(graph, 3);
  const std::vector<Track> expected = {
      {{0, 0}, {1, 0}, {2, 0}},          // centred on view 0 and on view 1 (one copy kept)
      {{0, 0}, {1, 0}, {2, 0}, {3, 0}},  // view 2
      {{2, 0}, {3, 0}, {4, 0}, {5, 0}},  // view 3
      {{3, 0}, {4, 0}, {5, 0}},          // views 4 and 5
  };
  EXPECT_EQ(stars, expected);
  for (const Track& star : stars) {
    size_t of_a = 0;
    for (const auto& [view_id, feature_id] : star) of_a += view_id <= 2 ? 1 : 0;
    EXPECT_TRUE(of_a <= 1 || star.size() - of_a <= 1) << "a star mixes more than one wrong observation";
  }
}

TEST(BuildMatchStarTracks, LeavesOutAViewMatchedThroughTwoFeatures) {
  ViewGraph graph;
  graph.AddEdge(0, 1, {{0, 0}}, kAnyPose);
  graph.AddEdge(0, 2, {{0, 0}, {0, 1}}, kAnyPose);  // feature 0 of view 0 matches two features of view 2
  graph.AddEdge(0, 3, {{0, 0}}, kAnyPose);
  const std::vector<Track> stars = BuildMatchStarTracks(graph, 3);
  ASSERT_FALSE(stars.empty());
  EXPECT_EQ(stars.front(), (Track{{0, 0}, {1, 0}, {3, 0}}));
  for (const Track& star : stars) {
    if (star.count(0) > 0 && star.at(0) == 0) {
      EXPECT_EQ(star.count(2), 0u);
    }
  }
}

TEST(BuildMatchStarTracks, DropsShortStarsAndInvalidEdges) {
  ViewGraph graph;
  graph.AddEdge(0, 1, {{0, 0}}, kAnyPose);
  graph.AddEdge(1, 2, {{0, 0}}, kAnyPose);
  // Only view 1's star reaches three views; the others see one neighbour each.
  EXPECT_EQ(BuildMatchStarTracks(graph, 3), (std::vector<Track>{{{0, 0}, {1, 0}, {2, 0}}}));
  EXPECT_EQ(BuildMatchStarTracks(graph, 2).size(), 3u);
  graph.InvalidateEdge(1, 2, EdgeInvalidation{});
  EXPECT_TRUE(BuildMatchStarTracks(graph, 3).empty());
}

}  // namespace
}  // namespace sfm_pruning
