#include "sfm_pruning/geometry/two_view_geometry.hpp"

#include <sstream>

#include "sfm_pruning/util/error.hpp"
#include "sfm_pruning/util/option_checks.hpp"

namespace sfm_pruning {

TwoViewGeometry EstimateTwoViewGeometry(const FeatureSet& features_i, const CameraIntrinsics& intrinsics_i,
                                        const FeatureSet& features_j, const CameraIntrinsics& intrinsics_j,
                                        const std::vector<FeatureMatch>& matches,
                                        const TwoViewGeometryOptions& options) {
  // Once per pair, before any work: cheap next to the RANSAC.
  options.Check();
  std::vector<Eigen::Vector3d> bearings_i, bearings_j;
  bearings_i.reserve(matches.size());
  bearings_j.reserve(matches.size());
  for (const FeatureMatch& match : matches) {
    if (match.i >= features_i.size() || match.j >= features_j.size()) {
      throw Error("two-view geometry: match (" + std::to_string(match.i) + ", " + std::to_string(match.j) +
                  ") refers to a missing feature (views have " + std::to_string(features_i.size()) + " and " +
                  std::to_string(features_j.size()) + " features)");
    }
    bearings_i.push_back(intrinsics_i.Unproject(features_i.Position(match.i)));
    bearings_j.push_back(intrinsics_j.Unproject(features_j.Position(match.j)));
  }

  TwoViewGeometry geometry;
  // Fewer putative matches than inliers required can never pass; skip the RANSAC.
  if (matches.size() < static_cast<size_t>(options.min_num_inliers)) {
    geometry.reason = "too few matches: " + std::to_string(matches.size()) + " < " +
                      std::to_string(options.min_num_inliers);
    return geometry;
  }
  const RelativePoseResult estimate = EstimateRelativePose(bearings_i, bearings_j, options.relative_pose);
  geometry.relative_pose = estimate.relative_pose;
  geometry.num_inliers = estimate.num_inliers;
  geometry.rotation_std_deg = estimate.rotation_std_deg;
  geometry.inlier_ratio = matches.empty() ? 0.0 : static_cast<double>(estimate.num_inliers) / matches.size();
  geometry.inlier_matches.reserve(estimate.inliers.size());
  for (const int k : estimate.inliers) geometry.inlier_matches.push_back(matches[k]);

  if (!estimate.success) {
    geometry.reason = "relative pose failed: " + estimate.reason;
  } else if (geometry.num_inliers < options.min_num_inliers) {
    geometry.reason = "too few inliers: " + std::to_string(geometry.num_inliers) + " < " +
                      std::to_string(options.min_num_inliers);
  } else if (geometry.inlier_ratio < options.min_inlier_ratio) {
    std::ostringstream reason;
    reason << "inlier ratio too low: " << geometry.inlier_ratio << " < " << options.min_inlier_ratio;
    geometry.reason = reason.str();
  } else {
    geometry.success = true;
  }
  return geometry;
}

void TwoViewGeometryOptions::Check() const {
  // 0 leaves the count to the relative pose's own minimum (5 inliers).
  RequireAtLeast(min_num_inliers, 0, "TwoViewGeometryOptions::min_num_inliers");
  RequireInRange(min_inlier_ratio, 0.0, 1.0, "TwoViewGeometryOptions::min_inlier_ratio");
  relative_pose.Check();
}

}  // namespace sfm_pruning
