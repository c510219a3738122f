// Epipolar geometry of calibrated views in bearing space: the essential matrix of a relative
// pose, the angular epipolar error, and the four poses that share one essential matrix.
#pragma once

#include <array>

#include <Eigen/Core>

#include "sfm_pruning/sfm/pose.hpp"

namespace sfm_pruning {

// E = [t_ij]_x R_ij, so that b_j^T E b_i = 0 for bearings of the same point (pose.hpp convention).
Eigen::Matrix3d EssentialMatrix(const RelativePose& relative_ij);

// First-order (Sampson) angular epipolar error in radians: the smallest joint rotation
// sqrt(d_i^2 + d_j^2) of the two bearings that puts them on a common epipolar plane.
//   e = b_j . (t x R b_i),  error = |e| / sqrt(|t x R b_i|^2 + |b_j x t|^2)
// for unit bearings. Scale-invariant in t. Cheirality is not checked.
double AngularEpipolarError(const RelativePose& relative_ij, const Eigen::Vector3d& bearing_i,
                            const Eigen::Vector3d& bearing_j);

// One relative pose (|t| = 1) whose essential matrix is `essential` up to scale and sign, by SVD;
// EssentialPoseCandidates gives the other three. `essential` must have rank 2 (two equal
// non-zero singular values for an exact essential matrix).
RelativePose RelativePoseFromEssential(const Eigen::Matrix3d& essential);

// The four relative poses with the essential matrix of `relative_ij` (up to sign), |t| kept:
// (R, t), (R, -t), (R_pi R, t), (R_pi R, -t) with R_pi the half-turn about t (the "twisted pair").
// Only one of them puts the observed points in front of both cameras.
std::array<RelativePose, 4> EssentialPoseCandidates(const RelativePose& relative_ij);

}  // namespace sfm_pruning
