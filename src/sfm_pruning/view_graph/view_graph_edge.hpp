// One edge of the view graph: a verified two-view geometry, plus the record of why it was cut.
//
// Edges are flagged invalid rather than erased (docs/architecture.md) so the pruning report can
// say which pairs were removed, by which stage, and by how much they missed the threshold.
#pragma once

#include <string>
#include <vector>

#include "sfm_pruning/sfm/matches.hpp"
#include "sfm_pruning/sfm/pose.hpp"

namespace sfm_pruning {

// The stage that cut an edge. Values are stable: reports and tests refer to them by name.
enum class EdgeInvalidReason {
  kNone,                       // the edge is valid
  kTooFewInliers,              // value: inlier count
  kLowInlierRatio,             // value: inliers / putative matches
  kRotationResidual,           // value: deg between R_ij and the averaged rotations
  kInterSubgraphInconsistent,  // value: deg (or relative translation error) of the RANSAC vote
  kSubgraphLoopInconsistent,   // value: inconsistent subgraph loops of its pair, threshold: consistent ones
                               // (triangle vote); or the measure that broke its cycle and its bound
                               // (trusted forest: degrees, scale ratio or translation fraction)
  kUnverifiedSubgraphPair,     // value: trust of its pair, threshold: 0 (redundant, no transform to verify it)
  kModelDisagreement,          // value: share of its matches the pruned model transfers, threshold: the
                               // share required (pruning/model_edge_audit.hpp)
  kUnverifiedRotation,         // value: median deg between its pair's edges and a rotation averaging of
                               // the rest, threshold: the bound (pruning/unverified_pair_rotations.hpp)
  kLandmarkDisagreement,       // value: matches left after the landmark check, threshold: the minimum
                               // (pruning/landmark_match_check.hpp)
  kOther,                      // any other stage; value is stage-defined
};

// "too_few_inliers", ...: snake_case, as written to reports.
std::string EdgeInvalidReasonName(EdgeInvalidReason reason);

// Why an edge was cut: the reason, the measured quantity and the threshold it was held to,
// in the unit the reason documents (degrees for angles).
struct EdgeInvalidation {
  EdgeInvalidReason reason = EdgeInvalidReason::kNone;
  double value = 0.0;
  double threshold = 0.0;
};

struct ViewGraphEdge {
  // Inlier correspondences: FeatureMatch::i indexes the features of ViewPair::first, j those of
  // ViewPair::second.
  std::vector<FeatureMatch> matches;
  // Maps camera `first` to camera `second` (sfm/pose.hpp); |t| = 1.
  RelativePose relative_pose;
  // Similarity used by spanning trees and Louvain; the number of inliers unless a caller sets it.
  double weight = 0.0;
  bool is_valid = true;
  EdgeInvalidation invalidation;  // reason kNone while is_valid
};

}  // namespace sfm_pruning
