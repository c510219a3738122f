// Pairwise relative pose error, the accuracy measure of GLOMAP and of the PruneSfM paper.
//
// For two images i, j with true absolute poses (R_i, c_i), (R_j, c_j) and estimated ones, the
// relative poses i -> j are taken with RelativePoseBetween (pose.hpp: X_j = R_ij X_i + t_ij) on
// both sides, and
//   rotation error    = angle of R_ij_true^T R_ij_est                  (RotationAngleBetween)
//   translation error = angle between t_ij_true and t_ij_est, in [0, 180] (AngleBetweenVectors)
//   pair error        = max(rotation error, translation error), degrees.
// The translation error compares directions only, so it does not depend on the unknown scale
// of the estimate, nor does either error depend on its world frame.
//
// Coincident camera centres leave t_ij without a direction. Two cameras count as coincident
// when |c_i - c_j| <= 1e-12 * max(|c_i|, |c_j|) (rounding noise of identical centres). Then:
//   both sides coincident          -> translation error 0 (the estimate agrees with the truth)
//   exactly one side coincident    -> translation error 180 (no direction is the worst answer).
#pragma once

#include <vector>

#include "sfm_pruning/eval/camera_matching.hpp"
#include "sfm_pruning/sfm/pose.hpp"

namespace sfm_pruning {

struct RelativePoseError {
  double rotation_deg = 0.0;
  double translation_deg = 0.0;
  double MaxDeg() const { return rotation_deg > translation_deg ? rotation_deg : translation_deg; }
};

// Error of the estimated relative pose of the pair (i, j) against the true one.
RelativePoseError ComputeRelativePoseError(const Pose& true_i, const Pose& true_j, const Pose& estimated_i,
                                           const Pose& estimated_j);

// The pair error (max of both, degrees) of every unordered pair of ground-truth cameras, in the
// order (0,1), (0,2), ..., (1,2), ... of `cameras`: N (N - 1) / 2 values. A pair touching an
// image missing from the estimate gets +infinity, so it counts as a failure in every recall.
std::vector<double> PairwisePoseErrorsDeg(const std::vector<MatchedCamera>& cameras);

}  // namespace sfm_pruning
