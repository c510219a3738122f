// SO(3) helpers: the exponential and logarithm maps, projection of a 3x3 matrix onto SO(3), and
// means of sets of rotations. Rotations are Eigen::Matrix3d; angle-axis vectors are radians.
//
// The geodesic distance between two rotations is pose.hpp's RotationAngleBetween (arccos of the
// trace, accurate to ~1e-8 rad). When tiny angles matter, LogSO3(R_a^T R_b).norm() is the same
// distance with full precision near zero.
#pragma once

#include <vector>

#include <Eigen/Core>

namespace sfm_pruning {

// Skew-symmetric matrix [v]_x with [v]_x w = v x w.
Eigen::Matrix3d SkewMatrix(const Eigen::Vector3d& v);

// Rotation matrix -> angle-axis vector omega (|omega| = angle in [0, pi], direction = axis).
// Accurate near 0 (no division by a vanishing sine) and near pi (the axis is read from the
// symmetric part of R, which stays well conditioned there). At exactly pi the two opposite
// vectors are the same rotation; either may be returned.
Eigen::Vector3d LogSO3(const Eigen::Matrix3d& rotation);

// Angle-axis vector -> rotation matrix (Rodrigues), with a Taylor form near zero.
Eigen::Matrix3d ExpSO3(const Eigen::Vector3d& omega);

// The rotation nearest to `matrix` in the Frobenius norm (SVD; the smallest singular direction
// is flipped when needed so that det = +1).
Eigen::Matrix3d ProjectToRotation(const Eigen::Matrix3d& matrix);

// Chordal L2 mean: the rotation minimising sum_k w_k ||R - R_k||_F^2, i.e. the projection of the
// weighted arithmetic mean of the matrices. `weights` is empty (all 1) or one per rotation.
// Returns the identity for an empty set.
Eigen::Matrix3d ChordalMeanRotation(const std::vector<Eigen::Matrix3d>& rotations,
                                    const std::vector<double>& weights = {});

struct GeodesicMeanOptions {
  // kL2: the Karcher mean (minimises the sum of squared geodesic distances).
  // kL1: the geodesic median (Weiszfeld iterations in the tangent space); robust to outliers.
  enum class Norm { kL2, kL1 };
  Norm norm = Norm::kL2;
  // Iterations of the tangent-space update, started from the chordal mean.
  int max_iterations = 100;
  // Stop when the update rotates by less than this.
  double convergence_tolerance_rad = 1e-12;
  // L1 only: residuals below this are clamped so that an input equal to the current estimate
  // does not divide by zero.
  double l1_min_residual_rad = 1e-12;

  // Throws std::invalid_argument naming the first field out of range (util/option_checks.hpp).
  void Check() const;
};

struct RotationMeanResult {
  Eigen::Matrix3d rotation = Eigen::Matrix3d::Identity();
  int num_iterations = 0;
  bool converged = false;
};

// Geodesic (Karcher L2 or L1 median) mean of rotations; `weights` as in ChordalMeanRotation.
RotationMeanResult GeodesicMeanRotation(const std::vector<Eigen::Matrix3d>& rotations,
                                        const GeodesicMeanOptions& options = {},
                                        const std::vector<double>& weights = {});

}  // namespace sfm_pruning
