#include "sfm_pruning/pruning/edge_depth_scale.hpp"

#include <vector>

#include "sfm_pruning/util/statistics.hpp"

namespace sfm_pruning {

std::optional<double> EdgeDepthScale(const ViewGraph& graph, IndexT view_i, IndexT view_j, const SubgraphSolution& k1,
                                     const std::map<ObservationKey, IndexT>& landmarks_k1, const Pose& pose_j_in_k1,
                                     const SubgraphSolution& k2, const std::map<ObservationKey, IndexT>& landmarks_k2,
                                     size_t min_correspondences) {
  const auto pose_j_in_k2 = k2.poses.find(view_j);
  if (pose_j_in_k2 == k2.poses.end()) return std::nullopt;
  std::vector<double> ratios;
  for (const FeatureMatch& match : graph.OrientedMatches(view_i, view_j)) {
    const auto in_k1 = landmarks_k1.find({view_i, match.i});
    const auto in_k2 = landmarks_k2.find({view_j, match.j});
    if (in_k1 == landmarks_k1.end() || in_k2 == landmarks_k2.end()) continue;
    const double depth_k1 = (k1.landmarks.at(in_k1->second).X - pose_j_in_k1.center).norm();
    const double depth_k2 = (k2.landmarks.at(in_k2->second).X - pose_j_in_k2->second.center).norm();
    if (depth_k1 > 0.0 && depth_k2 > 0.0) ratios.push_back(depth_k1 / depth_k2);
  }
  if (ratios.size() < min_correspondences) return std::nullopt;
  return Median(std::move(ratios));
}

}  // namespace sfm_pruning
