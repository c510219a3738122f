#include "sfm_pruning/geometry/opengv_boundary.hpp"

#include <cmath>

namespace sfm_pruning {

RelativePose RelativePoseFromOpenGV(const OpenGVTransformation& T_12) {
  // X_i = R_12 X_j + t_12  <=>  X_j = R_12^T X_i - R_12^T t_12.
  const Eigen::Matrix3d R_12 = T_12.leftCols<3>();
  return {R_12.transpose(), -R_12.transpose() * T_12.col(3)};
}

OpenGVTransformation RelativePoseToOpenGV(const RelativePose& relative_ij) {
  const RelativePose ji = relative_ij.Inverse();  // X_i = R_ji X_j + t_ji is OpenGV's form
  OpenGVTransformation T_12;
  T_12 << ji.rotation, ji.translation;
  return T_12;
}

Pose PoseFromOpenGV(const OpenGVTransformation& T_wc) {
  return Pose(T_wc.leftCols<3>().transpose(), T_wc.col(3));
}

OpenGVTransformation PoseToOpenGV(const Pose& pose) {
  OpenGVTransformation T_wc;
  T_wc << pose.rotation.transpose(), pose.center;
  return T_wc;
}

double OpenGVThresholdFromAngle(double angle_rad) { return 1.0 - std::cos(angle_rad); }

opengv::bearingVectors_t ToOpenGVVectors(const std::vector<Eigen::Vector3d>& vectors) {
  return opengv::bearingVectors_t(vectors.begin(), vectors.end());
}

}  // namespace sfm_pruning
