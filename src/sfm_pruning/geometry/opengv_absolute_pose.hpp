// Absolute pose (PnP) from bearing vectors and world points: OpenGV's AbsolutePoseSacProblem
// with EPnP (default) or Kneip's P3P, optional nonlinear refinement on the inliers (OpenGV's
// optimize_nonlinear), inlier re-selection. The result is our Pose (world -> camera rotation,
// camera centre); OpenGV's camera -> world form never leaves the .cpp.
#pragma once

#include <string>
#include <vector>

#include <Eigen/Core>

#include "sfm_pruning/geometry/ransac_options.hpp"
#include "sfm_pruning/sfm/pose.hpp"

namespace sfm_pruning {

struct AbsolutePoseOptions {
  enum class Solver {
    kEpnp,      // EPnP, 6-point samples; the method of the paper (METHOD.md §4)
    kP3pKneip,  // Kneip's P3P, 4-point samples (3 + 1 to pick among the solutions)
  };
  Solver solver = Solver::kEpnp;
  // Inlier threshold: angle between the observed bearing and the direction to the point.
  double max_angular_error_deg = 0.25;
  // Alternative pixel threshold: when both are > 0, the angular threshold becomes
  // atan(max_reprojection_error_px / focal_length_px), the angle that a reprojection error of
  // that many pixels subtends at the image centre (slightly looser towards the borders).
  double max_reprojection_error_px = 0.0;
  double focal_length_px = 0.0;
  RansacOptions ransac;
  // Rounds of nonlinear refinement on the inliers, each followed by inlier re-selection.
  int refinement_rounds = 2;
  // Below this many inliers the estimate is reported as failed.
  int min_num_inliers = 6;

  // Throws std::invalid_argument naming the first field out of range (util/option_checks.hpp).
  void Check() const;
};

// The angular inlier threshold (radians) the options describe.
double AbsolutePoseThresholdRad(const AbsolutePoseOptions& options);

struct AbsolutePoseResult {
  bool success = false;
  std::string reason;  // why it failed; empty on success
  Pose pose;           // world -> camera
  std::vector<int> inliers;  // indices into the inputs, increasing
  int num_inliers = 0;
  int num_ransac_iterations = 0;
};

// `bearings[k]` (unit, camera frame) observes `points_world[k]`.
AbsolutePoseResult EstimateAbsolutePose(const std::vector<Eigen::Vector3d>& bearings,
                                        const std::vector<Eigen::Vector3d>& points_world,
                                        const AbsolutePoseOptions& options = {});

}  // namespace sfm_pruning
