#include "sfm_pruning/pruning/baseline_ratio_consistency.hpp"

#include "sfm_pruning/util/option_checks.hpp"

#include <algorithm>
#include <map>
#include <optional>
#include <utility>
#include <vector>

#include "sfm_pruning/geometry/triangulation.hpp"
#include "sfm_pruning/sfm/pose.hpp"
#include "sfm_pruning/util/statistics.hpp"

namespace sfm_pruning {
namespace {

// Distance from view i's centre of each of its features that edge <i, j> triangulates in front of
// both cameras, for a unit baseline: feature id of i -> distance.
using DistanceByFeature = std::map<IndexT, double>;

std::optional<DistanceByFeature> UnitBaselineDistances(const ViewGraph& graph, IndexT view_i, IndexT view_j,
                                                       const SfmData& views_and_intrinsics,
                                                       const FeaturesPerView& features, double min_parallax_rad) {
  const CameraIntrinsics* intrinsics_i = views_and_intrinsics.FindIntrinsics(view_i);
  const CameraIntrinsics* intrinsics_j = views_and_intrinsics.FindIntrinsics(view_j);
  const auto features_i = features.find(view_i);
  const auto features_j = features.find(view_j);
  if (intrinsics_i == nullptr || intrinsics_j == nullptr || features_i == features.end() ||
      features_j == features.end()) {
    return std::nullopt;
  }
  const RelativePose relative = graph.OrientedRelativePose(view_i, view_j);
  const double baseline = relative.translation.norm();
  if (!(baseline > 0.0)) return std::nullopt;
  DistanceByFeature distances;
  for (const FeatureMatch& match : graph.OrientedMatches(view_i, view_j)) {
    if (match.i >= features_i->second.size() || match.j >= features_j->second.size()) continue;
    const std::optional<TwoViewPoint> point =
        TriangulateTwoView(relative, intrinsics_i->Unproject(features_i->second.Position(match.i)),
                           intrinsics_j->Unproject(features_j->second.Position(match.j)), min_parallax_rad);
    if (point && point->depth_i > 0.0 && point->depth_j > 0.0) {
      distances.emplace(match.i, point->point_i.norm() / baseline);
    }
  }
  return distances;
}

}  // namespace

double BaselineRatioCheck::Factor() const {
  if (!(measured_ratio > 0.0) || !(implied_ratio > 0.0)) return 1.0;
  return std::max(measured_ratio / implied_ratio, implied_ratio / measured_ratio);
}

std::vector<BaselineRatioCheck> MeasureBaselineRatios(const ViewGraph& graph, const SubgraphSolution& solution,
                                                      const SfmData& views_and_intrinsics,
                                                      const FeaturesPerView& features,
                                                      const BaselineRatioOptions& options) {
  const double min_parallax_rad = DegToRad(options.min_parallax_deg);
  std::vector<BaselineRatioCheck> checks;
  for (const auto& [view_i, neighbours] : graph.ValidAdjacency()) {
    const auto pose_i = solution.poses.find(view_i);
    if (pose_i == solution.poses.end()) continue;
    // Each posed neighbour away from i's centre (a zero solved baseline implies no ratio), with its
    // measured distances.
    struct Neighbour {
      IndexT view;
      DistanceByFeature distances;
      double solved_baseline;
    };
    std::vector<Neighbour> measured;
    for (const IndexT view_j : neighbours) {
      const auto pose_j = solution.poses.find(view_j);
      if (pose_j == solution.poses.end()) continue;
      const double solved_baseline = (pose_j->second.center - pose_i->second.center).norm();
      if (!(solved_baseline > 0.0)) continue;
      std::optional<DistanceByFeature> distances =
          UnitBaselineDistances(graph, view_i, view_j, views_and_intrinsics, features, min_parallax_rad);
      if (!distances || distances->size() < options.min_common_points) continue;
      measured.push_back({view_j, std::move(*distances), solved_baseline});
    }
    for (size_t a = 0; a < measured.size(); ++a) {
      for (size_t b = a + 1; b < measured.size(); ++b) {
        // d_ij / d_ik = |c_i - c_k| / |c_i - c_j| for every feature both edges triangulate.
        std::vector<double> ratios;
        for (const auto& [feature, distance_ij] : measured[a].distances) {
          const auto distance_ik = measured[b].distances.find(feature);
          if (distance_ik != measured[b].distances.end() && distance_ik->second > 0.0) {
            ratios.push_back(distance_ij / distance_ik->second);
          }
        }
        if (ratios.size() < options.min_common_points) continue;
        BaselineRatioCheck check;
        check.view_i = view_i;
        check.view_j = measured[a].view;
        check.view_k = measured[b].view;
        check.num_common_points = ratios.size();
        check.measured_ratio = Median(std::move(ratios));
        check.implied_ratio = measured[b].solved_baseline / measured[a].solved_baseline;
        checks.push_back(check);
      }
    }
  }
  return checks;
}

void BaselineRatioOptions::Check() const {
  RequireAtLeast<size_t>(min_common_points, 2, "BaselineRatioOptions::min_common_points");
  RequireInRange(min_parallax_deg, 0.0, 90.0, "BaselineRatioOptions::min_parallax_deg");
}

}  // namespace sfm_pruning
