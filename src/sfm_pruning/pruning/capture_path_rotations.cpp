#include "sfm_pruning/pruning/capture_path_rotations.hpp"

#include <algorithm>
#include <cmath>
#include <map>

#include <Eigen/Core>

#include "sfm_pruning/global/rotation_averaging.hpp"
#include "sfm_pruning/sfm/pose.hpp"

namespace sfm_pruning {

CapturePathRotationCheck CheckAgainstCapturePath(const CaptureOrderOptions& options, const CaptureOrder& order,
                                                 const ViewGraph& graph) {
  CapturePathRotationCheck check;
  if (!order.Used() || options.path_max_deviation_deg <= 0.0) return check;

  ViewGraph path;
  for (const IndexT view : graph.Nodes()) path.AddNode(view);
  graph.ForEachValidEdge([&](const ViewPair& pair, const ViewGraphEdge& edge) {
    const size_t apart = order.PlacesApart(pair.first, pair.second);
    if (apart >= 1 && apart <= options.path_window_views) path.AddEdge(pair, edge);
  });
  check.num_path_edges = path.NumValidEdges();
  if (check.num_path_edges == 0) return check;

  // The engine's robust averaging (L1, then Geman-McClure), its filter removing the path edges
  // that disagree with the others: a twin pair between neighbours is outvoted by its neighbours.
  std::map<IndexT, Eigen::Matrix3d> rotations;
  const RotationAveragingResult averaged = EstimateGlobalRotations(&path, RotationAveragingOptions(), &rotations);
  if (!averaged.success) return check;
  check.applied = true;
  check.num_path_views = rotations.size();
  check.path_residual_deg = averaged.residuals.median_deg;

  graph.ForEachValidEdge([&](const ViewPair& pair, const ViewGraphEdge& edge) {
    const auto ri = rotations.find(pair.first);
    const auto rj = rotations.find(pair.second);
    if (ri == rotations.end() || rj == rotations.end()) return;
    const size_t apart = order.PlacesApart(pair.first, pair.second);
    const double deviation =
        RadToDeg(RotationAngleBetween(edge.relative_pose.rotation, rj->second * ri->second.transpose()));
    const double drift = 3.0 * check.path_residual_deg * std::sqrt(static_cast<double>(apart));
    const double bound = std::max(options.path_max_deviation_deg, drift);
    if (deviation > bound) check.removed.push_back({pair, apart, deviation, bound});
  });
  return check;
}

}  // namespace sfm_pruning
