// The only place where OpenGV's conventions meet ours. Everything outside geometry/opengv_*.cpp
// sees pose.hpp's conventions only.
//
// OpenGV relative pose [R_12 | t_12]:  X_1 = R_12 X_2 + t_12 (camera 2 expressed in camera 1).
//   We always pass view i as OpenGV's viewpoint 1 and view j as viewpoint 2, so
//   R_ij = R_12^T and t_ij = -R_12^T t_12 (pose.hpp: X_j = R_ij X_i + t_ij).
// OpenGV absolute pose [R | t]:  X_world = R X_cam + t (camera -> world, t = camera centre).
//   Our Pose has rotation = R^T (world -> camera) and center = t.
// OpenGV RANSAC thresholds live in bearing space: 1 - cos(angle).
#pragma once

#include <vector>

#include <Eigen/Core>
#include <opengv/types.hpp>

#include "sfm_pruning/sfm/pose.hpp"

namespace sfm_pruning {

// [R | t] as OpenGV stores it (opengv::transformation_t).
using OpenGVTransformation = Eigen::Matrix<double, 3, 4>;

// OpenGV relative pose (viewpoint 1 = view i, viewpoint 2 = view j) -> our RelativePose i -> j.
// The translation keeps its length.
RelativePose RelativePoseFromOpenGV(const OpenGVTransformation& T_12);
// Inverse of RelativePoseFromOpenGV.
OpenGVTransformation RelativePoseToOpenGV(const RelativePose& relative_ij);

// OpenGV absolute pose (camera -> world) -> our Pose (world -> camera rotation, centre).
Pose PoseFromOpenGV(const OpenGVTransformation& T_wc);
// Inverse of PoseFromOpenGV.
OpenGVTransformation PoseToOpenGV(const Pose& pose);

// OpenGV's bearing-space threshold for an angular error: 1 - cos(angle).
double OpenGVThresholdFromAngle(double angle_rad);

// Copies vectors into OpenGV's aligned container (bearings and points share the type).
opengv::bearingVectors_t ToOpenGVVectors(const std::vector<Eigen::Vector3d>& vectors);

}  // namespace sfm_pruning
