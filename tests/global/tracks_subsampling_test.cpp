#include "sfm_pruning/global/track_subsampling.hpp"

#include <algorithm>

#include <gtest/gtest.h>

namespace sfm_pruning {
namespace {

// 40 tracks seen by views 1 and 2 at the same pixel, track t in quadrant t % 4 of a 1000 x 1000
// image. Tracks 8..11 (one per quadrant) are also seen by view 3, so they are the longest; view 4
// sees only tracks 30 and 31.
std::vector<SampledTrack> QuadrantTracks() {
  std::vector<SampledTrack> tracks(40);
  for (size_t t = 0; t < tracks.size(); ++t) {
    const double x = (t % 2 == 0 ? 100.0 : 600.0) + 10.0 * static_cast<double>(t / 4);
    const double y = (t % 4 < 2 ? 100.0 : 600.0) + 5.0 * static_cast<double>(t / 4);
    const Eigen::Vector2d pixel(x, y);
    tracks[t] = {{1, pixel}, {2, pixel}};
    if (t >= 8 && t <= 11) tracks[t].push_back({3, pixel});
    if (t == 30 || t == 31) tracks[t].push_back({4, pixel});
  }
  return tracks;
}

TEST(TrackSubsampling, WithoutACapEveryTrackIsKept) {
  const std::vector<SampledTrack> tracks = QuadrantTracks();
  const std::vector<size_t> kept = SelectWellDistributedTracks(tracks, {0, 2});
  ASSERT_EQ(kept.size(), tracks.size());
  for (size_t t = 0; t < kept.size(); ++t) EXPECT_EQ(kept[t], t);
  // A cap no view exceeds keeps everything too.
  EXPECT_EQ(SelectWellDistributedTracks(tracks, {40, 2}).size(), tracks.size());
}

TEST(TrackSubsampling, EachViewTakesTheLongestTrackOfEveryCellFirst) {
  // View 1 takes the longest track of each quadrant (8..11): its quota and those of views 2 and 3
  // are then full. View 4 is below the cap and keeps both of its tracks.
  const std::vector<size_t> kept = SelectWellDistributedTracks(QuadrantTracks(), {4, 2});
  EXPECT_EQ(kept, (std::vector<size_t>{8, 9, 10, 11, 30, 31}));
}

TEST(TrackSubsampling, CellsAreVisitedInTurnUntilTheQuotaIsFull) {
  // Cap 6 with 4 cells: one round gives 8..11, the next takes the best remaining track of the
  // first two cells (ties between equal lengths go to the smaller index: 0 and 1).
  const std::vector<size_t> kept = SelectWellDistributedTracks(QuadrantTracks(), {6, 2});
  EXPECT_EQ(kept, (std::vector<size_t>{0, 1, 8, 9, 10, 11, 30, 31}));
  // One cell: the longest tracks whatever their position.
  EXPECT_EQ(SelectWellDistributedTracks(QuadrantTracks(), {4, 1}), (std::vector<size_t>{8, 9, 10, 11, 30, 31}));
}

}  // namespace
}  // namespace sfm_pruning
