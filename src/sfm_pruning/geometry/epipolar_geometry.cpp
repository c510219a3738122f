#include "sfm_pruning/geometry/epipolar_geometry.hpp"

#include <cmath>

#include <Eigen/SVD>

#include "sfm_pruning/geometry/so3.hpp"

namespace sfm_pruning {

Eigen::Matrix3d EssentialMatrix(const RelativePose& relative_ij) {
  return SkewMatrix(relative_ij.translation) * relative_ij.rotation;
}

double AngularEpipolarError(const RelativePose& relative_ij, const Eigen::Vector3d& bearing_i,
                            const Eigen::Vector3d& bearing_j) {
  const Eigen::Vector3d t = relative_ij.translation.normalized();
  const Eigen::Vector3d b_i = bearing_i.normalized();
  const Eigen::Vector3d b_j = bearing_j.normalized();
  const Eigen::Vector3d E_bi = t.cross(relative_ij.rotation * b_i);  // epipolar plane normal in j
  // |E^T b_j| = |R^T (b_j x t)| = |b_j x t|: the gradient with respect to b_i.
  const double denominator_sq = E_bi.squaredNorm() + b_j.cross(t).squaredNorm();
  const double e = b_j.dot(E_bi);
  // Both gradients vanish only when both bearings point along the baseline (at the epipoles),
  // where every point is consistent with the epipolar constraint.
  if (denominator_sq < 1e-30) return 0.0;
  return std::abs(e) / std::sqrt(denominator_sq);
}

RelativePose RelativePoseFromEssential(const Eigen::Matrix3d& essential) {
  // E = U diag(s, s, 0) V^T = [t]_x R with t = U e3 and R = U W V^T, W the quarter turn about z.
  // E's sign is free, so U and V may be negated to make both proper rotations.
  const Eigen::JacobiSVD<Eigen::Matrix3d> svd(essential, Eigen::ComputeFullU | Eigen::ComputeFullV);
  Eigen::Matrix3d U = svd.matrixU();
  Eigen::Matrix3d V = svd.matrixV();
  if (U.determinant() < 0.0) U = -U;
  if (V.determinant() < 0.0) V = -V;
  Eigen::Matrix3d W;
  W << 0.0, -1.0, 0.0,  //
      1.0, 0.0, 0.0,    //
      0.0, 0.0, 1.0;
  return RelativePose(U * W * V.transpose(), U.col(2));
}

std::array<RelativePose, 4> EssentialPoseCandidates(const RelativePose& relative_ij) {
  const Eigen::Vector3d& t = relative_ij.translation;
  const Eigen::Vector3d axis = t.normalized();
  // Half-turn about the baseline: 2 a a^T - I. [t]_x (2 a a^T - I) R = -[t]_x R.
  const Eigen::Matrix3d half_turn = 2.0 * axis * axis.transpose() - Eigen::Matrix3d::Identity();
  const Eigen::Matrix3d R = relative_ij.rotation;
  const Eigen::Matrix3d R_twisted = half_turn * R;
  return {RelativePose(R, t), RelativePose(R, -t), RelativePose(R_twisted, t), RelativePose(R_twisted, -t)};
}

}  // namespace sfm_pruning
