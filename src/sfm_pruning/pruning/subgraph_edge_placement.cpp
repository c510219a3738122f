#include "sfm_pruning/pruning/subgraph_edge_placement.hpp"

#include "sfm_pruning/util/option_checks.hpp"

#include <algorithm>
#include <set>

namespace sfm_pruning {

AbsolutePoseOptions DefaultSubgraphPnpOptions() {
  AbsolutePoseOptions options;
  options.solver = AbsolutePoseOptions::Solver::kEpnp;
  options.max_reprojection_error_px = 4.0;
  options.min_num_inliers = 12;
  return options;
}

MatchCoverage MeasureMatchCoverage(const ViewGraph& graph, IndexT view_i, IndexT view_j, const Pose& pose_j,
                                   const SubgraphSolution& k1, const std::map<ObservationKey, IndexT>& landmarks_k1,
                                   const CameraIntrinsics& intrinsics_j, const EdgePlacementOptions& options) {
  MatchCoverage coverage;
  const auto pose_i = k1.poses.find(view_i);
  if (pose_i == k1.poses.end()) return coverage;
  std::set<IndexT> matched_landmarks;
  for (const FeatureMatch& match : graph.OrientedMatches(view_i, view_j)) {
    const auto landmark = landmarks_k1.find({view_i, match.i});
    if (landmark != landmarks_k1.end()) matched_landmarks.insert(landmark->second);
  }
  const double margin = options.coverage_image_margin_px;
  const double max_angle = DegToRad(options.coverage_max_ray_angle_deg);
  std::set<IndexT> seen_by_i;
  // landmarks_k1 is ordered by (view, feature): i's observations are one contiguous range.
  for (auto it = landmarks_k1.lower_bound({view_i, 0}); it != landmarks_k1.end() && it->first.first == view_i; ++it) {
    if (!seen_by_i.insert(it->second).second) continue;
    const Eigen::Vector3d& X = k1.landmarks.at(it->second).X;
    const Eigen::Vector3d X_j = pose_j.ToCamera(X);
    if (!(X_j.z() > 0.0)) continue;
    const Eigen::Vector2d pixel = intrinsics_j.Project(X_j);
    if (!(pixel.x() >= margin && pixel.y() >= margin && pixel.x() <= intrinsics_j.width() - margin &&
          pixel.y() <= intrinsics_j.height() - margin)) {
      continue;
    }
    if (AngleBetweenVectors(X - pose_i->second.center, X - pose_j.center) > max_angle) continue;
    ++coverage.expected;
    coverage.matched += matched_landmarks.count(it->second);
  }
  return coverage;
}


const char* EdgePlacementStatusName(EdgePlacementStatus status) {
  switch (status) {
    case EdgePlacementStatus::kPlaced: return "placed";
    case EdgePlacementStatus::kMissingViewData: return "missing_view_data";
    case EdgePlacementStatus::kTooFewCorrespondences: return "too_few_correspondences";
    case EdgePlacementStatus::kPnpFailed: return "pnp_failed";
  }
  return "unknown";
}

std::vector<ViewPair> ConnectingEdges(const ViewGraph& graph, const std::set<IndexT>& views_k1,
                                      const std::set<IndexT>& views_k2) {
  std::vector<ViewPair> edges;
  graph.ForEachValidEdge([&](const ViewPair& pair, const ViewGraphEdge&) {
    if (views_k1.count(pair.first) && views_k2.count(pair.second)) {
      edges.push_back(pair);
    } else if (views_k1.count(pair.second) && views_k2.count(pair.first)) {
      edges.push_back({pair.second, pair.first});
    }
  });
  std::sort(edges.begin(), edges.end());
  return edges;
}

EdgePlacement PlaceViewInSubgraph(const ViewGraph& graph, IndexT view_i, IndexT view_j,
                                  const SubgraphSolution& k1,
                                  const std::map<ObservationKey, IndexT>& landmarks_k1,
                                  const SfmData& views_and_intrinsics, const FeaturesPerView& features,
                                  const EdgePlacementOptions& options) {
  EdgePlacement placement;
  placement.view_i = view_i;
  placement.view_j = view_j;
  const CameraIntrinsics* intrinsics = views_and_intrinsics.FindIntrinsics(view_j);
  const auto features_j = features.find(view_j);
  if (intrinsics == nullptr || features_j == features.end()) return placement;

  std::vector<Eigen::Vector3d> bearings;
  std::vector<Eigen::Vector3d> points;
  for (const FeatureMatch& match : graph.OrientedMatches(view_i, view_j)) {
    const auto landmark = landmarks_k1.find({view_i, match.i});
    if (landmark == landmarks_k1.end() || match.j >= features_j->second.size()) continue;
    bearings.push_back(intrinsics->Unproject(features_j->second.Position(match.j)));
    points.push_back(k1.landmarks.at(landmark->second).X);
  }
  placement.num_correspondences = points.size();
  if (points.size() < options.min_correspondences) {
    placement.status = EdgePlacementStatus::kTooFewCorrespondences;
    return placement;
  }

  AbsolutePoseOptions pnp = options.pnp;
  if (pnp.max_reprojection_error_px > 0.0) pnp.focal_length_px = intrinsics->FocalLength();
  pnp.ransac.seed = options.pnp.ransac.seed ^ ((static_cast<uint64_t>(view_i) << 32) | view_j);
  const AbsolutePoseResult pose = EstimateAbsolutePose(bearings, points, pnp);
  placement.num_pnp_inliers = pose.num_inliers;
  if (!pose.success) {
    placement.status = EdgePlacementStatus::kPnpFailed;
    return placement;
  }
  placement.status = EdgePlacementStatus::kPlaced;
  placement.pose_j_in_k1 = pose.pose;
  const MatchCoverage coverage = MeasureMatchCoverage(graph, view_i, view_j, placement.pose_j_in_k1, k1, landmarks_k1,
                                                      *intrinsics, options);
  placement.num_expected_landmarks = coverage.expected;
  placement.num_matched_landmarks = coverage.matched;
  return placement;
}

void EdgePlacementOptions::Check() const {
  // EPnP needs 4 points; fewer leave the placement undetermined.
  RequireAtLeast<size_t>(min_correspondences, 4, "EdgePlacementOptions::min_correspondences");
  RequirePositiveAtMost(coverage_max_ray_angle_deg, 180.0, "EdgePlacementOptions::coverage_max_ray_angle_deg");
  RequireAtLeast(coverage_image_margin_px, 0.0, "EdgePlacementOptions::coverage_image_margin_px");
  pnp.Check();
}

}  // namespace sfm_pruning
