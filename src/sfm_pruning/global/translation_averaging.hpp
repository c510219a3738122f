// Translation averaging (METHOD.md §2.5): the framework's relative-translation-based positioning,
// selectable instead of global positioning. Camera centres from the edge directions of the view
// graph, then points triangulated from the tracks.
//
// Edge directions in the world frame (sfm/pose.hpp): X_j = R_ij X_i + t_ij with t = -R c gives
//   t_ij = t_j - R_j R_i^T t_i = -R_j c_j + R_j c_i = -R_j (c_j - c_i),
// so c_j - c_i is parallel to d_ij = -R_j^T t_ij (|t_ij| = 1 in the view graph; R_j is the
// averaged rotation, so the direction inherits its rotation error).
//
// Cost: the same bounded ray cost as global positioning (global_positioning_solver.hpp) with the
// camera c_j as the "point" seen from c_i:  huber(| d_ij - s_ij (c_j - c_i) |^2), s_ij >= min.
// Chosen over LUD's | (c_j - c_i) - s_ij d_ij |, s_ij >= 1: LUD's residual grows with the
// baseline, so an outlier direction on a long edge pulls with a force proportional to the scene
// size, whereas this residual is about sin(angular error) <= 1 (as in BATA), so a wrong edge can
// only pull with a bounded force. Being the same problem as global positioning, it shares the
// solver, the random start and the gauge (smallest view id fixed; scale by the edge scales).
// Robustness: Huber, then the solver's rejection rounds drop the edges whose direction misses
// c_j - c_i by more than solver.rejection_threshold_deg and solve again.
#pragma once

#include <map>
#include <vector>

#include <Eigen/Core>

#include "sfm_pruning/geometry/triangulation.hpp"
#include "sfm_pruning/global/global_positioning_scene.hpp"
#include "sfm_pruning/global/global_positioning_solver.hpp"
#include "sfm_pruning/global/tracks.hpp"
#include "sfm_pruning/sfm/features.hpp"
#include "sfm_pruning/sfm/sfm_data.hpp"
#include "sfm_pruning/view_graph/view_graph.hpp"

namespace sfm_pruning {

struct TranslationAveragingOptions {
  // Loss (0.1 ~ 5.7 deg), edge rejection rounds (5 deg), bounds, random start (seed),
  // iterations, threads.
  PositioningSolverOptions solver;
  // Points: triangulated from the observations of positioned views, again from those within
  // max_angular_residual_deg of that first point (outliers drag a DLT), then observations whose
  // ray misses the point by more than max_angular_residual_deg are dropped (as in global
  // positioning).
  TriangulationMethod triangulation = TriangulationMethod::kDlt;
  double max_angular_residual_deg = 3.0;

  // Throws std::invalid_argument naming the first field out of range (util/option_checks.hpp).
  void Check() const;
};

struct TranslationAveragingResult {
  PositioningResult positioning;  // success, message, counts, solver cost of the last solve
  size_t num_edges = 0;           // valid edges between two views that can receive a pose
  size_t num_rejected_edges = 0;  // dropped by the solver's rejection rounds
};

// Positions every view that can receive a pose (global_positioning_rays.hpp: in sfm_data with a
// pose id and a rotation, keyed by view id) and has a valid edge to another such view. Replaces
// sfm_data->poses and sfm_data->structure as PositionCamerasAndPoints does (landmark id = track
// index). The edges should connect the views: each further component floats freely.
// On failure (no edge, rigs, solver failure) sfm_data is left untouched.
TranslationAveragingResult PositionCamerasByTranslationAveraging(const TranslationAveragingOptions& options,
                                                                 const ViewGraph& graph,
                                                                 const std::map<IndexT, Eigen::Matrix3d>& rotations,
                                                                 const std::vector<Track>& tracks,
                                                                 const FeaturesPerView& features, SfmData* sfm_data);

}  // namespace sfm_pruning
