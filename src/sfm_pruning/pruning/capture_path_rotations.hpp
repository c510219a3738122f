// The capture path's rotations (PruneSfM's addition, with the capture order: capture_order.hpp).
// When the photos were taken along a path, the edges between views a few places apart in the
// capture order are true far more often than the others, and they overlap: each view has several.
// Averaged robustly, they give every view a rotation that does not depend on any pair between
// views far apart in the order. A pair whose two views see two copies of a structure repeated by a
// rotation (the walls of a courtyard, the faces of a box, the halves of a cup) has a relative
// rotation off by that symmetry's angle, at least 60 degrees for the six-fold symmetry of a
// hexagon, and is removed before the partition; a pair that matches a copy repeated by a
// translation (a row of facades) keeps its rotation and is left to the rest of the pruning.
//
// The path's rotations drift with the places between two views. The bound is the larger of
// path_max_deviation_deg and three times the drift a random walk of the path edges' median
// residual s would reach over the m places between the two views (3 s sqrt(m)).
#pragma once

#include <vector>

#include "sfm_pruning/pruning/capture_order.hpp"
#include "sfm_pruning/sfm/types.hpp"
#include "sfm_pruning/view_graph/view_graph.hpp"

namespace sfm_pruning {

struct CapturePathRotationCheck {
  bool applied = false;        // the order is used, the check is on and the path's rotations were averaged
  size_t num_path_edges = 0;   // valid edges between views at most path_window_views apart
  size_t num_path_views = 0;   // views the averaged path reaches
  size_t num_path_pieces = 0;  // connected pieces of at least 3 views averaged, each in its own frame
  double path_residual_deg = 0.0;  // s: the median residual of the path edges after averaging
  std::vector<CapturePathDeviation> removed;  // the edges above their bound, ViewPair order
};

// Measures every valid edge of `graph` against the rotations averaged over its capture path (the
// valid edges between views at most options.path_window_views apart), each connected piece of the
// path (at least 3 views) averaged in its own frame. Nothing is judged when the order is not used
// or path_max_deviation_deg is 0; an edge is judged only when both its views are in one averaged
// piece. The graph is not changed.
CapturePathRotationCheck CheckAgainstCapturePath(const CaptureOrderOptions& options, const CaptureOrder& order,
                                                 const ViewGraph& graph);

}  // namespace sfm_pruning
