#include "sfm_pruning/pruning/unverified_pair_rotations.hpp"

#include <map>

#include "sfm_pruning/geometry/so3.hpp"
#include "sfm_pruning/util/statistics.hpp"

namespace sfm_pruning {

std::vector<double> MedianRotationErrorsAgainstTheRest(const ViewGraph& graph,
                                                       const std::vector<std::vector<ViewPair>>& groups,
                                                       const RotationAveragingOptions& options) {
  ViewGraph rest = graph;
  const EdgeInvalidation judged{EdgeInvalidReason::kUnverifiedRotation, 0.0, 0.0};
  for (const std::vector<ViewPair>& group : groups) {
    for (const ViewPair& pair : group) rest.InvalidateEdge(pair.first, pair.second, judged);
  }
  std::map<IndexT, Eigen::Matrix3d> rotations;
  std::vector<double> errors(groups.size(), -1.0);
  if (rest.NumValidEdges() == 0 || !EstimateGlobalRotations(&rest, options, &rotations).success) return errors;
  for (size_t g = 0; g < groups.size(); ++g) {
    std::vector<double> angles;
    for (const ViewPair& pair : groups[g]) {
      const ViewGraphEdge* edge = graph.FindEdge(pair.first, pair.second);
      const auto first = rotations.find(pair.first);
      const auto second = rotations.find(pair.second);
      if (edge == nullptr || !edge->is_valid || first == rotations.end() || second == rotations.end()) continue;
      // ViewPair order: the edge maps camera `first` to camera `second`, R_ij = R_j R_i^T.
      const Eigen::Matrix3d implied = second->second * first->second.transpose();
      angles.push_back(RadToDeg(RotationAngleBetween(implied, edge->relative_pose.rotation)));
    }
    if (!angles.empty()) errors[g] = Median(std::move(angles));
  }
  return errors;
}

}  // namespace sfm_pruning
