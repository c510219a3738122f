// Nonlinear refinement of a calibrated relative pose on its inlier correspondences: a
// Levenberg-Marquardt of its own on the five degrees of freedom, with exact derivatives by
// ceres::Jet. Not a ceres::Problem: this runs up to four times for every verified pair, where
// building a problem of one residual block per correspondence cost more than the RANSAC.
// The rotation is updated multiplicatively (R = Exp(delta) R_0, well conditioned at any angle)
// and the translation moves in the plane orthogonal to it and is normalised, so the scale gauge is
// fixed exactly: the result always has |t| = 1.
#pragma once

#include <limits>
#include <vector>

#include <Eigen/Core>

#include "sfm_pruning/sfm/pose.hpp"

namespace sfm_pruning {

struct RelativePoseRefinementOptions {
  // Scale of the Cauchy loss on the angular epipolar error; <= 0 means plain least squares.
  // Refinement runs on RANSAC inliers, so this only softens the pull of borderline matches.
  double loss_scale_rad = 0.0;
  int max_num_iterations = 50;

  // Throws std::invalid_argument naming the first field out of range (util/option_checks.hpp).
  void Check() const;
};

struct RelativePoseRefinementSummary {
  bool converged = false;  // the pose was refined (to convergence or the iteration cap) and is finite
  // 1/2 sum of rho(e^2) over the correspondences, e the angular epipolar error in radians and
  // rho the identity or the Cauchy loss (Ceres' convention).
  double initial_cost = 0.0;
  double final_cost = 0.0;
  // The refined rotation's uncertainty to first order: the covariance (rad^2) of the increment omega
  // in R_true = Exp(omega) R_refined, from the residuals' own variance (no assumed pixel noise)
  // and the normal matrix of the angular epipolar errors, the translation direction's coupling
  // included. A pair of small baseline, a narrow field of view or a near-planar structure, where
  // a rotation trades against a translation, shows it as a large variance along that axis.
  // Infinite when the pose is not refined (fewer than 6 correspondences) or degenerate.
  Eigen::Matrix3d rotation_covariance = Eigen::Matrix3d::Constant(std::numeric_limits<double>::infinity());

  // The standard deviation along the rotation's least determined axis, radians (infinite as above).
  double RotationStdRad() const;
};

// Minimises the squared angular epipolar errors (epipolar_geometry.hpp) of the correspondences
// `indices` of `bearings_i` / `bearings_j`, starting from and writing to `relative_ij`.
// Needs at least 5 correspondences; returns converged = false (pose untouched) otherwise.
RelativePoseRefinementSummary RefineRelativePose(const std::vector<Eigen::Vector3d>& bearings_i,
                                                 const std::vector<Eigen::Vector3d>& bearings_j,
                                                 const std::vector<int>& indices,
                                                 const RelativePoseRefinementOptions& options,
                                                 RelativePose* relative_ij);

}  // namespace sfm_pruning
