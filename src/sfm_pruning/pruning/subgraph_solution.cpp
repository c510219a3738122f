#include "sfm_pruning/pruning/subgraph_solution.hpp"

#include <vector>

#include "sfm_pruning/geometry/so3.hpp"

namespace sfm_pruning {

Eigen::Vector3d SubgraphMeanCentre(const SubgraphSolution& solution) {
  Eigen::Vector3d sum = Eigen::Vector3d::Zero();
  for (const auto& [view_id, pose] : solution.poses) sum += pose.center;
  return solution.poses.empty() ? sum : Eigen::Vector3d(sum / static_cast<double>(solution.poses.size()));
}

Pose SubgraphMeanPose(const SubgraphSolution& solution) {
  if (solution.poses.empty()) return Pose();
  std::vector<Eigen::Matrix3d> rotations;
  rotations.reserve(solution.poses.size());
  for (const auto& [view_id, pose] : solution.poses) rotations.push_back(pose.rotation);
  return Pose(GeodesicMeanRotation(rotations).rotation, SubgraphMeanCentre(solution));
}

std::map<ObservationKey, IndexT> IndexLandmarksByObservation(const SubgraphSolution& solution) {
  std::map<ObservationKey, IndexT> index;
  for (const auto& [landmark_id, landmark] : solution.landmarks) {
    for (const auto& [view_id, observation] : landmark.observations) {
      index.emplace(ObservationKey{view_id, observation.id_feat}, landmark_id);  // first (smallest) wins
    }
  }
  return index;
}

}  // namespace sfm_pruning
