// Structure filtering after bundle adjustment (METHOD.md §2.4): drops observations whose
// reprojection error is too large or whose point lies behind the camera, then landmarks whose
// remaining posed observations are too few or too close to parallel to fix the depth.
//
// Order of the tests, per landmark (in id order, so the result is deterministic):
//   1. each posed observation: behind the camera -> removed; error > max_reprojection_error_px
//      -> removed. Observations of unposed views are neither tested nor counted.
//   2. fewer than min_num_observations posed observations left -> landmark removed.
//   3. largest pairwise triangulation angle of the remaining posed views below
//      min_triangulation_angle_deg -> landmark removed (its depth is poorly determined).
// Everything removed is returned, so retriangulation.hpp can try to bring it back once the
// poses have been refined again.
#pragma once

#include <cstddef>
#include <map>

#include "sfm_pruning/sfm/sfm_data.hpp"

namespace sfm_pruning {

struct StructureFilteringOptions {
  // About 4 sigma of 1 px Gaussian noise per coordinate: an inlier is dropped with probability
  // exp(-8) ~ 3e-4, a 20 px outlier always.
  double max_reprojection_error_px = 4.0;
  // Points triangulated under a smaller angle have a depth uncertainty of roughly
  // noise / (focal * angle) times their distance, i.e. tens of percent at 1 px and f ~ 1000.
  double min_triangulation_angle_deg = 1.5;
  // Posed observations a landmark needs to be kept (< 2 cannot be triangulated).
  size_t min_num_observations = 2;

  // Throws std::invalid_argument naming the first field out of range (util/option_checks.hpp).
  void Check() const;
};

struct StructureFilteringResult {
  size_t num_observations_removed_error = 0;   // reprojection error above the threshold
  size_t num_observations_removed_behind = 0;  // point behind the camera
  size_t num_landmarks_removed_few_observations = 0;
  size_t num_landmarks_removed_angle = 0;
  size_t num_landmarks_kept = 0;
  size_t num_observations_kept = 0;  // posed observations of the kept landmarks

  // What was removed, keyed by landmark id: for a removed landmark all of it (X and every
  // observation), for a kept one only its removed observations. Input to RetriangulateLandmarks.
  std::map<IndexT, Landmark> removed;

  size_t NumObservationsRemoved() const { return num_observations_removed_error + num_observations_removed_behind; }
  size_t NumLandmarksRemoved() const { return num_landmarks_removed_few_observations + num_landmarks_removed_angle; }
};

// Filters sfm_data->structure in place. Never prints.
StructureFilteringResult FilterStructure(const StructureFilteringOptions& options, SfmData* sfm_data);

}  // namespace sfm_pruning
