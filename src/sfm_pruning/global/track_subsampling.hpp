// A well-distributed subset of the tracks for the solvers whose cost grows with the number of
// observations (global positioning, the first bundle adjustment): every view keeps up to
// `max_tracks_per_view` tracks spread over its image, the longest first. Cameras are as well
// determined by a few hundred tracks per view spread over the image as by thousands; the points
// of the other tracks are triangulated from the solved cameras afterwards (GLOMAP-style
// subsampling for the solve only).
//
// Selection, deterministic: each view's image (the bounding box of its observed pixels) is cut
// into grid_cells x grid_cells cells; in each cell the view's tracks are ranked longest first
// (ties: smaller track index). Views are visited in id order; a view takes the best remaining track
// of each non-empty cell in turn (round robin over the cells) until it observes
// `max_tracks_per_view` selected tracks, counting those that earlier views selected.
#pragma once

#include <cstddef>
#include <vector>

#include <Eigen/Core>

#include "sfm_pruning/sfm/types.hpp"

namespace sfm_pruning {

struct TrackSubsamplingOptions {
  // 0 = keep every track.
  size_t max_tracks_per_view = 0;
  // Cells per image side.
  size_t grid_cells = 8;

  // Throws std::invalid_argument naming the first field out of range (util/option_checks.hpp).
  void Check() const;
};

// What the selection needs of one observation of a track.
struct SampledObservation {
  IndexT view_id = kUndefinedIndex;
  Eigen::Vector2d pixel = Eigen::Vector2d::Zero();
};
using SampledTrack = std::vector<SampledObservation>;  // at most one observation per view

// Indices into `tracks` of the selected tracks, increasing. All of them when the cap is 0 or no
// view has more tracks than the cap.
std::vector<size_t> SelectWellDistributedTracks(const std::vector<SampledTrack>& tracks,
                                                const TrackSubsamplingOptions& options);

}  // namespace sfm_pruning
