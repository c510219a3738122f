// The capture path's model (PruneSfM's addition, with the capture order: capture_order.hpp). The
// rotation check (capture_path_rotations.hpp) catches a pair that matched a copy repeated by a
// rotation; a pair that matched a copy repeated by a translation (a row of facades, a wall of
// identical windows) keeps a true rotation and only its translation is wrong. The pairs between
// views a few places apart in the capture order see the same copy, so the model solved from them
// alone (the GLOBAL engine on the path's edges: rotations, positions from their tracks, bundle
// adjustment) places every view without any pair between views far apart. A far pair whose
// verified direction to its partner, t_ij, points elsewhere than the direction from view j to view
// i in that model, R_j (c_i - c_j), matched a copy a period away: removed before the partition.
//
// The path's model drifts with the places between two views, as its rotations do. The bound is the
// larger of path_max_direction_deviation_deg and three times the drift a random walk of the path
// edges' median direction residual s would reach over the m places between the two views
// (3 s sqrt(m)). A model whose own path edges disagree with it by more than
// path_max_direction_deviation_deg in the median (a path whose neighbour pairs are themselves
// ambiguous, such as a facade seen head-on, whose planar two-fold ambiguity leaves some neighbour
// pairs' rotations wrong) judges nothing: it could not tell a twin from its own error.
#pragma once

#include <vector>

#include "sfm_pruning/global/global_engine.hpp"
#include "sfm_pruning/pruning/capture_order.hpp"
#include "sfm_pruning/sfm/sfm_data.hpp"
#include "sfm_pruning/sfm/types.hpp"
#include "sfm_pruning/view_graph/view_graph.hpp"

namespace sfm_pruning {

struct CapturePathDirectionCheck {
  bool solved = false;                // the order is used, the check is on, and a piece of the path was solved
  bool applied = false;               // solved, and the path's own edges agree with its model (see the top)
  size_t num_path_edges = 0;          // valid edges between views at most path_window_views apart
  size_t num_path_views = 0;          // views the solved pieces posed
  size_t num_path_pieces = 0;         // connected pieces of at least 3 views solved, each in its own frame
  double path_residual_deg = 0.0;     // s: the median direction residual of the path edges in their model
  std::vector<CapturePathDeviation> removed;  // the edges above their bound, ViewPair order
};

// Solves each connected piece of the capture path of `graph` (the valid edges between views at most
// options.path_window_views apart; pieces of at least 3 views) with the GLOBAL engine (`engine`,
// the options the pruning solves its subgraphs with), then measures the translation direction of
// every valid edge between views more than path_window_views apart whose views the same piece
// posed. Nothing is judged when the order is not used or path_max_direction_deviation_deg is 0.
// The graph is not changed.
CapturePathDirectionCheck CheckDirectionsAgainstCapturePath(const CaptureOrderOptions& options,
                                                            const CaptureOrder& order, const ViewGraph& graph,
                                                            const GlobalEngineOptions& engine,
                                                            const SfmData& views_and_intrinsics,
                                                            const FeaturesPerView& features);

}  // namespace sfm_pruning
