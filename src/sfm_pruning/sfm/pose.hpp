// Pose conventions: THE reference for every pose in PruneSfM.
//
// Absolute pose of a camera (class Pose), as in OpenMVG's sfm_data.json:
//   rotation  R : world -> camera, a proper rotation matrix.
//   center    c : the camera centre in world coordinates.
//   A world point X maps to camera coordinates  X_cam = R (X - c) = R X + t,  with t = -R c.
//   The camera looks along +z of its own frame; +x right, +y down in the image.
//   (COLMAP's images.txt stores the same R as a Hamilton quaternion and t = -R c.)
//
// Relative pose of an edge <i, j> of the view graph (struct RelativePose):
//   maps camera-i coordinates to camera-j coordinates:   X_j = R_ij X_i + t_ij
//   so  R_ij = R_j R_i^T  and  t_ij = t_j - R_ij t_i  (up to scale; view graphs store |t_ij| = 1).
//   The centre of camera j seen from camera i is  -R_ij^T t_ij.
//   (OpenGV's relative pose is the opposite direction, X_1 = R_12 X_2 + t_12; geometry/opengv
//   converts at the boundary, nothing else sees OpenGV's convention.)
//
// Units: rotation angles in the API are radians unless a name ends in _deg.
#pragma once

#include <algorithm>
#include <cmath>

#include <Eigen/Core>
#include <Eigen/Geometry>

namespace sfm_pruning {

struct Pose {
  Eigen::Matrix3d rotation = Eigen::Matrix3d::Identity();  // world -> camera
  Eigen::Vector3d center = Eigen::Vector3d::Zero();         // camera centre, world frame

  Pose() = default;
  Pose(const Eigen::Matrix3d& R, const Eigen::Vector3d& c) : rotation(R), center(c) {}

  // Builds a pose from the world-to-camera [R | t] (COLMAP / OpenCV form).
  static Pose FromRotationTranslation(const Eigen::Matrix3d& R, const Eigen::Vector3d& t) {
    return Pose(R, -R.transpose() * t);
  }

  Eigen::Vector3d translation() const { return -rotation * center; }
  Eigen::Vector3d ToCamera(const Eigen::Vector3d& X_world) const { return rotation * (X_world - center); }
  Eigen::Vector3d ToWorld(const Eigen::Vector3d& X_cam) const { return rotation.transpose() * X_cam + center; }
  // Direction of the optical axis (+z of the camera) in world coordinates.
  Eigen::Vector3d ViewingDirection() const { return rotation.row(2).transpose(); }
};

struct RelativePose {
  Eigen::Matrix3d rotation = Eigen::Matrix3d::Identity();  // R_ij: camera i -> camera j
  Eigen::Vector3d translation = Eigen::Vector3d::Zero();   // t_ij, X_j = R_ij X_i + t_ij

  RelativePose() = default;
  RelativePose(const Eigen::Matrix3d& R, const Eigen::Vector3d& t) : rotation(R), translation(t) {}

  // The same edge seen from j to i.
  RelativePose Inverse() const { return {rotation.transpose(), -rotation.transpose() * translation}; }
  // Centre of camera j in camera i's frame.
  Eigen::Vector3d CenterOfJInI() const { return -rotation.transpose() * translation; }
};

// Relative pose i -> j implied by two absolute poses (translation not normalized).
inline RelativePose RelativePoseBetween(const Pose& pose_i, const Pose& pose_j) {
  const Eigen::Matrix3d R_ij = pose_j.rotation * pose_i.rotation.transpose();
  return {R_ij, pose_j.translation() - R_ij * pose_i.translation()};
}

// Absolute pose of j from the absolute pose of i and the relative pose i -> j, whose translation
// is taken at face value (scale it first if it is a unit direction).
inline Pose ComposePose(const Pose& pose_i, const RelativePose& relative_ij) {
  const Eigen::Matrix3d R_j = relative_ij.rotation * pose_i.rotation;
  const Eigen::Vector3d t_j = relative_ij.rotation * pose_i.translation() + relative_ij.translation;
  return Pose::FromRotationTranslation(R_j, t_j);
}

// Angle in radians of the rotation R_a^T R_b (the geodesic distance on SO(3)). Computed through
// the quaternion (2 atan2(|v|, |w|)) rather than acos of the trace, which loses all precision
// below about 1e-7 rad: the pose metrics and unit tests compare angles near zero.
inline double RotationAngleBetween(const Eigen::Matrix3d& R_a, const Eigen::Matrix3d& R_b) {
  const Eigen::Quaterniond q(R_a.transpose() * R_b);
  return 2.0 * std::atan2(q.vec().norm(), std::abs(q.w()));
}

// Unsigned angle in radians between two non-zero vectors, in [0, pi]. Uses atan2 so that small
// angles keep full precision.
inline double AngleBetweenVectors(const Eigen::Vector3d& a, const Eigen::Vector3d& b) {
  return std::atan2(a.cross(b).norm(), a.dot(b));
}

inline double RadToDeg(double rad) { return rad * (180.0 / M_PI); }
inline double DegToRad(double deg) { return deg * (M_PI / 180.0); }

}  // namespace sfm_pruning
