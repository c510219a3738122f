// Retriangulation (METHOD.md §2.4): re-estimates landmarks from their posed observations once
// the poses have been refined and outlier observations filtered, and optionally brings back
// observations (and whole landmarks) that structure_filtering.hpp removed.
//
// Per landmark, in id order:
//   1. candidate X = TriangulateMultiView (DLT) of the bearings (CameraIntrinsics::Unproject) of
//      its posed observations; kept only if in front of every camera, with a largest pairwise
//      angle >= min_triangulation_angle_deg, and if its summed squared reprojection error is not
//      above the current X's (the current X, typically fresh from bundle adjustment, minimises
//      the true reprojection error and DLT only an algebraic one, so never trade it for worse).
//   2. track completion (with `removed`): each removed observation of a posed view not already
//      in the track is added back when its reprojection error at X is <= max_reprojection_error_px.
//   A landmark that filtering removed entirely is restored when its posed observations
//   triangulate with every error within the threshold and enough angle.
#pragma once

#include <cstddef>
#include <map>

#include "sfm_pruning/sfm/sfm_data.hpp"

namespace sfm_pruning {

struct RetriangulationOptions {
  // Same meaning and defaults as StructureFilteringOptions, so that retriangulation does not
  // bring back what the next filtering pass would remove again.
  double max_reprojection_error_px = 4.0;
  double min_triangulation_angle_deg = 1.5;
  // Re-add removed observations / landmarks given to RetriangulateLandmarks.
  bool complete_tracks = true;

  // Throws std::invalid_argument naming the first field out of range (util/option_checks.hpp).
  void Check() const;
};

struct RetriangulationResult {
  size_t num_landmarks_updated = 0;    // X replaced by the new triangulation
  size_t num_landmarks_unchanged = 0;  // triangulation failed or was not better
  size_t num_landmarks_restored = 0;   // removed by filtering, now valid again
  size_t num_observations_restored = 0;
};

// Retriangulates sfm_data->structure in place. `removed` (may be null) is
// StructureFilteringResult::removed; it is only read. Never prints.
RetriangulationResult RetriangulateLandmarks(const RetriangulationOptions& options,
                                             const std::map<IndexT, Landmark>* removed, SfmData* sfm_data);

}  // namespace sfm_pruning
