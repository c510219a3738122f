#include "sfm_pruning/pruning/chained_relative_pose.hpp"

namespace sfm_pruning {

ChainedRelativePose ChainRelativePose(const Pose& mean_pose_k1, const Pose& pose_j_in_k1,
                                      const Pose& pose_j_in_k2, const Pose& mean_pose_k2) {
  const RelativePose c1_to_j = RelativePoseBetween(mean_pose_k1, pose_j_in_k1);
  const RelativePose j_to_c2 = RelativePoseBetween(pose_j_in_k2, mean_pose_k2);
  ChainedRelativePose chain;
  chain.rotation = j_to_c2.rotation * c1_to_j.rotation;
  chain.offset = j_to_c2.rotation * c1_to_j.translation;
  chain.per_unit_scale = j_to_c2.translation;
  return chain;
}

std::optional<double> SolveChainScale(const std::vector<ChainedRelativePose>& chains, double min_relative_spread) {
  if (chains.size() < 2) return std::nullopt;
  Eigen::Vector3d mean_offset = Eigen::Vector3d::Zero();
  Eigen::Vector3d mean_slope = Eigen::Vector3d::Zero();
  for (const ChainedRelativePose& chain : chains) {
    mean_offset += chain.offset;
    mean_slope += chain.per_unit_scale;
  }
  mean_offset /= static_cast<double>(chains.size());
  mean_slope /= static_cast<double>(chains.size());
  double cross = 0.0;
  double slope_spread = 0.0;
  double slope_energy = 0.0;
  for (const ChainedRelativePose& chain : chains) {
    const Eigen::Vector3d d_offset = chain.offset - mean_offset;
    const Eigen::Vector3d d_slope = chain.per_unit_scale - mean_slope;
    cross += d_offset.dot(d_slope);
    slope_spread += d_slope.squaredNorm();
    slope_energy += chain.per_unit_scale.squaredNorm();
  }
  if (!(slope_spread > min_relative_spread * min_relative_spread * slope_energy) || slope_spread <= 0.0) {
    return std::nullopt;
  }
  return -cross / slope_spread;
}

Similarity3 FrameSimilarityOfChain(const Pose& mean_pose_k1, const Pose& mean_pose_k2,
                                   const Eigen::Matrix3d& chained_rotation,
                                   const Eigen::Vector3d& chained_translation, double beta) {
  const Eigen::Matrix3d back_to_k1 = mean_pose_k1.rotation.transpose() * chained_rotation.transpose();
  Similarity3 k2_to_k1;
  k2_to_k1.scale = beta;
  k2_to_k1.rotation = back_to_k1 * mean_pose_k2.rotation;
  k2_to_k1.translation =
      mean_pose_k1.center - back_to_k1 * (beta * (mean_pose_k2.rotation * mean_pose_k2.center) + chained_translation);
  return k2_to_k1;
}

}  // namespace sfm_pruning

