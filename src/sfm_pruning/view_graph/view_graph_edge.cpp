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
    case EdgeInvalidReason::kUnverifiedRotation:
      return "unverified_rotation";
    case EdgeInvalidReason::kLandmarkDisagreement:
      return "landmark_disagreement";
    case EdgeInvalidReason::kOther:
      return "other";
  }
  return "unknown";
}

}  // namespace sfm_pruning
