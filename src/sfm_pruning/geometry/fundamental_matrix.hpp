// The fundamental matrix of an image pair from correspondences that are already (mostly)
// inliers, e.g. the verified matches of a pair: Hartley-normalised linear 8-point fit, rank 2
// enforced, then iteratively reweighted to minimise a Cauchy-robustified Sampson distance, so that a
// few remaining outliers do not pull it. No RANSAC: the caller's verification did that.
//
// Convention: x_j^T F x_i = 0 for homogeneous points (x, y, 1) of the same scene point in view i
// and view j. Any 2-d coordinates work (pixels, or normalised coordinates of a prior K).
#pragma once

#include <vector>

#include <Eigen/Core>

namespace sfm_pruning {

struct FundamentalMatrixOptions {
  // Sampson distance (in the units of the points) at which the Cauchy weight halves.
  double robust_scale = 1.0;
  // Reweighting passes after the plain linear fit (0 = the linear fit only).
  int num_reweighting_iterations = 4;

  // Throws std::invalid_argument naming the first field out of range (util/option_checks.hpp).
  void Check() const;
};

// First-order geometric (Sampson) distance of a correspondence to F, in the points' units.
double SampsonDistance(const Eigen::Matrix3d& F, const Eigen::Vector2d& x_i, const Eigen::Vector2d& x_j);

// F from at least 8 correspondences, scaled to unit Frobenius norm. Returns false (F untouched)
// with fewer than 8 points or when the points are degenerate (the linear system has no
// well-defined null vector, e.g. all points identical).
// `definition` (optional) receives how well the data pin F down: the ratio of the two smallest
// singular values of the final weighted linear system. Points in general position give a large
// ratio; points on one plane (or a pure rotation) leave a 3-d family of solutions and a ratio
// near 1, where F, and anything computed from it, is arbitrary.
bool EstimateFundamentalMatrix(const std::vector<Eigen::Vector2d>& points_i, const std::vector<Eigen::Vector2d>& points_j,
                               const FundamentalMatrixOptions& options, Eigen::Matrix3d* F,
                               double* definition = nullptr);

}  // namespace sfm_pruning
