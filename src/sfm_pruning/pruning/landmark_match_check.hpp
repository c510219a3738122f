// The matches of the edges between two aligned subgraphs, checked one by one against the
// subgraphs' own landmarks (not in the paper; docs/pruning.md, "Matches checked against the
// subgraphs' landmarks").
//
// Why: on a street of identical facades a true pair next to a thin stretch holds 30–50 % twin
// matches (a facade feature matched to the same feature one module along). They lie close to
// their epipolar lines, so the verification keeps them, and union-find tracks spread each one over
// two whole tracks, which folds the final solve even on a graph without a single twin edge
// (the synthetic street). 177 of the 182 mixed tracks of the street's default
// model join two or more subgraphs. Inside an accepted subgraph the landmarks are consistent (its
// solve passed the tests), and the pair's frame transform was verified by the RANSAC and the loop
// check. Under it, a true match's feature looks at the other subgraph's landmark of its partner; a
// twin match's looks one facade module away from it.
//
// A pair without a transform (too few edges to vote, no supported hypothesis) has none to carry
// the landmarks, so each view of its edge is placed in the other's subgraph by the edge's own EPnP
// (whose RANSAC follows the edge's majority) and checked against that placement.
//
// What it cannot see: a pair whose transform is itself the twins' (then its twin matches agree
// and its true ones are dropped: the decision, not this check, is wrong), an edge whose majority
// is twins, and the matches whose features no landmark of either subgraph observes (kept).
#pragma once

#include <cstddef>
#include <vector>

#include "sfm_pruning/pruning/recursive_partition.hpp"
#include "sfm_pruning/sfm/features.hpp"
#include "sfm_pruning/sfm/sfm_data.hpp"
#include "sfm_pruning/sfm/similarity.hpp"
#include "sfm_pruning/view_graph/view_graph.hpp"

namespace sfm_pruning {

struct LandmarkMatchCheckOptions {
  // A match is dropped when a landmark of one side, carried into the other subgraph's frame, is
  // more than this many degrees off the ray of the other side's feature; 0 = off (the paper).
  double max_angle_deg = 5.0;
  // An edge left with fewer matches is removed (its relative pose came from the dropped ones).
  size_t min_matches = 5;
  // Edges of pairs without a frame transform (too few edges to vote, no supported hypothesis):
  // each view is placed in the other's subgraph by the edge's own EPnP, and the landmarks are
  // checked against that placement (false: such edges are left alone).
  bool place_views_without_transform = true;

  // Throws std::invalid_argument naming the first field out of range (util/option_checks.hpp).
  void Check() const;
};

// Two accepted subgraphs (indices into the partition's accepted list) and the frame transform of
// their pair, X_k1 = k2_to_k1(X_k2).
struct AlignedSubgraphs {
  int k1 = -1;
  int k2 = -1;
  Similarity3 k2_to_k1;
};

struct LandmarkMatchCheckReport {
  size_t num_edges = 0;    // valid edges between two subgraphs that were checked
  size_t num_matches = 0;  // their matches
  size_t num_tested = 0;   // matches with a landmark on at least one side
  size_t num_dropped = 0;
  // Edges left with fewer than min_matches, with their subgraphs (the caller removes them).
  std::vector<EdgeOfSubgraphs> emptied;
};

// The angle in radians between the ray of `pixel` seen by a camera at `pose` with `intrinsics`
// and the direction from that camera to X.
double RayAngleToPoint(const CameraIntrinsics& intrinsics, const Pose& pose, const Eigen::Vector2d& pixel,
                       const Eigen::Vector3d& X);

// Drops, from every valid edge of `graph` between two accepted subgraphs, the matches a landmark
// contradicts (Options::max_angle_deg), through the transform of the pair's entry in `pairs` or,
// without one, the edge's own placement (Options::place_views_without_transform). Poses and landmarks come from the
// accepted subgraphs' solutions, rays from `features` and the views' intrinsics. Edges are not
// invalidated here: those left with too few matches are listed in the report.
LandmarkMatchCheckReport CheckMatchesAgainstLandmarks(const LandmarkMatchCheckOptions& options,
                                                      const std::vector<AcceptedSubgraph>& accepted,
                                                      const std::vector<AlignedSubgraphs>& pairs,
                                                      const SfmData& views_and_intrinsics,
                                                      const FeaturesPerView& features, ViewGraph* graph);

}  // namespace sfm_pruning
