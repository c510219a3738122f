#include "sfm_pruning/pruning/capture_path_directions.hpp"

#include <map>
#include <utility>
#include <vector>

#include "sfm_pruning/sfm/pose.hpp"
#include "sfm_pruning/util/statistics.hpp"

namespace sfm_pruning {
namespace {

// Degrees between an edge's verified direction t_ij and the one its views' poses imply,
// R_j (c_i - c_j) (X_j = R_ij X_i + t_ij, sfm/pose.hpp).
double DirectionDeviationDeg(const ViewGraphEdge& edge, const Pose& pose_i, const Pose& pose_j) {
  const Eigen::Vector3d implied = pose_j.rotation * (pose_i.center - pose_j.center);
  return RadToDeg(AngleBetweenVectors(edge.relative_pose.translation, implied));
}

}  // namespace

CapturePathDirectionCheck CheckDirectionsAgainstCapturePath(const CaptureOrderOptions& options,
                                                            const CaptureOrder& order, const ViewGraph& graph,
                                                            const GlobalEngineOptions& engine,
                                                            const SfmData& views_and_intrinsics,
                                                            const FeaturesPerView& features) {
  CapturePathDirectionCheck check;
  if (!order.Used() || options.path_max_direction_deviation_deg <= 0.0) return check;
  const ViewGraph path = order.PathGraph(graph, options.path_window_views);
  check.num_path_edges = path.NumValidEdges();
  if (check.num_path_edges == 0) return check;

  // Each piece of the path solved on its own, in its own frame (CapturePathPieces).
  std::map<IndexT, Pose> poses;
  std::map<IndexT, size_t> piece_of;
  for (const ViewGraph& piece_graph : CapturePathPieces(path)) {
    SfmData model;
    GlobalEngineReport report;
    RunGlobalEngine(engine, piece_graph, views_and_intrinsics, features, &model, &report);
    if (!report.success) continue;
    for (const IndexT view : model.PosedViewIds()) {
      poses[view] = model.PoseOf(model.views.at(view));
      piece_of[view] = check.num_path_pieces;
    }
    ++check.num_path_pieces;
  }
  if (poses.empty()) return check;
  check.solved = true;
  check.num_path_views = poses.size();

  // Visits the valid edges whose views one piece posed, with their places apart and deviation.
  const auto for_each_posed_edge = [&](const ViewGraph& edges, auto&& visit) {
    edges.ForEachValidEdge([&](const ViewPair& pair, const ViewGraphEdge& edge) {
      const auto pi = poses.find(pair.first);
      const auto pj = poses.find(pair.second);
      if (pi == poses.end() || pj == poses.end()) return;
      if (piece_of.at(pair.first) != piece_of.at(pair.second)) return;  // no common frame
      visit(pair, order.PlacesApart(pair.first, pair.second), DirectionDeviationDeg(edge, pi->second, pj->second));
    });
  };
  std::vector<double> residuals;
  for_each_posed_edge(path, [&](const ViewPair&, size_t, double deviation) { residuals.push_back(deviation); });
  if (residuals.empty()) return check;
  check.path_residual_deg = Median(std::move(residuals));
  if (check.path_residual_deg > options.path_max_direction_deviation_deg) return check;
  check.applied = true;

  for_each_posed_edge(graph, [&](const ViewPair& pair, size_t apart, double deviation) {
    if (apart <= options.path_window_views) return;  // the path's own edges made the model
    const double bound =
        CapturePathBoundDeg(options.path_max_direction_deviation_deg, check.path_residual_deg, apart);
    if (deviation > bound) check.removed.push_back({pair, apart, deviation, bound});
  });
  return check;
}

}  // namespace sfm_pruning
