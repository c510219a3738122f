// Step 1 of the inter-subgraph pruning (paper, "Inter-Subgraph Edge Pruning"; METHOD.md §4.1):
// place image j of an edge <i, j> (i in subgraph k1, j in subgraph k2) in k1's frame.
//
// The 2D–3D correspondences are the edge's inlier matches whose feature in i is an observation
// of a landmark of k1 (looked up by (view i, feature id) in the landmarks' observations): the
// landmark's X^k1 pairs with the bearing of the matched feature of j (FeaturesPerView position
// -> j's CameraIntrinsics::Unproject). EPnP inside OpenGV's RANSAC (geometry/
// opengv_absolute_pose.hpp) then gives P̂_j^k1.
// Fewer than `min_correspondences` correspondences, or a failed PnP, mean the edge cannot vote
// (the status says which); what happens to such an edge is the caller's decision
// (SubgraphAlignmentOptions::non_voting_edges).
#pragma once

#include <cstddef>
#include <map>
#include <set>
#include <vector>

#include "sfm_pruning/geometry/opengv_absolute_pose.hpp"
#include "sfm_pruning/pruning/subgraph_solution.hpp"
#include "sfm_pruning/sfm/features.hpp"
#include "sfm_pruning/sfm/sfm_data.hpp"
#include "sfm_pruning/view_graph/view_graph.hpp"

namespace sfm_pruning {

// EPnP, inliers within 4 px (converted to an angle with j's focal length), 12 inliers at least.
AbsolutePoseOptions DefaultSubgraphPnpOptions();

struct EdgePlacementOptions {
  // Below this many 2D–3D correspondences PnP is not attempted (the edge cannot vote).
  size_t min_correspondences = 12;
  // PnP settings. When pnp.max_reprojection_error_px > 0 the focal length is taken from j's
  // intrinsics (pnp.focal_length_px is overwritten). pnp.ransac.seed is mixed with the edge's
  // view ids, so every edge has its own deterministic sampler.
  AbsolutePoseOptions pnp = DefaultSubgraphPnpOptions();
  // Match coverage of a placed edge (EdgePlacement::num_expected_landmarks): a landmark of k1
  // observed by i is expected in j when it lies in front of the placed j, projects at least
  // coverage_image_margin_px inside j's image, and the rays from i and from j to it differ by at
  // most coverage_max_ray_angle_deg (beyond that, descriptors are not expected to match).
  double coverage_max_ray_angle_deg = 45.0;
  double coverage_image_margin_px = 10.0;

  // Throws std::invalid_argument naming the first field out of range (util/option_checks.hpp).
  void Check() const;
};

enum class EdgePlacementStatus {
  kPlaced,                  // P̂_j^k1 estimated
  kMissingViewData,         // j has no view, intrinsics or features: nothing to unproject
  kTooFewCorrespondences,   // fewer than min_correspondences 2D–3D pairs
  kPnpFailed,               // EstimateAbsolutePose failed (too few inliers, degenerate)
};

// "placed", "missing_view_data", "too_few_correspondences", "pnp_failed".
const char* EdgePlacementStatusName(EdgePlacementStatus status);

struct EdgePlacement {
  IndexT view_i = kUndefinedIndex;  // in k1
  IndexT view_j = kUndefinedIndex;  // in k2
  EdgePlacementStatus status = EdgePlacementStatus::kMissingViewData;
  size_t num_correspondences = 0;
  int num_pnp_inliers = 0;
  Pose pose_j_in_k1;  // valid when status == kPlaced
  // Match coverage (kPlaced only): of the landmarks of k1 observed by i that the placed j is
  // expected to see, how many the edge matched. A true edge matches most of them; an edge that
  // matched a copy of the structure misses everything outside the copy (the unique texture
  // around it), so its ratio stays near the copy's share of i's points.
  size_t num_expected_landmarks = 0;
  size_t num_matched_landmarks = 0;
};

// Valid edges of `graph` with one end in `views_k1` and the other in `views_k2`, oriented
// (i in k1, j in k2), in increasing (i, j) order.
std::vector<ViewPair> ConnectingEdges(const ViewGraph& graph, const std::set<IndexT>& views_k1,
                                      const std::set<IndexT>& views_k2);

// Match coverage of the edge (i, j) with j at `pose_j` in k1's frame (i posed in k1; nothing
// expected otherwise): EdgePlacement::num_expected_landmarks / num_matched_landmarks.
struct MatchCoverage {
  size_t expected = 0;
  size_t matched = 0;
};
MatchCoverage MeasureMatchCoverage(const ViewGraph& graph, IndexT view_i, IndexT view_j, const Pose& pose_j,
                                   const SubgraphSolution& k1, const std::map<ObservationKey, IndexT>& landmarks_k1,
                                   const CameraIntrinsics& intrinsics_j, const EdgePlacementOptions& options);

// Places view j of the edge (i, j) in k1's frame. `landmarks_k1` is
// IndexLandmarksByObservation(k1) (built once per subgraph by the caller).
EdgePlacement PlaceViewInSubgraph(const ViewGraph& graph, IndexT view_i, IndexT view_j,
                                  const SubgraphSolution& k1,
                                  const std::map<ObservationKey, IndexT>& landmarks_k1,
                                  const SfmData& views_and_intrinsics, const FeaturesPerView& features,
                                  const EdgePlacementOptions& options = {});

}  // namespace sfm_pruning
