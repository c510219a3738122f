#include "sfm_pruning/view_graph/view_graph_edge.hpp"

namespace sfm_pruning {

std::string EdgeInvalidReasonName(EdgeInvalidReason reason) {
  switch (reason) {
    case EdgeInvalidReason::kNone:
      return "none";
    case EdgeInvalidReason::kTooFewInliers:
      return "too_few_inliers";
    case EdgeInvalidReason::kLowInlierRatio:
      return "low_inlier_ratio";
    case EdgeInvalidReason::kRotationResidual:
      return "rotation_residual";
    case EdgeInvalidReason::kInterSubgraphInconsistent:
      return "inter_subgraph_inconsistent";
    case EdgeInvalidReason::kSubgraphLoopInconsistent:
      return "subgraph_loop_inconsistent";
    case EdgeInvalidReason::kUnverifiedSubgraphPair:
      return "unverified_subgraph_pair";
    case EdgeInvalidReason::kModelDisagreement:
      return "model_disagreement";
    case EdgeInvalidReason::kLandmarkDisagreement:
      return "landmark_disagreement";
    case EdgeInvalidReason::kMissingCorrespondences:
      return "missing_correspondences";
    case EdgeInvalidReason::kTranslationDirection:
      return "translation_direction";
    case EdgeInvalidReason::kOther:
      return "other";
  }
  return "unknown";
}

std::string EdgeMeasureName(EdgeMeasure measure) {
  switch (measure) {
    case EdgeMeasure::kOfReason:
      return "unspecified";
    case EdgeMeasure::kInliers:
      return "inliers";
    case EdgeMeasure::kInlierRatio:
      return "inlier_ratio";
    case EdgeMeasure::kDegrees:
      return "degrees";
    case EdgeMeasure::kTranslationFraction:
      return "translation_fraction";
    case EdgeMeasure::kScaleRatio:
      return "scale_ratio";
    case EdgeMeasure::kBrokenLoops:
      return "broken_loops";
    case EdgeMeasure::kTrust:
      return "trust";
    case EdgeMeasure::kAgreeingShare:
      return "agreeing_share";
    case EdgeMeasure::kMatchesLeft:
      return "matches_left";
    case EdgeMeasure::kObservedShare:
      return "observed_share";
    case EdgeMeasure::kCorrespondences:
      return "correspondences";
    case EdgeMeasure::kVotingEdges:
      return "voting_edges";
  }
  return "unspecified";
}

EdgeMeasure DefaultEdgeMeasure(EdgeInvalidReason reason) {
  switch (reason) {
    case EdgeInvalidReason::kTooFewInliers:
      return EdgeMeasure::kInliers;
    case EdgeInvalidReason::kLowInlierRatio:
      return EdgeMeasure::kInlierRatio;
    case EdgeInvalidReason::kRotationResidual:
    case EdgeInvalidReason::kInterSubgraphInconsistent:
    case EdgeInvalidReason::kTranslationDirection:
      return EdgeMeasure::kDegrees;
    case EdgeInvalidReason::kSubgraphLoopInconsistent:
      return EdgeMeasure::kBrokenLoops;
    case EdgeInvalidReason::kUnverifiedSubgraphPair:
      return EdgeMeasure::kTrust;
    case EdgeInvalidReason::kModelDisagreement:
      return EdgeMeasure::kAgreeingShare;
    case EdgeInvalidReason::kLandmarkDisagreement:
      return EdgeMeasure::kMatchesLeft;
    case EdgeInvalidReason::kMissingCorrespondences:
      return EdgeMeasure::kObservedShare;
    case EdgeInvalidReason::kNone:
    case EdgeInvalidReason::kOther:
      return EdgeMeasure::kOfReason;
  }
  return EdgeMeasure::kOfReason;
}

}  // namespace sfm_pruning
