// Depth votes on the links of tracks: a match whose depth disagrees with what the feature's other
// matches say about that depth does not join the feature's track.
//
// Why: a match between two copies of a repeated texture can pass the epipolar test of a *true*
// pair. A camera that moves along a repeated facade sees the copy one module further at the place
// where the other view saw the original: the shift runs along the baseline, so the match lies on
// its epipolar line (at the module shift itself it is a point at infinity). Such a link merges the
// track of one copy with the track of the other; the views of the two halves are usually
// disjoint, so no view sees two features of the track and tracks.hpp cannot notice. Global
// positioning then pulls the cameras of both halves onto one point: the model folds.
//
// The depth tells them apart. Along each edge (i, j) the matched rays triangulate to an inverse
// depth in view i, in units of the edge's baseline (|t_ij| = 1): rho(a; i, j). For one feature a of
// view i, the ratio rho(a; i, j) / rho(a; i, k) is the ratio of the two baselines, the same for
// every feature the two edges share. That common ratio is the densest cluster of the shared
// features' ratios (not their median: an edge pair may share as many twin links as true ones, and
// only the true ones agree exactly), far points left out. A link whose ratio to one of the
// feature's other links is off the common ratio by more than a factor max_inverse_depth_ratio
// (widened by the angular noise over each match's parallax) disagrees with that link. A link that
// disagrees with more of the feature's other links than it agrees with, at either end, is dropped
// from the tracks (it stays an inlier of its edge: the rotation averaging has used it already).
// Inverse depths below far_fraction of the edge's median count as that floor, so far points and
// points at infinity compare as "far" instead of by noise.
//
// Measured on generated streets whose kept pairs are all true (docs/global.md, "Tracks"): 99 % of
// the twin links and 0.1 % of the true ones dropped.
#pragma once

#include <cstddef>

#include "sfm_pruning/sfm/features.hpp"
#include "sfm_pruning/sfm/sfm_data.hpp"
#include "sfm_pruning/view_graph/view_graph.hpp"

namespace sfm_pruning {

struct LinkDepthVoteOptions {
  // On by default in every solve (docs/method.md has the evidence); false: every inlier joins.
  bool enabled = true;
  // Two links of one feature agree when their inverse-depth ratio is within this factor of their
  // edges' common ratio. 2: twice the noise of a far point seen with a 0.3 deg parallax.
  double max_inverse_depth_ratio = 2.0;
  // Inverse depths below this fraction of the edge's median count as this fraction (far points,
  // points at infinity and the few that triangulate behind the cameras compare as "far").
  double far_fraction = 0.1;
  // Angular noise of a ray (and of the edge's pose): a match with parallax angle theta has its
  // inverse depth known to about noise / theta (relative), which widens the agreement of its
  // links. 0.25: the verification's inlier bound (RelativePoseOptions::max_angular_error_deg).
  double angular_noise_deg = 0.25;
  // Edges of one view whose common ratio rests on fewer shared features give no votes.
  size_t min_shared_features = 5;

  // Throws std::invalid_argument naming the first field out of range (util/option_checks.hpp).
  void Check() const;
};

struct LinkDepthVoteResult {
  ViewGraph graph;               // the input with the dropped links removed from the edges' matches
  size_t num_links = 0;          // matches of the valid edges
  size_t num_dropped_links = 0;  // removed
};

// Votes on the links of the valid edges of `graph` (their relative poses and inliers; pixel rays
// from `features` and the intrinsics of `views_and_intrinsics`). Edges of views without
// intrinsics or features keep their matches. Deterministic.
LinkDepthVoteResult DropDepthInconsistentLinks(const LinkDepthVoteOptions& options, const ViewGraph& graph,
                                              const SfmData& views_and_intrinsics, const FeaturesPerView& features);

}  // namespace sfm_pruning
