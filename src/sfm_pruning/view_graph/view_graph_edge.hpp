// One edge of the view graph: a verified two-view geometry, plus the record of why it was cut.
//
// Edges are flagged invalid rather than erased (docs/architecture.md) so the pruning report can
// say which pairs were removed, by which stage, and by how much they missed the threshold.
#pragma once

#include <limits>
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
  kInterSubgraphInconsistent,  // value: deg (or, measure kTranslationFraction, the relative translation
                               // error) of the RANSAC vote
  kSubgraphLoopInconsistent,   // value: inconsistent subgraph loops of its pair, threshold: consistent ones
                               // (triangle vote); or the measure that broke its cycle and its bound
                               // (trusted forest: kDegrees, kScaleRatio or kTranslationFraction)
  kUnverifiedSubgraphPair,     // value: trust of its pair, threshold: 0 (redundant, no transform to verify it)
  kModelDisagreement,          // value: share of its matches the pruned model transfers, threshold: the
                               // share required (pruning/model_edge_audit.hpp)
  kLandmarkDisagreement,       // value: matches left after the landmark check, threshold: the minimum
                               // (pruning/landmark_match_check.hpp)
  kMissingCorrespondences,     // value: share of the landmarks the model predicts in its views that they
                               // observe, threshold: the round's bound (pruning/missing_correspondence_check.hpp)
  kTranslationDirection,       // value: deg between t_ij and the direction a model of its views implies
                               // (pruning/capture_path_directions.hpp)
  kOther,                      // any other stage; value is stage-defined
};

// "too_few_inliers", ...: snake_case, as written to reports.
std::string EdgeInvalidReasonName(EdgeInvalidReason reason);

// What an invalidation's value and threshold measure. Most reasons have one measure
// (DefaultEdgeMeasure); a test that can fail on one of several measures (a cycle of subgraphs:
// rotation, scale or translation) names the one that failed.
enum class EdgeMeasure {
  kOfReason,             // the reason's own measure (DefaultEdgeMeasure)
  kInliers,              // inlier matches
  kInlierRatio,          // inliers / putative matches
  kDegrees,              // an angle
  kTranslationFraction,  // a displacement over the length it is held to (a baseline, a loop's mean side)
  kScaleRatio,           // the larger of two scales over the smaller
  kBrokenLoops,          // value: subgraph triangles its pair breaks, threshold: those it closes
  kTrust,                // pair trust (pruning/pair_trust.hpp): 1 = as distinctive as a true edge
  kAgreeingShare,        // share of the matches whose landmark projects onto the partner feature
  kMatchesLeft,          // matches left after a match-level check, threshold: the minimum kept
  kObservedShare,        // share of the predicted landmarks observed, threshold: the round's bound
  kCorrespondences,      // 2D-3D correspondences that could place the edge, threshold: the minimum
  kVotingEdges,          // edges between the edge's two subgraphs, threshold: the minimum for a vote
};

// "degrees", "translation_fraction", ...: snake_case, as written to view_graph.json.
std::string EdgeMeasureName(EdgeMeasure measure);
// The measure of a reason's value when its producer does not name one (kOfReason for kNone, kOther).
EdgeMeasure DefaultEdgeMeasure(EdgeInvalidReason reason);

// Why an edge was cut: the reason, the measured quantity and the threshold it was held to, in the
// unit of `Measure()`.
struct EdgeInvalidation {
  EdgeInvalidReason reason = EdgeInvalidReason::kNone;
  double value = 0.0;
  double threshold = 0.0;
  EdgeMeasure measure = EdgeMeasure::kOfReason;

  EdgeMeasure Measure() const { return measure == EdgeMeasure::kOfReason ? DefaultEdgeMeasure(reason) : measure; }
};

struct ViewGraphEdge {
  // Inlier correspondences: FeatureMatch::i indexes the features of ViewPair::first, j those of
  // ViewPair::second.
  std::vector<FeatureMatch> matches;
  // Maps camera `first` to camera `second` (sfm/pose.hpp); |t| = 1.
  RelativePose relative_pose;
  // The verified rotation's standard deviation along its least determined axis, degrees, when the
  // verification estimated it (RelativePoseResult); infinite otherwise (a pose given by a database).
  double rotation_std_deg = std::numeric_limits<double>::infinity();
  // Similarity used by spanning trees and Louvain; the number of inliers unless a caller sets it.
  double weight = 0.0;
  bool is_valid = true;
  EdgeInvalidation invalidation;  // reason kNone while is_valid
};

}  // namespace sfm_pruning
