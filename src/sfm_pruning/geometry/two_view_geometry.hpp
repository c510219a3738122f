// Geometric verification of one image pair: putative feature matches -> calibrated relative pose
// with its inlier matches, or a rejection with a reason. This is what the view-graph
// construction calls per pair (METHOD.md §1).
#pragma once

#include <limits>
#include <string>
#include <vector>

#include "sfm_pruning/geometry/opengv_relative_pose.hpp"
#include "sfm_pruning/sfm/camera_intrinsics.hpp"
#include "sfm_pruning/sfm/features.hpp"
#include "sfm_pruning/sfm/matches.hpp"
#include "sfm_pruning/sfm/pose.hpp"

namespace sfm_pruning {

struct TwoViewGeometryOptions {
  // GLOMAP's acceptance rule: at least this many inliers...
  int min_num_inliers = 30;
  // ...and at least this fraction of the putative matches.
  double min_inlier_ratio = 0.25;
  // RANSAC threshold (max_angular_error_deg), ransac (iterations, confidence, seed), refinement.
  RelativePoseOptions relative_pose;

  // Throws std::invalid_argument naming the first field out of range (util/option_checks.hpp).
  void Check() const;
};

struct TwoViewGeometry {
  bool success = false;
  std::string reason;  // why the pair was rejected; empty on success
  RelativePose relative_pose;  // first view -> second view, |t| = 1
  std::vector<FeatureMatch> inlier_matches;  // a subset of the input matches, input order
  int num_inliers = 0;
  double inlier_ratio = 0.0;  // num_inliers / number of putative matches
  double rotation_std_deg = std::numeric_limits<double>::infinity();  // RelativePoseResult's
};

// `matches[k].i` indexes `features_i`, `matches[k].j` indexes `features_j`; pixels become
// bearings through each view's CameraIntrinsics::Unproject (distortion removed). Throws Error
// when a match refers to a feature that does not exist. The relative pose and inliers are
// filled whenever RANSAC found a model, also when the pair is rejected by the thresholds.
TwoViewGeometry EstimateTwoViewGeometry(const FeatureSet& features_i, const CameraIntrinsics& intrinsics_i,
                                        const FeatureSet& features_j, const CameraIntrinsics& intrinsics_j,
                                        const std::vector<FeatureMatch>& matches,
                                        const TwoViewGeometryOptions& options = {});

}  // namespace sfm_pruning
