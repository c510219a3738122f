// Similarity alignment of an estimated reconstruction onto the ground truth through the camera
// centres, for the absolute position/rotation errors OpenMVG's quality evaluation reports.
// An estimate is only defined up to a similarity (scale, rotation, translation), so absolute
// errors are meaningful only after this alignment.
#pragma once

#include <cstdint>
#include <optional>
#include <vector>

#include <Eigen/Core>

#include "sfm_pruning/sfm/pose.hpp"
#include "sfm_pruning/sfm/similarity.hpp"

namespace sfm_pruning {

// Least-squares similarity (Umeyama 1991) minimising sum_k |target_k - T(source_k)|^2.
// Returns nullopt when the sizes differ or either point set has fewer than 3 points or lies on
// a line (the rotation about that line would be undetermined).
std::optional<Similarity3> FitSimilarityLeastSquares(const std::vector<Eigen::Vector3d>& source,
                                                     const std::vector<Eigen::Vector3d>& target);

struct RobustSimilarityOptions {
  // A point is an inlier when |target - T(source)| is below this fraction of the scene radius,
  // the median distance of the target points to their centroid (scale-free, so one default
  // serves scenes measured in metres or in arbitrary units).
  double inlier_threshold_scene_fraction = 0.1;
  int max_iterations = 1000;  // random minimal samples of 3 points
  uint64_t seed = 0;

  // Throws std::invalid_argument naming the first field out of range (util/option_checks.hpp).
  void Check() const;
};

struct RobustSimilarity {
  Similarity3 transform;   // least-squares fit on the inliers
  std::vector<bool> inliers;  // one flag per point
  size_t num_inliers = 0;
  double inlier_threshold = 0.0;  // absolute, in target units
};

// RANSAC over minimal samples of 3 correspondences scored by truncated squared residuals
// (MSAC), then least-squares refits on the inliers until the inlier set stops changing.
// Deterministic for a given seed. Returns nullopt when no sample yields a non-degenerate fit
// with at least 3 inliers (fewer than 3 points, all points collinear, zero scene radius).
std::optional<RobustSimilarity> FitSimilarityRobust(const std::vector<Eigen::Vector3d>& source,
                                                    const std::vector<Eigen::Vector3d>& target,
                                                    const RobustSimilarityOptions& options = {});

}  // namespace sfm_pruning
