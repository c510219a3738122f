// Global positioning (METHOD.md §2.3, GLOMAP; paper eq. 2): camera centres and points jointly
// from the observation rays alone, with the rotations held fixed. No relative translation is
// used, which is what makes it robust where translation averaging struggles (collinear motion,
// poorly estimated two-view baselines).
//
//   minimise over c_i, X_k, s_ik >= min_ray_scale
//     sum_(i,k) huber( | v_ik - s_ik (X_k - c_i) |^2 ),   v_ik = R_i^T b_ik
//
// b_ik is CameraIntrinsics::Unproject of the observed pixel (any camera model, distortion
// removed), so v_ik is the world-frame unit ray. Solved by global_positioning_solver.hpp from a
// random start. Gauge: the smallest positioned view id keeps its (random) initial centre, and the
// scale is left to the per-observation scales (see the solver header). The result is the scene up
// to a similarity; bundle adjustment follows.
#pragma once

#include <map>
#include <vector>

#include <Eigen/Core>

#include "sfm_pruning/global/global_positioning_scene.hpp"
#include "sfm_pruning/global/global_positioning_solver.hpp"
#include "sfm_pruning/global/track_subsampling.hpp"
#include "sfm_pruning/global/tracks.hpp"
#include "sfm_pruning/sfm/features.hpp"
#include "sfm_pruning/sfm/sfm_data.hpp"

namespace sfm_pruning {

struct GlobalPositioningOptions {
  // Loss, bounds, random start (seed), iterations, threads: see PositioningSolverOptions.
  PositioningSolverOptions solver;
  // After the solve, observations whose ray misses the point by more than this are dropped.
  // Loose (about 50 px at f = 1000) because the positions are not refined yet: it removes
  // gross outliers and points behind cameras, bundle adjustment does the fine filtering.
  double max_angular_residual_deg = 3.0;
  // Tracks in the solve: a well-distributed subset per view (track_subsampling.hpp); the points of
  // the others are triangulated from the solved cameras (TriangulateTracks, DLT), then filtered
  // like the solved ones. The solve's cost is linear in its observations, and camera centres from
  // a few hundred tracks per view spread over the image are as accurate as from all of them.
  TrackSubsamplingOptions subsampling{500, 8};

  // Throws std::invalid_argument naming the first field out of range (util/option_checks.hpp).
  void Check() const;
};

// Positions every view that has a rotation (world -> camera, keyed by view id), intrinsics, a
// pose id, features and at least one observation in a track with two such views. Replaces
// sfm_data->poses (one per positioned view) and sfm_data->structure (landmark id = index of the
// track in `tracks`, observations = feature id + raw pixel). The views should form one connected
// component: each further component would float freely (its own translation and scale).
// With `solve_tracks` (e.g. match_star_tracks.hpp), the solve uses those instead and every track
// of `tracks` is triangulated from the solved cameras (landmark ids stay the indices in `tracks`).
// On failure (nothing to position, rigs, solver failure) sfm_data is left untouched.
// Throws Error when a track names a feature that does not exist.
PositioningResult PositionCamerasAndPoints(const GlobalPositioningOptions& options,
                                           const std::map<IndexT, Eigen::Matrix3d>& rotations,
                                           const std::vector<Track>& tracks, const FeaturesPerView& features,
                                           SfmData* sfm_data, const std::vector<Track>* solve_tracks = nullptr);

// The same output as PositionCamerasAndPoints, without a solve: the views of `centers` (and
// `rotations`) keep those poses, and every track is triangulated from them and filtered by
// max_angular_residual_deg. For a graph whose poses are already known (RefineGlobalModel).
PositioningResult TriangulateFromPoses(const GlobalPositioningOptions& options,
                                       const std::map<IndexT, Eigen::Matrix3d>& rotations,
                                       const std::map<IndexT, Eigen::Vector3d>& centers,
                                       const std::vector<Track>& tracks, const FeaturesPerView& features,
                                       SfmData* sfm_data);

}  // namespace sfm_pruning
