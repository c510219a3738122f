#include <algorithm>
#include <random>

#include <gtest/gtest.h>

#include "sfm_pruning/global/tracks.hpp"

namespace sfm_pruning {
namespace {

const RelativePose kAnyPose(Eigen::Matrix3d::Identity(), Eigen::Vector3d(1.0, 0.0, 0.0));

// Matches given from view a to view b, any order of a and b (AddEdge orients them).
void AddMatches(ViewGraph* graph, IndexT a, IndexT b, const std::vector<FeatureMatch>& matches) {
  graph->AddEdge(a, b, matches, kAnyPose);
}

// Views 0..3:
//   clean track A  (0,0) (1,0) (2,0) (3,0)        length 4
//   clean track B  (0,1) (1,1) (2,1)              length 3
//   conflict       (0,2) (1,2) (2,2) (0,3)        view 0 twice
//   short track    (2,5) (3,5)                    length 2
ViewGraph MakeHandMadeGraph() {
  ViewGraph graph;
  AddMatches(&graph, 0, 1, {{0, 0}, {1, 1}, {2, 2}});
  AddMatches(&graph, 1, 2, {{0, 0}, {1, 1}, {2, 2}});
  AddMatches(&graph, 2, 3, {{0, 0}, {5, 5}});
  AddMatches(&graph, 2, 0, {{2, 3}});  // closes the conflicting chain onto feature 3 of view 0
  return graph;
}

TEST(BuildTracks, KeepsCleanTracksAndDropsTheConflictingOne) {
  const TrackBuildingResult result = BuildTracks(MakeHandMadeGraph());
  EXPECT_EQ(result.num_candidate_tracks, 3u + 1u);
  EXPECT_EQ(result.num_conflicting_tracks, 1u);
  EXPECT_EQ(result.num_short_tracks, 1u);
  EXPECT_EQ(result.num_capped_tracks, 0u);
  ASSERT_EQ(result.tracks.size(), 2u);
  EXPECT_EQ(result.tracks[0], (Track{{0, 0}, {1, 0}, {2, 0}, {3, 0}}));
  EXPECT_EQ(result.tracks[1], (Track{{0, 1}, {1, 1}, {2, 1}}));
}

TEST(BuildTracks, MinTrackLengthTwoKeepsPairs) {
  TrackBuildingOptions options;
  options.min_track_length = 2;
  const TrackBuildingResult result = BuildTracks(MakeHandMadeGraph(), options);
  EXPECT_EQ(result.num_short_tracks, 0u);
  ASSERT_EQ(result.tracks.size(), 3u);
  // Sorted by smallest (view, feature): (0,0), (0,1), then (2,5).
  EXPECT_EQ(result.tracks[2], (Track{{2, 5}, {3, 5}}));
}

TEST(BuildTracks, LongerMinimumDropsShorterTracks) {
  TrackBuildingOptions options;
  options.min_track_length = 4;
  const TrackBuildingResult result = BuildTracks(MakeHandMadeGraph(), options);
  EXPECT_EQ(result.num_short_tracks, 2u);
  EXPECT_EQ(result.tracks, (std::vector<Track>{{{0, 0}, {1, 0}, {2, 0}, {3, 0}}}));
}

TEST(BuildTracks, InvalidEdgesContributeNothing) {
  ViewGraph graph = MakeHandMadeGraph();
  graph.InvalidateEdge(0, 2, {EdgeInvalidReason::kRotationResidual, 12.0, 10.0});
  const TrackBuildingResult result = BuildTracks(graph);
  // Without the closing match the former conflict is a clean 3-view track.
  EXPECT_EQ(result.num_conflicting_tracks, 0u);
  ASSERT_EQ(result.tracks.size(), 3u);
  EXPECT_EQ(result.tracks[2], (Track{{0, 2}, {1, 2}, {2, 2}}));
}

TEST(BuildTracks, IndependentOfInsertionAndMatchOrder) {
  const TrackBuildingResult reference = BuildTracks(MakeHandMadeGraph());
  std::mt19937 rng(7);
  for (int trial = 0; trial < 5; ++trial) {
    // Same matches, edges inserted in another order and from the other end, matches shuffled.
    std::vector<std::pair<ViewPair, std::vector<FeatureMatch>>> edges = {
        {{0, 1}, {{0, 0}, {1, 1}, {2, 2}}},
        {{1, 2}, {{0, 0}, {1, 1}, {2, 2}}},
        {{2, 3}, {{0, 0}, {5, 5}}},
        {{0, 2}, {{3, 2}}}};
    std::shuffle(edges.begin(), edges.end(), rng);
    ViewGraph graph;
    for (auto& [pair, matches] : edges) {
      std::shuffle(matches.begin(), matches.end(), rng);
      std::vector<FeatureMatch> reversed;
      for (const FeatureMatch& m : matches) reversed.push_back({m.j, m.i});
      AddMatches(&graph, pair.second, pair.first, reversed);
    }
    const TrackBuildingResult result = BuildTracks(graph);
    EXPECT_EQ(result.tracks, reference.tracks);
    EXPECT_EQ(result.num_conflicting_tracks, reference.num_conflicting_tracks);
  }
}

TEST(BuildTracks, TotalCapKeepsTheLongestTracks) {
  TrackBuildingOptions options;
  options.max_num_tracks = 1;
  const TrackBuildingResult result = BuildTracks(MakeHandMadeGraph(), options);
  ASSERT_EQ(result.tracks.size(), 1u);
  EXPECT_EQ(result.tracks[0].size(), 4u);
  EXPECT_EQ(result.num_capped_tracks, 1u);
}

TEST(BuildTracks, PerViewCapKeepsTracksThatAViewStillNeeds) {
  ViewGraph graph = MakeHandMadeGraph();
  // Track C (3,7) (4,7) (5,7): view 4 and 5 have no track yet, so C survives a cap of 1.
  AddMatches(&graph, 3, 4, {{7, 7}});
  AddMatches(&graph, 4, 5, {{7, 7}});
  TrackBuildingOptions options;
  options.max_tracks_per_view = 1;
  const TrackBuildingResult result = BuildTracks(graph, options);
  ASSERT_EQ(result.tracks.size(), 2u);
  EXPECT_EQ(result.tracks[0], (Track{{0, 0}, {1, 0}, {2, 0}, {3, 0}}));
  EXPECT_EQ(result.tracks[1], (Track{{3, 7}, {4, 7}, {5, 7}}));
  EXPECT_EQ(result.num_capped_tracks, 1u);  // B: views 0, 1, 2 already have their track
}

TEST(BuildTracks, EmptyGraphGivesNoTracks) {
  const TrackBuildingResult result = BuildTracks(ViewGraph());
  EXPECT_TRUE(result.tracks.empty());
  EXPECT_EQ(result.num_candidate_tracks, 0u);
}

}  // namespace
}  // namespace sfm_pruning
