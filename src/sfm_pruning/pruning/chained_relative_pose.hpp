// Steps 2–3 of the inter-subgraph pruning (METHOD.md §4.2): the chained relative pose
// c1 -> i -> j -> c2 between the mean poses of two subgraphs, affine in the unknown scale β
// (k2 units -> k1 units), and the closed-form β* that minimises the spread of those
// translations over a set of edges.
//
// The paper writes (P^a_b = pose of b expressed in frame a, i.e. the camera-to-frame map; the
// paper's P̂_j^k is the inverse of our world-to-camera [R | t]):
//   Ṗ_{c1->i->j->c2} = S(P̂_{c2}^{k2})^{-1} · P̂_j^{k2} · (P̂_j^{k1})^{-1} · P̂_{c1}^{k1}
// Read right to left this maps camera-c1 coordinates to k1's frame, to camera j, to k2's frame,
// to camera c2: in our convention it is the RelativePose c1 -> c2 (pose.hpp), the composition
//   A = RelativePoseBetween(P_c1^{k1}, P̂_j^{k1})   c1 -> j, k1 units
//   B = RelativePoseBetween(P̂_j^{k2}, P_c2^{k2})   j -> c2, k2 units
//   R = R_B R_A,   t(β) = R_B t_A + β t_B   =: offset + β · per_unit_scale.
// S is applied to k2's whole frame: every k2 translation is multiplied by β, so only B's
// translation scales. This is the only reading under which t(β) does not depend on where k2's
// origin lies; with the right β all correct edges give the same t. (Taken literally, the paper's
// formula scales only P̂_{c2}^{k2}'s centre, which agrees across edges only when k2 already has
// k1's scale.)
#pragma once

#include <optional>
#include <vector>

#include <Eigen/Core>

#include "sfm_pruning/sfm/pose.hpp"
#include "sfm_pruning/sfm/similarity.hpp"

namespace sfm_pruning {

struct ChainedRelativePose {
  Eigen::Matrix3d rotation = Eigen::Matrix3d::Identity();  // R_{c1 c2}
  Eigen::Vector3d offset = Eigen::Vector3d::Zero();          // t at β = 0
  Eigen::Vector3d per_unit_scale = Eigen::Vector3d::Zero();  // dt / dβ
  Eigen::Vector3d Translation(double beta) const { return offset + beta * per_unit_scale; }
};

ChainedRelativePose ChainRelativePose(const Pose& mean_pose_k1, const Pose& pose_j_in_k1,
                                      const Pose& pose_j_in_k2, const Pose& mean_pose_k2);

// β* = argmin_β Σ_e |t_e(β) − t̄(β)|², t̄(β) = mean_e t_e(β). With t_e = a_e + β b_e,
// t_e − t̄ = (a_e − ā) + β (b_e − b̄) =: δa_e + β δb_e, so the cost is the 1-D quadratic
// Σ |δa_e|² + 2β Σ δa_e·δb_e + β² Σ |δb_e|², minimised at
//   β* = − Σ_e δa_e·δb_e / Σ_e |δb_e|².
// Empty when Σ|δb_e|² ≤ min_relative_spread² · Σ|b_e|² (fewer than two edges, or every edge
// sees the same j -> c2 translation: the set carries no scale information).
std::optional<double> SolveChainScale(const std::vector<ChainedRelativePose>& chains,
                                      double min_relative_spread = 1e-9);

// The frame transform k2 -> k1 that a chained pose c1 -> c2 (rotation R̄, translation t̄ in k1
// units) and the scale β imply (β scaling k2's whole frame): camera c2's coordinates in k1 units are
// β (R_c2 X2 + t_c2) = R̄ (R_c1 X1 + t_c1) + t̄, solved for X1:
//   X1 = β R X2 + T,   R = R_c1^T R̄^T R_c2,   T = C_c1 − R_c1^T R̄^T (β R_c2 C_c2 + t̄).
Similarity3 FrameSimilarityOfChain(const Pose& mean_pose_k1, const Pose& mean_pose_k2,
                                   const Eigen::Matrix3d& chained_rotation,
                                   const Eigen::Vector3d& chained_translation, double beta);

}  // namespace sfm_pruning
