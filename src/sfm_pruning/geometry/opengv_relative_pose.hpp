// Calibrated relative pose from bearing-vector correspondences: 5-point RANSAC (OpenGV's Ransac
// and CentralRelativePoseSacProblem, Stewenius or Nister, with minimal 5-point samples), cheirality disambiguation of the four
// poses sharing the essential matrix, Ceres refinement on the inliers, inlier re-selection.
// The result is in pose.hpp's convention (X_j = R_ij X_i + t_ij) with |t_ij| = 1.
#pragma once

#include <limits>
#include <string>
#include <vector>

#include <Eigen/Core>

#include "sfm_pruning/geometry/ransac_options.hpp"
#include "sfm_pruning/sfm/pose.hpp"

namespace sfm_pruning {

struct RelativePoseOptions {
  enum class Solver { kStewenius, kNister };
  Solver solver = Solver::kStewenius;
  // Inlier threshold on the angular epipolar error (epipolar_geometry.hpp), also given to
  // OpenGV's RANSAC as 1 - cos(angle). 0.25 deg is about 4 px at a 1000 px focal length.
  double max_angular_error_deg = 0.25;
  // Samples are minimal (5 correspondences), so at confidence 0.999 about 7k hypotheses are
  // needed at 25 % inliers, 700 at 40 %, 220 at 50 % and 28 at 75 %.
  RansacOptions ransac = {/*max_iterations=*/10000, /*confidence=*/0.999, /*seed=*/0};
  // Ceres refinement rounds on the inliers, each followed by inlier re-selection; 0 disables.
  int refinement_rounds = 2;
  // Model choice by precision (not in GLOMAP or COLMAP; 0 = off). With a ratio r in (0, 1) the
  // RANSAC and the refinement also run at r * max_angular_error_deg, and of the two models the one
  // with the lower truncated quadratic cost, sum over every correspondence of
  // min(e^2, (r * max_angular_error_deg)^2), is kept; its inliers are then selected at the full
  // threshold. Why: where the matches of a plane are joined by matches between copies of a texture
  // repeated along the baseline (a street of identical facades), a loose threshold lets a wrong
  // pose fit both sets loosely, and it wins the inlier count; the true pose fits the true matches
  // more tightly (docs/global.md, "Model choice by precision"). Costs a second RANSAC per pair.
  double precision_check_ratio = 0.0;
  // Drop inliers that triangulate behind either camera. Rays whose parallax is below the
  // inlier threshold are kept: their depth sign is noise (points at infinity).
  bool reject_points_behind = true;

  // Throws std::invalid_argument naming the first field out of range (util/option_checks.hpp).
  void Check() const;
};

struct RelativePoseResult {
  bool success = false;
  std::string reason;  // why it failed; empty on success
  RelativePose relative_pose;  // i -> j, |t| = 1
  std::vector<int> inliers;    // indices into the input arrays, increasing
  int num_inliers = 0;
  // Inliers triangulated in front of both cameras (a subset when reject_points_behind is off,
  // equal to the inliers with parallax otherwise).
  int num_inliers_in_front = 0;
  int num_ransac_iterations = 0;
  // The returned rotation's standard deviation along its least determined axis, degrees, from the
  // residuals of the inliers (RelativePoseRefinementSummary::RotationStdRad); infinite when it
  // cannot be estimated (five inliers, a degenerate configuration).
  double rotation_std_deg = std::numeric_limits<double>::infinity();
};

// `bearings_i[k]` and `bearings_j[k]` are the unit camera-frame bearings of match k in views i
// and j. Fails (success = false, with a reason) on mismatched sizes, too few correspondences for
// the solver (5), or no model found.
RelativePoseResult EstimateRelativePose(const std::vector<Eigen::Vector3d>& bearings_i,
                                        const std::vector<Eigen::Vector3d>& bearings_j,
                                        const RelativePoseOptions& options = {});

}  // namespace sfm_pruning
